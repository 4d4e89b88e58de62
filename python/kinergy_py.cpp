// The Python module `kinergy._kinergy` (pybind11), which the package `kinergy` (python/kinergy/)
// re-exports: a thin window onto the library, as the CLI is.
//   scene = kinergy.load("derivations/energy/sliding_rod.yaml")   (or kinergy.loads(yaml_text))
//   scene.set("l", "2 m"); solution = scene.solve()
//   solution["omega2"].closed, .latex, .value(digits=30), float(...), .sympy()
//   solution.derive("text" | "latex" | "html"); scene.draw(state=None) -> SVG
//   solution.simulate(until, samples=1000) -> dict of NumPy columns; solution.to_dataframe()
// A bad scene raises kinergy.SceneError with file, line, column, message and fix.
//
// Threads. kinergy's core (GiNaC: reference counts, the global Digits) is not thread-safe, so
// one thread at a time holds it (core_mutex), and a call that computes releases the GIL first
// (in_core): other Python threads run meanwhile, and calls from several threads are taken one
// after another. Parallel solving is by processes (batch, multiprocessing, Dask). A thread
// never waits for the core while it holds the GIL: the core's holder takes the GIL to check
// for Ctrl-C (check_signals), and would wait for it for ever.
#include <optional>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pythread.h>

#include <cmath>
#include <deque>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>

#include "kinergy/app/app.hpp"
#include "kinergy/batch/batch.hpp"
#include "kinergy/common/error.hpp"
#include "kinergy/common/interrupt.hpp"
#include "kinergy/confirm/confirm.hpp"
#include "kinergy/common/markup.hpp"
#include "kinergy/draw/figure.hpp"
#include "kinergy/emit/derive.hpp"
#include "kinergy/emit/emit.hpp"
#include "kinergy/emit/latex.hpp"
#include "kinergy/emit/mathml.hpp"
#include "kinergy/model/simplify.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/scene/scene.hpp"
#include "kinergy/confirm/check.hpp"
#include "kinergy/simulate/simulate.hpp"
#include "kinergy/verify/verify.hpp"

namespace py = pybind11;
using namespace pybind11::literals;
using namespace kinergy;

namespace {

struct PySolution;

// ---------------------------------------------------------------- the core, one thread at a time
std::recursive_mutex& core_mutex() {
  static std::recursive_mutex m;
  return m;
}
/// f() with the GIL released and the core held: f touches no Python object. Called with the GIL
/// held (from a binding), never from inside another in_core.
template <class F>
auto in_core(F&& f) -> decltype(f()) {
  py::gil_scoped_release nogil;
  std::lock_guard<std::recursive_mutex> core(core_mutex());
  return f();
}
/// A solution is freed with the core held (its GiNaC expressions share reference-counted nodes
/// with whatever another thread computes), and without the GIL while it waits for the core.
struct CoreDelete {
  void operator()(const Solution* s) const {
    if (PyGILState_Check()) {
      py::gil_scoped_release nogil;
      std::lock_guard<std::recursive_mutex> core(core_mutex());
      delete s;
    } else {
      std::lock_guard<std::recursive_mutex> core(core_mutex());
      delete s;
    }
  }
};

/// Python's main thread, where signal handlers run (set at import).
unsigned long g_main_thread = 0;
/// The interrupt hook (common/interrupt.hpp): on the main thread, Python's signal handlers are run
/// (Ctrl-C raises KeyboardInterrupt there); an exception they raise stops the computation.
void check_signals() {
  if (PyThread_get_thread_ident() != g_main_thread) return;
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) throw Interrupted{};  // the exception stays set: the translator keeps it
}

// A scene as written, its parameters changeable before it is solved. It keeps its text, the name
// it was loaded under and the values set since, so that it pickles (a Dask worker rebuilds it).
// A scene as written, its parameters changeable before it is solved. It keeps its text, the name
// it was loaded under and the values set since, so that it pickles (a Dask worker rebuilds it).
// (SceneDef holds no GiNaC: a scene is copied and freed without the core.)
struct PyScene {
  scene::SceneDef def;
  std::string text, name;
  std::vector<std::pair<std::string, std::string>> sets;

