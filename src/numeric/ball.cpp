#include "kinergy/numeric/ball.hpp"

#include <dlfcn.h>
#include <sys/auxv.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <string>

#include <cln/cln.h>
#include <cln/integer_io.h>

#include "arb_api.hpp"
#include "kinergy/common/error.hpp"
#include "kinergy/numeric/evaluate.hpp"

#ifndef KINERGY_LIBDIR
#define KINERGY_LIBDIR "lib"
#endif
#ifndef KINERGY_ARB_INSTALLED
#define KINERGY_ARB_INSTALLED ""
#endif
#ifndef KINERGY_ARB_BUILT
#define KINERGY_ARB_BUILT ""
#endif

namespace kinergy::numerics {

using namespace GiNaC;
namespace api = arbapi;

namespace {

/// The ball arithmetic module, loaded once, when first needed (arb_api.hpp says why). Looked for:
/// $KINERGY_ARB_MODULE; beside the program or module that holds this code (a build directory),
/// in <prefix>/LIBDIR/kinergy/ from <prefix>/bin (the CLI) or from <prefix>/lib/python3.x/
/// dist-packages (the Python module); where it was installed; where it was built.
const api::Api& module() {
  static const api::Api* loaded = nullptr;
  static std::string failure;
  static std::once_flag once;
  std::call_once(once, [] {
    std::vector<std::string> tried;
    if (const char* env = std::getenv("KINERGY_ARB_MODULE"); env && *env) {
      tried.push_back(env);
    } else {
      // the file that holds this code: a shared module (the Python one) by dladdr; the program
      // itself by the file name execve was given (AT_EXECFN: the path a shell found on PATH;
      // dladdr names the main program by its argv[0], which may be a bare name)
      std::vector<std::filesystem::path> selves;
      Dl_info info{};
      std::error_code err;
      if (dladdr(reinterpret_cast<void*>(&bits_for), &info) && info.dli_fname && std::strchr(info.dli_fname, '/'))
        selves.push_back(std::filesystem::weakly_canonical(std::filesystem::absolute(info.dli_fname), err));
      if (const auto* exe = reinterpret_cast<const char*>(getauxval(AT_EXECFN)); exe && std::strchr(exe, '/'))
        selves.push_back(std::filesystem::weakly_canonical(std::filesystem::absolute(exe), err));
      for (auto& self : selves) {
        const std::filesystem::path dir = self.parent_path();
        for (const std::filesystem::path& p :
             {dir / "kinergy_arb.so", dir.parent_path() / "kinergy_arb.so", dir.parent_path() / KINERGY_LIBDIR / "kinergy" / "kinergy_arb.so",
              dir.parent_path().parent_path().parent_path() / KINERGY_LIBDIR / "kinergy" / "kinergy_arb.so"})
          if (std::find(tried.begin(), tried.end(), p.lexically_normal().string()) == tried.end()) tried.push_back(p.lexically_normal().string());
      }
      for (const char* p : {KINERGY_ARB_INSTALLED, KINERGY_ARB_BUILT})
        if (*p) tried.push_back(p);
    }
    std::string errors;
    for (auto& p : tried) {
      if (!std::filesystem::exists(p)) continue;
      void* h = dlopen(p.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (!h) {
        errors += std::string("; ") + dlerror();
        continue;
      }
      auto entry = reinterpret_cast<const api::Api* (*)()>(dlsym(h, "kinergy_arb_api"));
      if (entry && entry()->version == api::kVersion) {
        loaded = entry();
        return;
      }
      errors += "; " + p + " is not kinergy's ball arithmetic module of this version";
    }
    failure = "the ball arithmetic module kinergy_arb.so was not found";
    if (!tried.empty()) {
      failure += " (looked for";
      for (auto& p : tried) failure += " " + p;
      failure += ")";
    }
    failure += errors;
  });
  if (!loaded)
    throw InputError(failure + ": proven digits need it",
                     "reinstall kinergy (it installs <prefix>/" KINERGY_LIBDIR "/kinergy/kinergy_arb.so), or set KINERGY_ARB_MODULE to its path");
  return *loaded;
}

bool is_float(const ex& e) { return is_a<numeric>(e) && ex_to<numeric>(e).is_real() && !ex_to<numeric>(e).is_rational(); }

/// A float anywhere in e (a number found numerically).
bool holds_float(const ex& e) {
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
    if (is_float(*it)) return true;
  return false;
}

std::string decimal(const cln::cl_I& n) {
  std::ostringstream os;
  cln::fprintdecimal(os, n);
  return os.str();
}

/// An exact rational (a float: the binary fraction it is) as the module's constant.
api::Const rational(const numeric& v) {
  const cln::cl_RA q = v.is_rational() ? cln::the<cln::cl_RA>(v.to_cl_N()) : cln::rational(cln::the<cln::cl_R>(v.to_cl_N()));
  return {api::Const::Rational, decimal(cln::numerator(q)), decimal(cln::denominator(q))};
}

/// Signed hexadecimal digits ("-1f") as an integer.
cln::cl_I from_hex(const std::string& s) {
  const bool neg = !s.empty() && s[0] == '-';
  const char* p = s.c_str() + (neg ? 1 : 0);
  return cln::read_integer(16, neg ? -1 : 0, p, 0, std::strlen(p));
}

/// m · 2^e exactly, as a CLN float with as many bits as m (a rational would cost a gcd, and a
/// rational of 2^400000 would make every later step slow).
numeric scaled(const cln::cl_I& m, long e) {
  if (cln::zerop(m)) return 0;
  const long bits = std::max<long>(static_cast<long>(cln::integer_length(m)) + 2, 64);
  const cln::cl_F f = cln::cl_float(m, cln::float_format(static_cast<long>(static_cast<double>(bits) * 0.30103) + 2));
  return numeric(cln::cl_N(cln::scale_float(f, e)));
}

/// ±(hi · 2⁶⁴ + lo) as an integer.
cln::cl_I from_limbs(const std::uint64_t* limbs, bool negative) {
  const cln::cl_I m = cln::logior(cln::ash(cln::cl_I(static_cast<unsigned long>(limbs[1])), 64), cln::cl_I(static_cast<unsigned long>(limbs[0])));
  return negative ? cln::cl_I(-m) : m;
}

/// The ends' integers a, b of [a · 2^e, b · 2^e].
std::pair<cln::cl_I, cln::cl_I> end_integers(const api::Interval& i) {
  if (i.small) return {from_limbs(i.a_limbs, i.a_negative), from_limbs(i.b_limbs, i.b_negative)};
  return {from_hex(i.a), from_hex(i.b)};
}

Enclosure enclosure(const api::Interval& i) {
  const auto [a, b] = end_integers(i);
  return {scaled(a, i.e), scaled(b, i.e)};
}

/// The enclosure and its midpoint (a + b) · 2^(e−1), exact, from the integers.
std::pair<Enclosure, numeric> enclosure_and_mid(const api::Interval& i) {
  const auto [a, b] = end_integers(i);
  return {{scaled(a, i.e), scaled(b, i.e)}, scaled(a + b, i.e - 1)};
}

}  // namespace

/// The tape in plain numbers (a friend of Tape: it reads the instructions).
struct detail::BallRun {
  static api::Program program(const Tape& t) {
    // the module numbers the operations as Tape::Op does
    static_assert(static_cast<int>(Tape::Op::Const) == 0 && static_cast<int>(Tape::Op::Input) == 1 &&
                  static_cast<int>(Tape::Op::Pow) == 11 && static_cast<int>(Tape::Op::Atan2) == 18 &&
                  static_cast<int>(Tape::Op::Tanh) == 24 && static_cast<int>(Tape::Op::Integral) == 25);
    api::Program p;
    p.inputs = t.n_inputs_;
    for (auto& in : t.code_) p.code.push_back({static_cast<std::uint8_t>(in.op), in.a, in.b, in.c});
    for (auto& c : t.exact_) {
      if (c.is_equal(Pi)) p.consts.push_back({api::Const::Pi});
      else if (c.is_equal(Euler)) p.consts.push_back({api::Const::Euler});
      else if (c.is_equal(Catalan)) p.consts.push_back({api::Const::Catalan});
      else if (is_a<numeric>(c) && ex_to<numeric>(c).is_real()) p.consts.push_back(rational(ex_to<numeric>(c)));
      else throw std::invalid_argument("a constant ball arithmetic does not know");
    }
    p.outs.assign(t.outs_.begin(), t.outs_.end());
    for (auto& f : t.integrands_) p.integrands.push_back(program(*f));
    return p;
  }
  /// A float among the tape's constants, or its integrands' (a number found numerically, written
  /// into the form).
  static bool has_float(const Tape& t) {
    for (auto& c : t.exact_)
      if (is_float(c)) return true;
    for (auto& f : t.integrands_)
      if (has_float(*f)) return true;
    return false;
  }
};

namespace {

/// An input's exact value as a program of its own (a rational: one constant).
api::Program input_program(const ex& v) {
  if (is_a<numeric>(v) && ex_to<numeric>(v).is_real()) {
    api::Program p;
    p.code.push_back({0, 0, -1, 0});
    p.consts.push_back(rational(ex_to<numeric>(v)));
    p.outs.push_back(0);
    return p;
  }
  return detail::BallRun::program(Tape::compile(v, {}));  // π/6, √2, …
}

/// The module's answer as a Proven; nothing when proven undefined. @throws std::domain_error.
std::optional<Proven> proven(const api::Answer& a) {
  switch (a.kind) {
    case 0: {
      Enclosure e = enclosure(a.at);
      return Proven{Proven::Kind::Exact, e.lo, e, a.bits};
    }
    case 1: {
      auto [e, mid] = enclosure_and_mid(a.at);
      return Proven{Proven::Kind::Digits, mid, e, a.bits};
    }
    case 2: return Proven{Proven::Kind::Unsigned, 0, enclosure(a.at), a.bits};
    case 3: return std::nullopt;
    default: throw std::domain_error(a.error);
  }
}

}  // namespace

struct BallEvaluator::Impl {
  const api::Api& m;
  void* handle;
  Impl(const api::Api& api, void* h) : m(api), handle(h) {}
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  ~Impl() { m.destroy(handle); }
};

BallEvaluator::BallEvaluator(const Tape& t, const std::vector<ex>& inputs) {
  from_float_ = detail::BallRun::has_float(t) || std::any_of(inputs.begin(), inputs.end(), holds_float);
  std::vector<api::Program> in;
  for (auto& v : inputs) in.push_back(input_program(v));
  const api::Api& m = module();
  impl_ = std::make_unique<Impl>(m, m.create(detail::BallRun::program(t), in));  // in place: its destructor frees the handle
}
BallEvaluator::~BallEvaluator() = default;
BallEvaluator::BallEvaluator(BallEvaluator&&) noexcept = default;
BallEvaluator& BallEvaluator::operator=(BallEvaluator&&) noexcept = default;

std::optional<Proven> BallEvaluator::digits(int n, long max_bits) const { return proven(impl_->m.digits(impl_->handle, n, max_bits)); }

namespace {

/// An input known to lie in [lo, hi] as the module's program (an Interval constant).
api::Program interval_program(const Enclosure& e) {
  api::Program x;
  x.code.push_back({0, 0, -1, 0});
  api::Const c = rational(e.lo);
  const api::Const hi = rational(e.hi);
  c.kind = api::Const::Interval;
  c.num2 = hi.num;
  c.den2 = hi.den;
  x.consts.push_back(c);
  x.outs.push_back(0);
  return x;
}

/// A proven value as what it encloses: the point itself when exact.
Enclosure enclosed(const Proven& p) { return p.kind == Proven::Kind::Exact ? Enclosure{p.value, p.value} : p.at; }

/// root_digits with inputs known only to balls (other roots' enclosures); n ≤ 0: an enclosure at
/// the precision of |n| digits, whatever digits it fixes.
std::optional<Proven> root_in_balls(const ex& r, const symbol& u, const numeric& x0, const numeric& lo, const numeric& hi,
                                    const exmap& values, const std::vector<std::pair<ex, Enclosure>>& balls, int n, long max_bits) {
  std::vector<ex> in{u};
  std::vector<api::Program> inputs{input_program(x0)};
  for (auto& [s, e] : balls)
    if (r.has(s) && !s.is_equal(u)) {
      in.push_back(s);
      inputs.push_back(interval_program(e));
    }
  for (auto& [s, v] : values) {
    const ex& sym = s;  // (a structured binding is not captured by a lambda before C++20 in every compiler)
    if (r.has(sym) && !sym.is_equal(u) && std::none_of(balls.begin(), balls.end(), [&](const auto& b) { return b.first.is_equal(sym); })) {
      if (holds_float(v)) return std::nullopt;
      in.push_back(sym);
      inputs.push_back(input_program(v));
    }
  }
  Tape tr, td;
  try {
    tr = Tape::compile(r, in, Tape::Accept::Integrals);
    td = Tape::compile(r.diff(u), in, Tape::Accept::Integrals);
  } catch (const std::invalid_argument&) {
    return std::nullopt;  // a function the tape has no instruction for, or a symbol without a value
  }
  if (detail::BallRun::has_float(tr) || detail::BallRun::has_float(td)) return std::nullopt;
  // the start as the exact binary fraction a float is: it is only where Newton begins
  const api::Answer a = module().root(detail::BallRun::program(tr), detail::BallRun::program(td), inputs, rational(x0), rational(lo),
                                      rational(hi), lo < hi, n, max_bits);
  if (a.kind != 0 && a.kind != 1) return std::nullopt;
  return proven(a);
}

}  // namespace

std::optional<Proven> root_digits(const ex& r, const symbol& u, const numeric& x0, const numeric& lo, const numeric& hi,
                                  const exmap& values, int n, long max_bits) {
  return root_in_balls(r, u, x0, lo, hi, values, {}, n, max_bits);
}

std::optional<Proven> digits_at_roots(const ex& g, const std::vector<RootOf>& roots, const exmap& values, int n, long max_bits) {
  // the inputs: the roots' unknowns, then g's other symbols with their values
  std::vector<ex> syms;
  std::vector<api::Program> given;
  for (auto& r : roots) syms.push_back(r.u);
  for (auto& [s, v] : values) {
    const ex& sym = s;  // (not captured as a structured binding: see root_in_balls)
    if (!g.has(sym) || std::any_of(roots.begin(), roots.end(), [&](const RootOf& r) { return r.u.is_equal(sym); })) continue;
    if (holds_float(v)) return std::nullopt;
    syms.push_back(sym);
    given.push_back(input_program(v));
  }
  Tape t;
  try {
    t = Tape::compile(g, syms, Tape::Accept::Integrals);
  } catch (const std::invalid_argument&) {
    return std::nullopt;  // a function the tape has no instruction for, or a symbol without a value
  }
  if (detail::BallRun::has_float(t)) return std::nullopt;
  // an integral in g or in a root's equation: capped by the n digits asked, as the module caps a
  // tape's own (api::integral_bits)
  bool integrals = t.has_integrals();
  for (auto& r : roots)
    for (auto it = r.residual.preorder_begin(); it != r.residual.preorder_end(); ++it) integrals = integrals || is_integral(*it);
  if (integrals) max_bits = std::min(max_bits, api::integral_bits(n));
  const api::Program program = detail::BallRun::program(t);
  const api::Api& m = module();
  for (int digits = n + 10;; digits *= 2) {
    const long bits = std::min(max_bits, bits_for(digits) + 64);
    // each root enclosed at this precision, in order: a root whose equation holds an earlier
    // root (two roots chained) takes that root's enclosure as an input known to its ball
    std::vector<api::Program> in;
    std::vector<std::pair<ex, Enclosure>> balls;
    for (auto& r : roots) {
      if (!is_a<symbol>(r.u)) return std::nullopt;
      auto p = root_in_balls(r.residual, ex_to<symbol>(r.u), r.at, r.lo, r.hi, values, balls, -digits, max_bits);
      if (!p) return std::nullopt;
      balls.emplace_back(r.u, enclosed(*p));
      in.push_back(interval_program(balls.back().second));
    }
    in.insert(in.end(), given.begin(), given.end());
    BallEvaluator::Impl run(m, m.create(program, in));
    const api::Answer a = m.digits(run.handle, n, bits);
    if (a.kind == 0 || a.kind == 1 || a.kind == 2) return proven(a);
    if (a.kind == 3 || bits >= max_bits) return std::nullopt;  // undefined on the roots' balls, or no precision fixes it
  }
}

long bits_for(int n) { return api::bits_for(n); }

long digits_in(long bits) { return static_cast<long>(static_cast<double>(bits) * 0.30102999566398120); }

numeric round_up2(const numeric& x) {
  if (!x.is_positive()) return 0;
  if (!x.is_rational()) {
    // a float (beyond 2^±4096): its decimal exponent from its binary one, the quotient taken in
    // floats and raised by a relative 2^−40 so that rounding cannot take it below x
    const cln::cl_F f = cln::the<cln::cl_F>(x.to_cl_N());
    const long e2 = cln::float_exponent(f);
    long k = static_cast<long>(std::floor(static_cast<double>(e2) * 0.30102999566398120)) - 2;
    auto up = [&](long kk) {
      const cln::cl_F q = f / cln::expt(cln::cl_float(10, cln::float_format(40)), cln::cl_I(kk));
      return cln::ceiling1(q * cln::cl_float(1 + cln::expt(cln::cl_RA(2), -40), cln::float_format(40)));
    };
    cln::cl_I d = up(k);
    while (d > 100) d = up(++k);
    while (d <= 10) d = up(--k);
    return numeric(cln::cl_N(cln::cl_float(d, cln::float_format(20)) * cln::expt(cln::cl_float(10, cln::float_format(40)), cln::cl_I(k))));
  }
  // x ≤ d · 10^k with d of two digits, d = ⌈x / 10^k⌉, k chosen so that 10 < d ≤ 100
  const cln::cl_RA q = cln::the<cln::cl_RA>(x.to_cl_N());
  const long l2 = static_cast<long>(cln::integer_length(cln::numerator(q))) - static_cast<long>(cln::integer_length(cln::denominator(q)));
  long k = static_cast<long>(std::floor(static_cast<double>(l2) * 0.30102999566398120)) - 2;  // log₁₀ x within 1
  auto up = [&](long kk) { return cln::ceiling1(q / cln::expt(cln::cl_RA(10), kk)); };
  cln::cl_I d = up(k);
  while (d > 100) d = up(++k);
  while (d <= 10) {
    cln::cl_I e = up(k - 1);
    if (e > 100) break;
    d = e;
    --k;
  }
  return numeric(cln::cl_N(d * cln::expt(cln::cl_RA(10), k)));
}

}  // namespace kinergy::numerics
