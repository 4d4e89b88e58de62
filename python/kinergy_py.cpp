// The Python module `kinergy` (pybind11): a thin window onto the library, as the CLI is.
//   scene = kinergy.load("derivations/energy/sliding_rod.yaml")   (or kinergy.loads(yaml_text))
//   scene.set("l", "2 m"); solution = scene.solve()
//   solution.results[0].closed, .latex, .value(digits=30), float(...), .sympy()
//   solution.derive("text" | "latex" | "html"); scene.draw(state=None) -> SVG
//   solution.simulate(until, samples=1000) -> dict of NumPy arrays
// A bad scene raises kinergy.SceneError with file, line, column, message and fix.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include "kinergy/app/app.hpp"
#include "kinergy/common/error.hpp"
#include "kinergy/confirm/confirm.hpp"
#include "kinergy/common/markup.hpp"
#include "kinergy/draw/figure.hpp"
#include "kinergy/emit/derive.hpp"
#include "kinergy/emit/emit.hpp"
#include "kinergy/emit/latex.hpp"
#include "kinergy/model/simplify.hpp"
#include "kinergy/numeric/evaluate.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/scene/scene.hpp"
#include "kinergy/confirm/check.hpp"
#include "kinergy/simulate/simulate.hpp"
#include "kinergy/verify/verify.hpp"

namespace py = pybind11;
using namespace kinergy;

namespace {

struct PySolution;

// A scene as written, its parameters changeable before it is solved. It keeps its text, the name
// it was loaded under and the values set since, so that it pickles (a Dask worker rebuilds it).
struct PyScene {
  scene::SceneDef def;
  std::string text, name;
  std::vector<std::pair<std::string, std::string>> sets;

  std::map<std::string, std::string> parameters() const {
    std::map<std::string, std::string> out;
    for (auto& p : def.parameters) out[p.name] = p.value.s;
    return out;
  }
  // each parameter that has a value, in SI units (what SymPy's lambdify of a result's closed form takes)
  std::map<std::string, double> values_si() const {
    const model::Model m = model::Model::build(def);
    const GiNaC::exmap env = m.numeric_environment();
    std::map<std::string, double> out;
    for (auto& p : m.params)
      if (p.value)
        if (auto v = numerics::evaluate(*p.value, env, 20)) out[p.name] = v->to_double();
    return out;
  }
  // a parameter's value as a scene writes it ("2 kg", "30 deg", 9.81)
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
    app::set_parameter(def, parameter, v);
    sets.emplace_back(parameter, v);
  }
  std::string draw(const py::object& state) const {
    model::Model m = model::Model::build(def);
    int st = 0;
    if (!state.is_none()) {
      st = m.state_index(py::str(state).cast<std::string>());
      if (st < 0) throw InputError("there is no state '" + py::str(state).cast<std::string>() + "'", "name a state of the scene's 'states'");
    }
    if (def.analyses.empty()) return draw::scene_at(m, {}, m.parameter_values(), st).svg();
    const Solution s = solve_scene(def);
    return draw::scene_at(s.model, s.branch.sol, parameter_values(s), st).svg();
  }
};