  std::map<std::string, std::string> parameters() const {
    std::map<std::string, std::string> out;
    for (auto& p : def.parameters) out[p.name] = p.value.s;
    return out;
  }
  // (in the core) each parameter that has a value, in SI units (what SymPy's lambdify of a
  // result's closed form takes)
  std::map<std::string, double> values_si() const {
    const model::Model m = model::Model::build(def);
    const GiNaC::exmap env = m.numeric_environment();
    std::map<std::string, double> out;
    for (auto& p : m.params)
      if (p.value)
        if (auto v = numerics::evaluate(*p.value, env, 20)) out[p.name] = v->to_double();
    return out;
  }
  // a parameter's value: text as a scene writes it ("2 kg", "30 deg"), or a number in the unit the
  // scene writes it in (2.0 for 'l: 1.2 m' is 2.0 m; 45 for 'theta2: 30 deg' is 45 deg); checked here
  void set(const std::string& parameter, const py::object& value) {
    std::string v;
    if (py::isinstance<py::str>(value)) {
      v = value.cast<std::string>();
    } else if ((py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value)) && !py::isinstance<py::bool_>(value)) {
      const double x = value.cast<double>();
      if (!std::isfinite(x)) throw InputError("the value " + py::repr(value).cast<std::string>() + " for '" + parameter + "' is not a finite number", "give a finite number");
      const std::string unit = app::written_unit(def, parameter);
      v = py::repr(value).cast<std::string>() + (unit.empty() ? "" : " " + unit);
    } else {
      throw InputError("the value for '" + parameter + "' is a " + py::str(value.get_type().attr("__name__")).cast<std::string>(),
                       "give text as a scene writes it ('2 kg') or a number in the scene's unit for it");
    }
    in_core([&] { app::set_parameter(def, parameter, v); });
    sets.emplace_back(parameter, v);
  }
  // (in the core) the scene at a state ("" the first) as SVG; a parameter without a value at a
  // sample value, said in `samples`
  // (without a state: the first that fixes every coordinate, those before it in `left_out`)
  std::string draw(const std::string& state, std::string& samples, std::vector<std::string>& left_out) const {
    model::Model m = model::Model::build(def);
    int st = 0;
    if (!state.empty()) {
      st = m.state_index(state);
      if (st < 0) throw InputError("there is no state '" + state + "'", "name a state of the scene's 'states'");
    }
    std::optional<Solution> s;
    if (!def.analyses.empty()) s = solve_scene(def);
    const model::Model& at = s ? s->model : m;
    const GiNaC::exmap solved = s ? s->branch.sol : GiNaC::exmap{};
    const GiNaC::exmap values = draw::with_samples(at, s ? parameter_values(*s) : m.parameter_values(), &samples);
    if (state.empty()) return draw::first_drawable(at, solved, values, left_out).svg();
    return draw::scene_at(at, solved, values, st).svg();
  }
};

/// A closed form as SymPy is given it: GiNaC's tree copied into plain nodes in the core (no GIL),
/// then built into SymPy objects with the GIL (no core): a thread never holds both.
struct Node {
  std::string kind;  ///< symbol, integer, rational, float, complex, constant, Add, Mul, Pow, function, integral
  std::string text, text2;
  int domain = 0;    ///< a symbol's: 1 positive, 2 real
  std::vector<Node> args;
};

/// (in the core) e's tree as nodes: sums, products, powers, rational and decimal numbers, the
/// elementary functions, π. @throws InputError for a kind of node SymPy is not given (naming the
/// result).
Node tree(const GiNaC::ex& e, const std::string& result) {
  using namespace GiNaC;
  Node n;
  auto args = [&](const ex& x) {
    for (std::size_t i = 0; i < x.nops(); ++i) n.args.push_back(tree(x.op(i), result));
  };
  if (is_a<symbol>(e)) {
    const symbol& x = ex_to<symbol>(e);
    n.kind = "symbol";
    n.text = x.get_name();
    n.domain = x.get_domain() == domain::positive ? 1 : x.get_domain() == domain::real ? 2 : 0;
    return n;
  }
  if (is_a<numeric>(e)) {
    const numeric& v = ex_to<numeric>(e);
    if (!v.is_real()) {
      n.kind = "complex";
      n.args = {tree(v.real(), result), tree(v.imag(), result)};
      return n;
    }
    std::ostringstream os;
    if (v.is_integer()) {
      n.kind = "integer";
      n.text = (os << v, os.str());
      return n;
    }
    if (v.is_rational()) {
      std::ostringstream d;
      d << v.denom();
      n.kind = "rational";
      n.text = (os << v.numer(), os.str());
      n.text2 = d.str();
      return n;
    }
    // a decimal: its digits as GiNaC holds them (CLN prints "1.25L-3" style exponents)
    os.precision(40);
    os << v;
    n.kind = "float";
    n.text = os.str();
    for (char& c : n.text)
      if (c == 'L' || c == 'E') c = 'e';
    return n;
  }
  if (is_a<constant>(e)) {
    n.kind = "constant";
    if (e.is_equal(Pi)) n.text = "pi";
    else if (e.is_equal(Euler)) n.text = "EulerGamma";
    else if (e.is_equal(Catalan)) n.text = "Catalan";
    if (!n.text.empty()) return n;
  }
  if (is_a<add>(e) || is_a<mul>(e) || is_a<power>(e)) {
    n.kind = is_a<add>(e) ? "Add" : is_a<mul>(e) ? "Mul" : "Pow";
    args(e);
    return n;
  }
  if (is_a<function>(e)) {
    static const std::map<std::string, std::string> names{
        {"sin", "sin"},   {"cos", "cos"},   {"tan", "tan"},     {"asin", "asin"},   {"acos", "acos"},   {"atan", "atan"},
        {"atan2", "atan2"}, {"sinh", "sinh"}, {"cosh", "cosh"}, {"tanh", "tanh"},   {"asinh", "asinh"}, {"acosh", "acosh"},
        {"atanh", "atanh"}, {"exp", "exp"},   {"log", "log"},   {"abs", "Abs"},     {"csgn", "sign"},   {"step", "Heaviside"},
        {"factorial", "factorial"}};
    const std::string f = ex_to<function>(e).get_name();
    if (auto it = names.find(f); it != names.end()) {
      n.kind = "function";
      n.text = it->second;
      args(e);
      return n;
    }
    if (f == "integral") {
      // ∫_a^b f ds (a work with no elementary antiderivative): integral(f, s, a, b)
      n.kind = "integral";
      args(e);
      return n;
    }
    throw InputError("result '" + result + "' holds the function " + f + ", which kinergy does not hand to SymPy", "use .closed (its text) instead");
  }
  throw InputError("result '" + result + "' holds " + emit::plain(e) + ", which kinergy does not hand to SymPy", "use .closed (its text) instead");
}

/// (with the GIL) the nodes as SymPy builds them; a symbol of GiNaC's positive or real domain as
/// such a SymPy symbol (one per name, in `symbols`).
py::object to_sympy(const Node& n, const py::module_& sp, py::dict& symbols) {
  py::list a;
  for (auto& x : n.args) a.append(to_sympy(x, sp, symbols));
  if (n.kind == "symbol") {
    const py::str name(n.text);
    if (!symbols.contains(name)) {
      py::dict assume;
      if (n.domain == 1) assume["positive"] = true;
      else if (n.domain == 2) assume["real"] = true;
      symbols[name] = sp.attr("Symbol")(name, **assume);
    }
    return symbols[name];
  }
  if (n.kind == "integer") return sp.attr("Integer")(n.text);
  if (n.kind == "rational") return sp.attr("Rational")(n.text, n.text2);
  if (n.kind == "float") return sp.attr("Float")(n.text, std::max<long>(15, static_cast<long>(n.text.size())));
  if (n.kind == "complex") return sp.attr("Add")(a[0], sp.attr("Mul")(sp.attr("I"), a[1]));
  if (n.kind == "constant") return sp.attr(n.text.c_str());
  if (n.kind == "function") return sp.attr(n.text.c_str())(*a);
  if (n.kind == "integral") return sp.attr("Integral")(a[0], py::make_tuple(a[1], a[2], a[3]));
  return sp.attr(n.kind.c_str())(*a);  // Add, Mul, Pow
}

/// One result of a solution. Its methods run in the core (the bindings wrap them in in_core).
struct PyResult {
  std::shared_ptr<const Solution> s;
  std::size_t i;
  const Result& r() const { return s->results[i]; }
  // the digits asked for, checked as a batch request's are (numerics::valid_digits)
  static void check_digits(long long digits) {
    if (!numerics::valid_digits(digits)) {
      auto [what, fix] = numerics::digits_fault("digits = " + std::to_string(digits));
      throw InputError(what, fix);
    }
  }
  std::string value(long long digits) const {
    check_digits(digits);
    if (!r().si) throw InputError("'" + r().name + "' has no value: a parameter in it has none", "give every parameter a value");
    auto v = r().evaluate(s->model.numeric_environment(), static_cast<int>(digits), digits <= 15);
    if (!v) throw InputError("'" + r().name + "' could not be evaluated", "ask for fewer digits");
    return numerics::format(v->v, static_cast<int>(digits));
  }
  double to_float() const { return std::stod(value(17)); }
  struct Ball {
    std::string value, midpoint, radius, evaluation;
    bool proven = false;
  };
  // the value proven by ball arithmetic, as `kinergy solve --digits N --json` gives it
  Ball ball(long long digits) const {
    check_digits(digits);
    const int n = static_cast<int>(digits);
    if (!r().si) throw InputError("'" + r().name + "' has no value: a parameter in it has none", "give every parameter a value");
    auto v = r().evaluate(s->model.numeric_environment(), n, false);
    if (!v) throw InputError("'" + r().name + "' could not be evaluated", "ask for fewer digits");
    auto [mid, rad] = v->ball(n);
    return {numerics::format(v->v, n), mid, rad, v->note(), v->proven};
  }
  // "omega2 = 3.502 rad/s" (or its closed form, when a parameter has no value)
  std::string shown() const {
    if (!r().si) return r().name + " = " + emit::plain(r().closed);
    return r().name + " = " + value(4) + (r().unit.empty() ? "" : " " + r().unit);
  }
  // ω₂ = √(3 g sin θ₂ / l) = 3.502 rad/s as TeX (the value to 6 digits, when there is one)
  std::string tex() const {
    std::string o = emit::tex_name(r().name) + " = " + emit::latex(r().closed);
    if (r().si) o += " = " + emit::tex_quantity(value(6), r().unit);
    return o;
  }
};

// what Solution.verify() gives: whether every claim holds, and each claim's check
struct Verdict {
  bool ok = true;
  py::list checks;
};

/// The columns of a run (each one value per row), built in the core.
struct Columns {
  std::vector<std::string> names;
  std::vector<std::vector<double>> values;
  std::vector<bool> impact;
};

struct PySolution {
  std::shared_ptr<const Solution> s;
  PyScene scene;     ///< what was solved (a pickled solution is solved again from it)
  bool confirmed = true;