/// GiNaC's expression e as SymPy builds it: sums, products, powers, rational and decimal numbers,
/// the elementary functions, π; a symbol of GiNaC's positive or real domain as such a SymPy
/// symbol (one per name, in `symbols`). @throws InputError for a kind of node SymPy is not given
/// (naming the result).
py::object to_sympy(const GiNaC::ex& e, const py::module_& sp, py::dict& symbols, const std::string& result) {
  using namespace GiNaC;
  auto args = [&](const ex& x) {
    py::list out;
    for (std::size_t i = 0; i < x.nops(); ++i) out.append(to_sympy(x.op(i), sp, symbols, result));
    return out;
  };
  if (is_a<symbol>(e)) {
    const symbol& x = ex_to<symbol>(e);
    const py::str name(x.get_name());
    if (!symbols.contains(name)) {
      py::dict assume;
      if (x.get_domain() == domain::positive) assume["positive"] = true;
      else if (x.get_domain() == domain::real) assume["real"] = true;
      symbols[name] = sp.attr("Symbol")(name, **assume);
    }
    return symbols[name];
  }
  if (is_a<numeric>(e)) {
    const numeric& n = ex_to<numeric>(e);
    if (!n.is_real()) return sp.attr("Add")(to_sympy(n.real(), sp, symbols, result), sp.attr("Mul")(sp.attr("I"), to_sympy(n.imag(), sp, symbols, result)));
    std::ostringstream os;
    if (n.is_integer()) return sp.attr("Integer")((os << n, os.str()));
    if (n.is_rational()) {
      std::ostringstream d;
      d << n.denom();
      return sp.attr("Rational")((os << n.numer(), os.str()), d.str());
    }
    // a decimal: its digits as GiNaC holds them (CLN prints "1.25L-3" style exponents)
    os.precision(40);
    os << n;
    std::string t = os.str();
    for (char& c : t)
      if (c == 'L' || c == 'E') c = 'e';
    return sp.attr("Float")(t, std::max<long>(15, static_cast<long>(t.size())));
  }
  if (is_a<constant>(e)) {
    if (e.is_equal(Pi)) return sp.attr("pi");
    if (e.is_equal(Euler)) return sp.attr("EulerGamma");
    if (e.is_equal(Catalan)) return sp.attr("Catalan");
  }
  if (is_a<add>(e)) return sp.attr("Add")(*args(e));
  if (is_a<mul>(e)) return sp.attr("Mul")(*args(e));
  if (is_a<power>(e)) return sp.attr("Pow")(*args(e));
  if (is_a<function>(e)) {
    static const std::map<std::string, std::string> names{
        {"sin", "sin"},   {"cos", "cos"},   {"tan", "tan"},     {"asin", "asin"},   {"acos", "acos"},   {"atan", "atan"},
        {"atan2", "atan2"}, {"sinh", "sinh"}, {"cosh", "cosh"}, {"tanh", "tanh"},   {"asinh", "asinh"}, {"acosh", "acosh"},
        {"atanh", "atanh"}, {"exp", "exp"},   {"log", "log"},   {"abs", "Abs"},     {"csgn", "sign"},   {"step", "Heaviside"},
        {"factorial", "factorial"}};
    const std::string f = ex_to<function>(e).get_name();
    if (auto it = names.find(f); it != names.end()) return sp.attr(it->second.c_str())(*args(e));
    if (f == "integral") {
      // ∫_a^b f ds (a work with no elementary antiderivative): integral(f, s, a, b)
      const py::list a = args(e);
      return sp.attr("Integral")(a[0], py::make_tuple(a[1], a[2], a[3]));
    }
    throw InputError("result '" + result + "' holds the function " + f + ", which kinergy does not hand to SymPy", "use .closed (its text) instead");
  }
  throw InputError("result '" + result + "' holds " + emit::plain(e) +
                       ", which kinergy does not hand to SymPy",
                   "use .closed (its text) instead");
}

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
  // the value proven by ball arithmetic, as `kinergy solve --digits N --json` gives it
  py::dict ball(long long digits) const {
    check_digits(digits);
    const int n = static_cast<int>(digits);
    if (!r().si) throw InputError("'" + r().name + "' has no value: a parameter in it has none", "give every parameter a value");
    auto v = r().evaluate(s->model.numeric_environment(), n, false);
    if (!v) throw InputError("'" + r().name + "' could not be evaluated", "ask for fewer digits");
    auto [mid, rad] = v->ball(n);
    py::dict d;
    d["value"] = numerics::format(v->v, n);
    d["proven"] = v->proven;
    d["midpoint"] = mid;
    d["radius"] = rad.empty() ? py::object(py::none()) : py::object(py::str(rad));
    d["evaluation"] = v->note();
    return d;
  }
  // the closed form as a SymPy expression, built from GiNaC's tree (not parsed from text: '^' is
  // not XOR, a parameter may be named 'lambda'), each symbol positive or real as kinergy knows it
  py::object sympy() const {
    const py::module_ sp = py::module_::import("sympy");
    py::dict symbols;
    return to_sympy(r().closed, sp, symbols, r().name);
  }
};

// what Solution.verify() gives: whether every claim holds, and each claim's check
struct Verdict {
  bool ok = true;
  py::list checks;
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
  std::string derive(const std::string& format) const {
    const emit::Derivation d = emit::derive(*s);
    if (format == "text") return emit::text(d);
    if (format == "latex") return emit::latex(d);
    if (format == "html") return app::derivation_page(*s, d);
    throw InputError("there is no derivation format '" + format + "'", "ask for 'text', 'latex' or 'html'");
  }
  // every claim of the scene's expect, as batch gives them: a list of {result, what, ok, detail};
  // the Verdict is true when every one holds
  py::object verify() const {
    py::list checks;
    bool all = true;
    for (auto& c : verify::verify(*s)) {
      py::dict d;
      d["result"] = c.name;
      d["what"] = c.what;
      d["ok"] = c.ok();
      d["detail"] = c.detail;
      checks.append(d);
      all = all && c.ok();
    }
    return py::cast(Verdict{all, checks});
  }
  // t, q, q̇, T, V at regular times (as `kinergy simulate --samples`), as NumPy arrays
  py::dict simulate(double until, int samples, const py::object& start) const {
    namespace sim = simulate;
    const model::Model& m = s->model;
    const int from = app::state_index(m, start.is_none() ? std::string() : py::str(start).cast<std::string>());
    sim::State s0 = app::start_values(m, s.get(), from);
    if (!(until > s0.t) || samples < 1) throw InputError("the run must end after it starts, with one sample or more", "give until > the start's time");
    sim::Options o;
    o.native = false;
    o.sample_dt = (until - s0.t) / samples;
    const sim::Run r = sim::run_following(m, s->branch.sol, parameter_values(*s), from, s0, until, o, sim::impulses_at(m, from));
    py::module_ np = py::module_::import("numpy");
    std::vector<double> t, T, V;
    std::vector<std::vector<double>> q, qd;
    for (auto& x : r.samples) {
      t.push_back(x.t);
      q.push_back(x.q);
      qd.push_back(x.qd);
      T.push_back(x.T);
      V.push_back(x.V);
    }
    std::vector<std::string> coords;
    for (auto& c : m.coords) coords.push_back(c.name);
    py::dict out;
    out["t"] = np.attr("array")(t);
    out["q"] = np.attr("array")(q);
    out["q_dot"] = np.attr("array")(qd);
    out["T"] = np.attr("array")(T);
    out["V"] = np.attr("array")(V);
    out["coordinates"] = coords;
    std::vector<double> impacts;
    for (auto& im : r.impacts) impacts.push_back(im.t);
    out["impacts"] = np.attr("array")(impacts);
    return out;
  }
  // for Jupyter: the results as LaTeX and as an HTML table
  std::string repr_latex() const {
    std::string o = "$\\begin{aligned}";
    for (std::size_t i = 0; i < s->results.size(); ++i) {
      const Result& r = s->results[i];
      o += (i ? "\\\\ " : "") + emit::tex_name(r.name) + " &= " + emit::latex(r.closed);
      if (r.si) o += " = " + PyResult{s, i}.value(6) + (r.unit.empty() ? "" : "\\ \\mathrm{" + r.unit + "}");
    }
    return o + "\\end{aligned}$";
  }
  std::string repr_html() const {
    std::string o = "<table><tr><th>result</th><th>closed form</th><th>value</th><th>unit</th></tr>";
    auto esc = [](const std::string& x) { return xml_escape(x); };
    for (std::size_t i = 0; i < s->results.size(); ++i) {
      const Result& r = s->results[i];
      o += "<tr><td>" + esc(r.name) + "</td><td><code>" + esc(emit::plain(r.closed)) + "</code></td><td>" +
           (r.si ? PyResult{s, i}.value(15) : std::string()) + "</td><td>" + esc(r.unit) + "</td></tr>";
    }
    return o + "</table>";
  }
};

// a path as Python gives it: str, pathlib.Path or any os.PathLike
PyScene load(const py::object& path) {
  const std::string p = py::str(py::module_::import("os").attr("fspath")(path));
  PyScene sc{scene::load_file(p), "", p, {}};
  std::ifstream f(p, std::ios::binary);
  std::ostringstream text;
  text << f.rdbuf();
  sc.text = text.str();
  return sc;
}
PyScene loads(const std::string& text, const std::string& name) { return {scene::load_string(text, name), text, name, {}}; }
PySolution solve_scene_def(const PyScene& sc, bool confirmed) {
  Solution s = solve_scene(sc.def);
  if (confirmed) confirm(s);  // each analysis a second way: a disagreement raises SceneError
  return {std::make_shared<const Solution>(std::move(s)), sc, confirmed};
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

// "omega2 = 3.502 rad/s" (or its closed form, when a parameter has no value)
std::string shown(const PyResult& r) {
  if (!r.r().si) return r.r().name + " = " + emit::plain(r.r().closed);
  return r.r().name + " = " + r.value(4) + (r.r().unit.empty() ? "" : " " + r.r().unit);
}

}  // namespace