  std::vector<PyResult> results() const {
    std::vector<PyResult> out;
    for (std::size_t i = 0; i < s->results.size(); ++i) out.push_back({s, i});
    return out;
  }
  // (in the core)
  std::string derive(const std::string& format) const {
    const emit::Derivation d = emit::derive(*s);
    if (format == "text") return emit::text(d);
    if (format == "latex") return emit::latex(d);
    if (format == "html") return app::derivation_page(*s, d);
    throw InputError("there is no derivation format '" + format + "'", "ask for 'text', 'latex' or 'html'");
  }
  // (in the core) the motion from a state until a time: t, each coordinate and its rate, T, V,
  // at `samples` regular times from the start to `until` (both included, as numpy.linspace),
  // and at each impact the state before and after it (two rows at its instant, flagged)
  Columns simulate(double until, long long samples, const std::string& start) const {
    namespace sim = simulate;
    const model::Model& m = s->model;
    const int from = app::state_index(m, start);
    sim::State s0 = app::start_values(m, s.get(), from);
    if (!std::isfinite(until) || !(until > s0.t))
      throw InputError("the run must end at a finite time after it starts (t = " + numerics::format(s0.t, 6) + " s)", "give until > the start's time");
    if (samples < 2 || samples > 10000000) throw InputError("samples = " + std::to_string(samples) + " is not from 2 to 10^7", "ask for 2 to 10^7 regular samples");
    sim::Options o;
    o.native = false;
    o.sample_dt = (until - s0.t) / static_cast<double>(samples - 1);
    const sim::Run r = sim::run_following(m, s->branch.sol, parameter_values(*s), from, s0, until, o, sim::impulses_at(m, from));
    Columns c;
    c.names.push_back("t");
    for (auto& q : m.coords) c.names.push_back(q.name);
    for (auto& q : m.coords) c.names.push_back(q.name + "_dot");
    c.names.push_back("T");
    c.names.push_back("V");
    c.values.resize(c.names.size());
    const std::size_t n = m.coords.size();
    for (auto& x : r.samples) {
      c.values[0].push_back(x.t);
      for (std::size_t k = 0; k < n; ++k) {
        c.values[1 + k].push_back(x.q[k]);
        c.values[1 + n + k].push_back(x.qd[k]);
      }
      c.values[1 + 2 * n].push_back(x.T);
      c.values[2 + 2 * n].push_back(x.V);
      c.impact.push_back(std::any_of(r.impacts.begin(), r.impacts.end(), [&](const sim::Impact& im) { return im.t == x.t; }));
    }
    return c;
  }
};

// a path as Python gives it: str, pathlib.Path or any os.PathLike
PyScene load(const py::object& path) {
  const std::string p = py::str(py::module_::import("os").attr("fspath")(path));
  PyScene sc{in_core([&] { return scene::load_file(p); }), "", p, {}};
  std::ifstream f(p, std::ios::binary);
  std::ostringstream text;
  text << f.rdbuf();
  sc.text = text.str();
  return sc;
}
PyScene loads(const std::string& text, const std::string& name) {
  return {in_core([&] { return scene::load_string(text, name); }), text, name, {}};
}
PySolution solve_scene_def(const PyScene& sc, bool confirmed) {
  std::shared_ptr<const Solution> s = in_core([&] {
    Solution x = solve_scene(sc.def);
    if (confirmed) confirm(x);  // each analysis a second way: a disagreement raises SceneError
    return std::shared_ptr<const Solution>(new Solution(std::move(x)), CoreDelete{});
  });
  return {std::move(s), sc, confirmed};
}

// pickling: a scene is its text, its name and the values set since; a solution is its scene
// solved again (the same bytes: kinergy's output does not depend on the process)
py::tuple scene_state(const PyScene& sc) {
  py::list sets;
  for (auto& [k, v] : sc.sets) sets.append(py::make_tuple(k, v));
  return py::make_tuple(sc.text, sc.name, sets);
}
PyScene scene_from(const py::tuple& t) {
  if (t.size() != 3) throw InputError("a pickled kinergy.Scene holds its text, name and values set", "pickle it with this version of kinergy");
  PyScene sc = loads(t[0].cast<std::string>(), t[1].cast<std::string>());
  for (auto item : t[2].cast<py::list>()) {
    auto kv = item.cast<py::tuple>();
    sc.set(kv[0].cast<std::string>(), kv[1]);
  }
  return sc;
}

/// A docstring with the signature Python's inspect reads (`name(args)\n--\n\n`): pybind11's own
/// (disabled) carry C++ types inspect cannot parse. The types are in the stubs (__init__.pyi).
/// (Kept for the module's life: pybind11 takes a docstring as a C string.)
const char* sig(const std::string& signature, const std::string& doc) {
  static std::deque<std::string> kept;
  return kept.emplace_back(signature + "\n--\n\n" + doc).c_str();
}

}  // namespace

PYBIND11_MODULE(_kinergy, m) {
  m.doc() = "kinergy's compiled core (the package kinergy re-exports it)";
  m.attr("__version__") = KINERGY_VERSION;
  py::options options;
  options.disable_function_signatures();
  g_main_thread = py::module_::import("threading").attr("main_thread")().attr("ident").cast<unsigned long>();
  set_interrupt_hook(&check_signals);
  // every bad input: kinergy.SceneError (a ValueError) with file, line, column, message and fix
  static py::object error_type = py::reinterpret_borrow<py::object>(
      PyErr_NewExceptionWithDoc("kinergy.SceneError", "A bad scene or request: file, line, column, message, fix.", PyExc_ValueError, nullptr));
  m.attr("SceneError") = error_type;
  py::register_exception_translator([](std::exception_ptr p) {
    // (a place that is not in a file — a value given in Python, a run's limit — is None)
    auto raise = [](const std::string& what, const std::string& file, int line, int col, const std::string& message, const std::string& fix) {
      py::object e = error_type(what);
      e.attr("file") = file.empty() ? py::object(py::none()) : py::object(py::str(file));
      e.attr("line") = line > 0 ? py::object(py::int_(line)) : py::object(py::none());
      e.attr("column") = col > 0 ? py::object(py::int_(col)) : py::object(py::none());
      e.attr("message") = message;
      e.attr("fix") = fix;
      PyErr_SetObject(error_type.ptr(), e.ptr());
    };
    try {
      if (p) std::rethrow_exception(p);
    } catch (const Interrupted&) {
      // Ctrl-C: the signal handler's exception (KeyboardInterrupt) is set already
      if (!PyErr_Occurred()) PyErr_SetNone(PyExc_KeyboardInterrupt);
    } catch (const SceneError& e) {
      raise(e.what(), e.pos().file, e.pos().line, e.pos().col, e.problem(), e.fix());
    } catch (const InputError& e) {
      raise(std::string(e.what()) + " \u2014 " + e.fix(), "", 0, 0, e.what(), e.fix());
    } catch (const simulate::SimulationError& e) {
      // a run that cannot be made (a step limit, a slip): the module's error, not RuntimeError
      const std::string at = e.pos().file.empty() ? std::string() : e.pos().str() + ": ";
      raise(at + e.what() + " \u2014 " + e.fix(), e.pos().file, e.pos().line, e.pos().col, e.what(), e.fix());
    }
  });

  py::class_<PyResult>(m, "Result", "One result of a solved scene: a closed form, its value in its unit, its LaTeX")
      .def_property_readonly("name", [](const PyResult& r) { return r.r().name; }, "its name in the scene's results")
      .def_property_readonly("unit", [](const PyResult& r) { return r.r().unit; }, "the unit its value is in ('' for a number)")
      .def_property_readonly(
          "closed", [](const PyResult& r) { return in_core([&] { return emit::plain(r.r().closed); }); },
          "the expression kinergy holds, as text: the closed form, or the equation a numeric root was taken of")
      .def_property_readonly(
          "closed_form",
          [](const PyResult& r) -> py::object {
            if (!r.r().closed_form) return py::none();
            return py::str(in_core([&] { return emit::plain(r.r().closed); }));
          },
          "the closed form as text, as batch's JSON gives it; None where a numeric root was needed")
      .def_property_readonly("latex", [](const PyResult& r) { return in_core([&] { return emit::latex(r.r().closed); }); }, "the closed form in LaTeX")
      .def("value", [](const PyResult& r, long long digits) { return in_core([&] { return r.value(digits); }); }, py::arg("digits") = 15,
           sig("value(self, digits=15)", "its value in its unit to `digits` significant digits (1 to 1000), as text"))
      .def(
          "ball",
          [](const PyResult& r, long long digits) {
            const PyResult::Ball b = in_core([&] { return r.ball(digits); });
            py::dict d;
            d["value"] = b.value;
            d["proven"] = b.proven;
            d["midpoint"] = b.midpoint;
            d["radius"] = b.radius.empty() ? py::object(py::none()) : py::object(py::str(b.radius));
            d["evaluation"] = b.evaluation;
            return d;
          },
          py::arg("digits") = 30,
          sig("ball(self, digits=30)",
              "its value to `digits` proven digits (ball arithmetic): a dict of value, proven, midpoint, radius (the exact "
              "value lies within radius of midpoint; None when not proven) and evaluation"))
      .def("__float__", [](const PyResult& r) { return in_core([&] { return r.to_float(); }); }, sig("__float__(self, /)", "its value in its unit"))
      .def_property_readonly(
          "si",
          [](const PyResult& r) -> py::object {
            if (!r.r().si) return py::none();
            return py::float_(in_core([&] { return r.r().si->to_double(); }));
          },
          "its value in SI units, as its closed form gives it (None when a parameter has no value)")
      .def(
          "sympy",
          [](const PyResult& r) {
            const Node n = in_core([&] { return tree(r.r().closed, r.r().name); });
            const py::module_ sp = py::module_::import("sympy");
            py::dict symbols;
            return to_sympy(n, sp, symbols);
          },
          sig("sympy(self)",
              "the closed form as a SymPy expression, built from kinergy's tree (each symbol positive or real as kinergy "
              "knows it); sympy must be installed"))
      .def(
          "__format__",
          [](const PyResult& r, const std::string& spec) {
            // f"{r:.3f}": its value in its unit, formatted as a float is
            const double v = in_core([&] { return r.to_float(); });
            return py::module_::import("builtins").attr("format")(py::float_(v), spec);
          },
          sig("__format__(self, spec, /)", "its value in its unit, formatted as a float is"))
      .def("_repr_latex_", [](const PyResult& r) { return "$" + in_core([&] { return r.tex(); }) + "$"; },
           sig("_repr_latex_(self)", "for Jupyter: name = closed form = value, in LaTeX"))
      .def("_repr_html_", [](const PyResult& r) { return in_core([&] { return emit::mathml(r.tex()); }); },
           sig("_repr_html_(self)", "for Jupyter: name = closed form = value, typeset as MathML"))
      .def("__repr__", [](const PyResult& r) {
        // <kinergy.Result omega2 = sqrt(3*g*sin(theta2)/l) = 3.502 rad/s>
        return in_core([&] {
          std::string o = "<kinergy.Result " + r.r().name + " = " + emit::plain(r.r().closed);
          if (r.r().si) o += " = " + r.value(4) + (r.r().unit.empty() ? "" : " " + r.r().unit);
          return o + ">";
        });
      });

  py::class_<PySolution>(m, "Solution", "A solved scene: a mapping of its results by name, in the scene's order")
      .def_property_readonly("results", &PySolution::results, "the results, in the scene's order")
      .def_property_readonly(
          "confirmed",
          [](const PySolution& s) {
            // how each analysis was confirmed a second way: [{analysis, by, difference, note}], and
            // for closed forms in parameters without values, the sampled values they were
            // confirmed at ({sampled: "m, L", samples: ["m = 5.07 kg, L = 0.578 m", …]})
            py::list out;
            for (auto& c : s.s->confirmed) {
              const auto& a = s.s->model.analyses[static_cast<std::size_t>(c.analysis)];
              py::dict d;
              d["analysis"] = a.kind + " " + s.s->model.states[static_cast<std::size_t>(a.from)].name + " -> " +
                              s.s->model.states[static_cast<std::size_t>(a.to)].name;
              d["by"] = c.by == kinergy::Confirmed::By::None ? py::object(py::none()) : py::object(py::str(kinergy::Confirmed::name(c.by)));
              d["difference"] = c.difference;
              d["note"] = c.note;
              if (!c.sampled.empty()) {
                d["sampled"] = c.sampled;
                d["samples"] = c.samples;
              }
              out.append(d);
            }
            return out;
          },
          "how each analysis was confirmed a second way (empty with solve(confirm=False))")
      .def(
          "__getitem__",
          [](const PySolution& s, const std::string& name) {
            for (auto& r : s.results())
              if (r.r().name == name) return r;
            throw py::key_error(name);
          },
          sig("__getitem__(self, name, /)", "the result named `name`"))
      // a mapping of the results by name, in the scene's order
      .def("__len__", [](const PySolution& s) { return s.s->results.size(); }, sig("__len__(self, /)", "the number of results"))
      .def(
          "__contains__",
          [](const PySolution& s, const py::object& name) {
            if (!py::isinstance<py::str>(name)) return false;
            const std::string n = name.cast<std::string>();
            return std::any_of(s.s->results.begin(), s.s->results.end(), [&](const Result& r) { return r.name == n; });
          },
          sig("__contains__(self, name, /)", "whether a result is named `name`"))
      .def(
          "keys",
          [](const PySolution& s) {
            py::list out;
            for (auto& r : s.s->results) out.append(r.name);
            return out;
          },
          sig("keys(self)", "the results' names, in the scene's order"))
      .def("__iter__",
           [](const PySolution& s) {
             py::list out;
             for (auto& r : s.s->results) out.append(r.name);
             return py::iter(out);
           },
           sig("__iter__(self, /)", "the results' names, in the scene's order"))
      .def("values", &PySolution::results, sig("values(self)", "the results, in the scene's order"))
      .def(
          "items",
          [](const PySolution& s) {
            py::list out;
            for (auto& r : s.results()) out.append(py::make_tuple(r.r().name, r));
            return out;
          },
          sig("items(self)", "(name, result) pairs, in the scene's order"))
      .def("__repr__",
           [](const PySolution& s) {
             std::string out = "<kinergy.Solution of '" + s.s->scene.title + "':";
             in_core([&] {
               for (auto& r : s.results()) out += " " + r.shown() + ";";
             });
             if (!s.s->results.empty()) out.pop_back();
             return out + ">";
           })
      .def(py::pickle([](const PySolution& s) { return py::make_tuple(scene_state(s.scene), s.confirmed); },
                      [](const py::tuple& t) {
                        if (t.size() != 2) throw InputError("a pickled kinergy.Solution holds its scene and whether it was confirmed", "pickle it with this version of kinergy");
                        return solve_scene_def(scene_from(t[0].cast<py::tuple>()), t[1].cast<bool>());
                      }))
      .def("derive", [](const PySolution& s, const std::string& format) { return in_core([&] { return s.derive(format); }); },
           py::arg("format") = "text", sig("derive(self, format='text')", "the worked solution: 'text', 'latex' or 'html'"))
      .def(
          "verify",
          [](const PySolution& s) {
            // every claim of the scene's expect, as batch gives them: a list of {result, what, ok,
            // detail}; the Verdict is true when every one holds
            const std::vector<verify::Check> cs = in_core([&] { return verify::verify(*s.s); });
            Verdict v;
            for (auto& c : cs) {
              py::dict d;
              d["result"] = c.name;
              d["what"] = c.what;
              d["ok"] = c.ok();
              d["detail"] = c.detail;
              v.checks.append(d);
              v.ok = v.ok && c.ok();
            }
            return v;
          },
          sig("verify(self)", "every claim of the scene's expect checked: a Verdict, true when each holds, with .checks (result, what, ok, detail)"))
      .def(
          "simulate",
          [](const PySolution& s, double until, long long samples, const py::object& start) {
            const std::string from = start.is_none() ? std::string() : py::str(start).cast<std::string>();
            const Columns c = in_core([&] { return s.simulate(until, samples, from); });
            py::module_ np = py::module_::import("numpy");
            py::dict out;
            for (std::size_t k = 0; k < c.names.size(); ++k) out[py::str(c.names[k])] = np.attr("array")(c.values[k]);
            out["impact"] = np.attr("array")(c.impact, "dtype"_a = "bool");
            return out;
          },
          py::arg("until"), py::arg("samples") = 1000, py::arg("start") = py::none(),
          sig("simulate(self, until, samples=1000, start=None)",
              "the motion from a state (the first by default) until a time: a dict of NumPy columns, one value per row "
              "(pandas.DataFrame(run) takes it): t, each coordinate, its rate (name_dot), T, V, and impact (True at the two "
              "rows of an impact: the state before and after it, at its instant). The rows are `samples` regular times from "
              "the start to `until`, both included (numpy.linspace's), and each impact's two rows"))
      .def(
          "to_dataframe",
          [](const PySolution& s) {
            // one row per result: name, value (a float in its unit), unit, closed_form (None where a
            // numeric root was needed), si
            py::list name, value, unit, closed, si;
            std::vector<double> values, sis;
            std::vector<std::string> forms;
            in_core([&] {
              for (auto& r : s.results()) {
                values.push_back(r.r().si ? r.to_float() : std::nan(""));
                sis.push_back(r.r().si ? r.r().si->to_double() : std::nan(""));
                forms.push_back(r.r().closed_form ? emit::plain(r.r().closed) : std::string());
              }
            });
            const py::module_ pd = py::module_::import("pandas");
            for (std::size_t i = 0; i < s.s->results.size(); ++i) {
              const Result& r = s.s->results[i];
              name.append(r.name);
              value.append(values[i]);
              unit.append(r.unit);
              closed.append(r.closed_form ? py::object(py::str(forms[i])) : py::object(py::none()));
              si.append(r.si ? py::object(py::float_(sis[i])) : py::object(py::none()));
            }
            py::dict cols;
            cols["value"] = value;
            cols["unit"] = unit;
            cols["closed_form"] = closed;
            cols["si"] = si;
            return pd.attr("DataFrame")(cols, "index"_a = pd.attr("Index")(name, "name"_a = "result"));
          },
          sig("to_dataframe(self)",
              "the results as a pandas DataFrame indexed by name: value (a float in its unit; NaN without one), unit, "
              "closed_form (None where a numeric root was needed), si"))
      .def("_repr_latex_",
           [](const PySolution& s) {
             // for Jupyter: every result, one per line
             return in_core([&] {
               std::string o = "$\\begin{aligned}";
               for (auto& r : s.results()) {
                 const std::string t = r.tex();
                 const auto eq = t.find(" = ");
                 o += (r.i ? "\\\\ " : "") + t.substr(0, eq) + " &= " + t.substr(eq + 3);
               }
               return o + "\\end{aligned}$";
             });
           },
           sig("_repr_latex_(self)", "for Jupyter: every result, name = closed form = value, in LaTeX"))
      .def("_repr_html_", [](const PySolution& s) {
        // for Jupyter, which shows text/html before text/latex: the results typeset as MathML (the
        // browser's own, no script), one per line, under the scene's title
        return in_core([&] {
          std::string o = "<div class=\"kinergy-solution\" style=\"font-size:120%\"><p><b>" + xml_escape(s.s->scene.title) + "</b></p>";
          for (auto& r : s.results()) o += emit::mathml(r.tex(), true);
          return o + "</div>";
        });
      }, sig("_repr_html_(self)", "for Jupyter: every result, name = closed form = value, typeset as MathML"));

  py::class_<PyScene>(m, "Scene", "A scene as written: change its parameters, solve it, draw it")
      .def_property_readonly("title", [](const PyScene& s) { return s.def.title; }, "the scene's title")
      .def_property_readonly(
          "parameters",
          [](const PyScene& s) {
            // read-only: a value is changed with set() (assigning into a copy changed nothing)
            return py::module_::import("types").attr("MappingProxyType")(py::cast(s.parameters()));
          },
          "name -> value as written (read-only: change one with set())")
      .def(
          "set",
          [](PyScene& s, const py::args& args, const py::kwargs& values) {
            // set("l", "2 m"), set("l", 2.0) in the scene's unit, or set(l="2 m", theta2=45)
            if (args.size() == 2) s.set(args[0].cast<std::string>(), args[1]);
            else if (!args.empty()) throw InputError("set takes a name and a value, or name=value pairs", "write set('l', '2 m') or set(l='2 m')");
            for (auto [k, v] : values) s.set(k.cast<std::string>(), py::reinterpret_borrow<py::object>(v));
          },
          sig("set(self, *args, **values)",
              "give parameters values: set('l', '2 m'), set('l', 2.0) (a number in the unit the scene writes it in), or "
              "set(l='2 m', theta2=45); each checked at once"))
      .def("values_si", [](const PyScene& s) { return in_core([&] { return s.values_si(); }); },
           sig("values_si(self)", "name -> value in SI units, for each parameter that has one"))
      .def("solve", &solve_scene_def, py::arg("confirm") = true,
           sig("solve(self, confirm=True)",
               "solve it: each result in closed form and its value, each analysis confirmed a second way (a simulation of "
               "the same scene, else the equations' residuals at 50 digits) unless confirm=False"))
      .def(
          "draw",
          [](const PyScene& s, const py::object& state) {
            const std::string st = state.is_none() ? std::string() : py::str(state).cast<std::string>();
            std::string samples;
            std::vector<std::string> left_out;
            std::string svg = in_core([&] { return s.draw(st, samples, left_out); });
            for (auto& why : left_out) py::module_::import("warnings").attr("warn")("left out of the drawing: " + why);
            if (!samples.empty()) {
              py::module_::import("warnings").attr("warn")("drawn with sample values for the parameters that have none: " + samples +
                                                           " (give them with scene.set(NAME, VALUE))");
            }
            return svg;
          },
          py::arg("state") = py::none(),
          sig("draw(self, state=None)", "the scene at a state (by default the first that fixes every coordinate, the states before it named in a "
                                        "warning) as SVG; a parameter without a value is drawn at a "
                                        "sample value (1 in SI units), with a warning that names it"))
      .def("__repr__",
           [](const PyScene& s) {
             std::string out = "<kinergy.Scene '" + s.def.title + "' (" + s.name + ")";
             for (std::size_t i = 0; i < s.def.parameters.size(); ++i)
               out += (i ? ", " : ": ") + s.def.parameters[i].name + " = " + s.def.parameters[i].value.s;
             return out + ">";
           })
      .def(py::pickle([](const PyScene& s) { return scene_state(s); }, [](const py::tuple& t) { return scene_from(t); }))
      .def(
          "_repr_mimebundle_",
          [](const PyScene& s, const py::object&, const py::object&) -> py::object {
            // for Jupyter: the scene drawn once (drawing a scene with analyses solves it), as SVG
            // and as that SVG inline in HTML, which a notebook shows first (an exported notebook
            // keeps it: nbconvert strips an image/svg+xml output's elements, not an HTML output's)
            std::string svg;
            std::string samples;  // (said under the picture in the HTML)
            try {
              std::vector<std::string> left_out;  // (the first state drawn is named by its figure)
              svg = in_core([&] { return s.draw("", samples, left_out); });
            } catch (const std::exception&) {
              return py::none();  // (a scene that cannot be drawn shows as its repr)
            }
            py::dict out;
            out["image/svg+xml"] = svg;
            const std::string note = samples.empty() ? "" : "<p><i>Drawn with sample values for the parameters that have none: " + samples + ".</i></p>";
            out["text/html"] = "<div class=\"kinergy-scene\">" + svg + note + "</div>";
            return out;
          },
          py::arg("include") = py::none(), py::arg("exclude") = py::none(),
          sig("_repr_mimebundle_(self, include=None, exclude=None)",
              "for Jupyter: the scene drawn at its first state, as SVG and as SVG inside HTML (None when it cannot be drawn)"));

  py::class_<Verdict>(m, "Verdict", "The checks of a scene's claims: true when every one holds")
      .def("__bool__", [](const Verdict& v) { return v.ok; }, sig("__bool__(self, /)", "whether every claim holds"))
      .def_property_readonly("checks", [](const Verdict& v) { return v.checks; }, "each claim: {result, what, ok, detail}")
      .def("__repr__", [](const Verdict& v) {
        std::string out = std::string("<kinergy.Verdict ") + (v.ok ? "holds" : "FAILS") + ":";
        for (auto c : v.checks) {
          auto d = c.cast<py::dict>();
          out += " " + d["result"].cast<std::string>() + " (" + d["what"].cast<std::string>() + ") " + (d["ok"].cast<bool>() ? "ok" : "fails") + ";";
        }
        if (!v.checks.empty()) out.pop_back();
        return out + ">";
      });
  m.def("load", &load, py::arg("path"), sig("load(path)", "a scene from a YAML file (a str or any os.PathLike)"));
  m.def("loads", &loads, py::arg("text"), py::arg("name") = "<string>", sig("loads(text, name='<string>')", "a scene from YAML text"));
  // many requests, as `kinergy batch` reads them (one JSON object each): the results' lines, in
  // order; variants of a scene share its solution where it holds (batch.hpp)
  m.def(
      "_batch",
      [](const std::vector<std::string>& requests) {
        std::string all;
        for (auto& r : requests) all += r + "\n";
        const std::string out = in_core([&] {
          std::istringstream in(all);
          std::ostringstream o;
          kinergy::batch::run(in, o);
          return o.str();
        });
        std::vector<std::string> lines;
        std::istringstream split(out);
        for (std::string l; std::getline(split, l);) lines.push_back(l);
        return lines;
      },
      py::arg("requests"), sig("_batch(requests)", "each request's result line (JSON), in order"));
}