PYBIND11_MODULE(kinergy, m) {
  m.doc() = "kinergy: plane rigid-body motion by energy and momentum, in closed form";
  m.attr("__version__") = KINERGY_VERSION;
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
    } catch (const SceneError& e) {
      raise(e.what(), e.pos().file, e.pos().line, e.pos().col, e.problem(), e.fix());
    } catch (const InputError& e) {
      raise(std::string(e.what()) + " \u2014 " + e.fix(), "", 0, 0, e.what(), e.fix());
    } catch (const simulate::SimulationError& e) {
      // a run that cannot be made (until = inf, a step limit, a slip): the module's error, not RuntimeError
      const std::string at = e.pos().file.empty() ? std::string() : e.pos().str() + ": ";
      raise(at + e.what() + " \u2014 " + e.fix(), e.pos().file, e.pos().line, e.pos().col, e.what(), e.fix());
    }
  });

  py::class_<PyResult>(m, "Result", "One result of a solved scene")
      .def_property_readonly("name", [](const PyResult& r) { return r.r().name; })
      .def_property_readonly("unit", [](const PyResult& r) { return r.r().unit; })
      .def_property_readonly("closed", [](const PyResult& r) { return emit::plain(r.r().closed); }, "the closed form as text")
      .def_property_readonly("latex", [](const PyResult& r) { return emit::latex(r.r().closed); }, "the closed form in LaTeX")
      .def_property_readonly("closed_form", [](const PyResult& r) { return r.r().closed_form; }, "False when a numeric root was needed")
      .def("value", &PyResult::value, py::arg("digits") = 15, "its value in its unit to `digits` significant digits (text)")
      .def("ball", &PyResult::ball, py::arg("digits") = 30,
           "its value to `digits` proven digits (ball arithmetic): a dict of value, proven, midpoint, radius (the exact "
           "value lies within radius of midpoint; None when not proven) and evaluation")
      .def("__float__", &PyResult::to_float)
      .def_property_readonly(
          "si", [](const PyResult& r) -> py::object { return r.r().si ? py::object(py::float_(r.r().si->to_double())) : py::object(py::none()); },
          "its value in SI units, as its closed form gives it (None when a parameter has no value)")
      .def("sympy", &PyResult::sympy, "the closed form as a SymPy expression (sympy must be installed)")
      .def("__format__",
           [](const PyResult& r, const std::string& spec) {
             // f"{r:.3f}": its value in its unit, formatted as a float is
             return py::module_::import("builtins").attr("format")(py::float_(r.to_float()), spec);
           })
      .def("__repr__", [](const PyResult& r) {
        return "<kinergy.Result " + r.r().name + " = " + emit::plain(r.r().closed) +
               (r.r().si ? " = " + r.value(4) + (r.r().unit.empty() ? "" : " " + r.r().unit) : std::string()) + ">";
      });

  py::class_<PySolution>(m, "Solution", "A solved scene")
      .def_property_readonly("results", &PySolution::results)
      .def_property_readonly(
          "confirmed",
          [](const PySolution& s) {
            // how each analysis was confirmed a second way: [{analysis, by, difference, note}]
            py::list out;
            for (auto& c : s.s->confirmed) {
              const auto& a = s.s->model.analyses[static_cast<std::size_t>(c.analysis)];
              py::dict d;
              d["analysis"] = a.kind + " " + s.s->model.states[static_cast<std::size_t>(a.from)].name + " -> " +
                              s.s->model.states[static_cast<std::size_t>(a.to)].name;
              d["by"] = c.by == kinergy::Confirmed::By::None ? py::object(py::none()) : py::object(py::str(kinergy::Confirmed::name(c.by)));
              d["difference"] = c.difference;
              d["note"] = c.note;
              out.append(d);
            }
            return out;
          },
          "how each analysis was confirmed a second way (empty with solve(confirm=False))")
      .def("__getitem__",
           [](const PySolution& s, const std::string& name) {
             for (auto& r : s.results())
               if (r.r().name == name) return r;
             throw py::key_error(name);
           })
      // a mapping of the results by name, in the scene's order
      .def("__len__", [](const PySolution& s) { return s.s->results.size(); })
      .def("__contains__",
           [](const PySolution& s, const py::object& name) {
             if (!py::isinstance<py::str>(name)) return false;
             const std::string n = name.cast<std::string>();
             return std::any_of(s.s->results.begin(), s.s->results.end(), [&](const Result& r) { return r.name == n; });
           })
      .def("keys",
           [](const PySolution& s) {
             py::list out;
             for (auto& r : s.s->results) out.append(r.name);
             return out;
           })
      .def("__iter__",
           [](const PySolution& s) {
             py::list out;
             for (auto& r : s.s->results) out.append(r.name);
             return py::iter(out);
           })
      .def("values", &PySolution::results)
      .def("items",
           [](const PySolution& s) {
             py::list out;
             for (auto& r : s.results()) out.append(py::make_tuple(r.r().name, r));
             return out;
           })
      .def("__repr__",
           [](const PySolution& s) {
             std::string out = "<kinergy.Solution of '" + s.s->scene.title + "':";
             for (auto& r : s.results()) out += " " + shown(r) + ";";
             if (!s.s->results.empty()) out.pop_back();
             return out + ">";
           })
      .def(py::pickle([](const PySolution& s) { return py::make_tuple(scene_state(s.scene), s.confirmed); },
                      [](const py::tuple& t) {
                        if (t.size() != 2) throw InputError("a pickled kinergy.Solution holds its scene and whether it was confirmed", "pickle it with this version of kinergy");
                        return solve_scene_def(scene_from(t[0].cast<py::tuple>()), t[1].cast<bool>());
                      }))
      .def("derive", &PySolution::derive, py::arg("format") = "text", "the worked solution: 'text', 'latex' or 'html'")
      .def("verify", &PySolution::verify,
           "every claim of the scene's expect checked: a Verdict, true when each holds, with .checks (result, what, ok, detail)")
      .def("simulate", &PySolution::simulate, py::arg("until"), py::arg("samples") = 1000, py::arg("start") = py::none(),
           "the motion from a state (the first by default) until a time, at regular samples: t, q, q_dot, T, V (NumPy)")
      .def("_repr_latex_", &PySolution::repr_latex)
      .def("_repr_html_", &PySolution::repr_html);

  py::class_<PyScene>(m, "Scene", "A scene as written: change its parameters, solve it, draw it")
      .def_property_readonly("title", [](const PyScene& s) { return s.def.title; })
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
          "give parameters values: set('l', '2 m'), set('l', 2.0) (a number in the unit the scene writes it in), or "
          "set(l='2 m', theta2=45); each checked at once")
      .def("values_si", &PyScene::values_si, "name -> value in SI units, for each parameter that has one")
      .def("solve", &solve_scene_def, py::arg("confirm") = true,
           "solve it: each result in closed form and its value, each analysis confirmed a second way (a simulation of the same "
           "scene, else the equations' residuals at 50 digits) unless confirm=False")
      .def("draw", &PyScene::draw, py::arg("state") = py::none(), "the scene at a state (the first by default) as SVG")
      .def("__repr__",
           [](const PyScene& s) {
             std::string out = "<kinergy.Scene '" + s.def.title + "' (" + s.name + ")";
             for (std::size_t i = 0; i < s.def.parameters.size(); ++i)
               out += (i ? ", " : ": ") + s.def.parameters[i].name + " = " + s.def.parameters[i].value.s;
             return out + ">";
           })
      .def(py::pickle([](const PyScene& s) { return scene_state(s); }, [](const py::tuple& t) { return scene_from(t); }))
      .def("_repr_svg_", [](const PyScene& s) -> py::object {
        try {
          return py::str(s.draw(py::none()));
        } catch (const std::exception&) {
          return py::none();
        }
      });

  py::class_<Verdict>(m, "Verdict", "The checks of a scene's claims: true when every one holds")
      .def("__bool__", [](const Verdict& v) { return v.ok; })
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
  m.def("load", &load, py::arg("path"), "a scene from a YAML file");
  m.def("loads", &loads, py::arg("text"), py::arg("name") = "<string>", "a scene from YAML text");
}
