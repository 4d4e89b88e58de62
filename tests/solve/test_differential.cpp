// The differential test (issue 25): every derivation's parameters perturbed (a fixed seed, five
// variants each, values within the physical range: masses, lengths and forces scaled 0.5–2×, angles
// 0.9–1.1×, 0 < e ≤ 1, μ < 1), each variant solved and confirmed a second way (by default: a
// simulation of the same scene, or the equations' residuals), in two processes — one with address
// randomisation off (setarch -R) — that must print the same bytes. A variant may be refused (a
// state it no longer reaches, a root that is gone): that is an answer; a disagreement between the
// closed form and the simulation, a difference between the runs, or an internal error is not.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <random>
#include <sstream>
#include <unistd.h>

#include "../support/helpers.hpp"
#include "kinergy/units/units.hpp"

namespace {

/// A uniform number in [lo, hi) from the generator's raw 32-bit output (std::mt19937's output is
/// fixed by the standard; its distributions are not).
double uniform(std::mt19937& rng, double lo, double hi) { return lo + (hi - lo) * (static_cast<double>(rng()) / 4294967296.0); }

/// A number written with 4 significant digits, as a scene writes it.
std::string decimal(double v) {
  std::ostringstream os;
  os << std::setprecision(4) << v;
  return os.str();
}

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

/// The perturbed value of parameter `name` written `text` ("5 kg", "0.4", "30 deg"), or "" to keep it.
std::string perturbed(const std::string& name, const std::string& text, std::mt19937& rng) {
  std::istringstream in(text);
  std::string number, unit;
  in >> number;
  std::getline(in, unit);
  while (!unit.empty() && unit.front() == ' ') unit.erase(unit.begin());
  char* end = nullptr;
  const double v = std::strtod(number.c_str(), &end);
  if (end == number.c_str() || *end != '\0' || !(v > 0)) return "";  // symbolic, unknown or not positive: kept
  if (unit.empty()) {
    if (name == "e" || name.rfind("e_", 0) == 0 || name.rfind("e1", 0) == 0 || name.rfind("e2", 0) == 0)
      return decimal(uniform(rng, 0.05, 1.0));  // 0 < e ≤ 1
    if (name.rfind("mu", 0) == 0) return decimal(uniform(rng, 0.05, 0.9));  // μ < 1
    return "";
  }
  kinergy::units::Dimension d;
  try {
    d = kinergy::units::parse_unit(unit).dim;
  } catch (const std::exception&) {
    return "";
  }
  // masses and lengths, and weights (a US problem gives its masses as weights in lb)
  const kinergy::units::Dimension force = kinergy::units::Dimension::mass() * kinergy::units::Dimension::length() / (kinergy::units::Dimension::time() * kinergy::units::Dimension::time());
  if (d == kinergy::units::Dimension::mass() || d == kinergy::units::Dimension::length() || d == force) return decimal(v * uniform(rng, 0.5, 2.0)) + " " + unit;
  if (unit == "deg" || unit == "rad") return decimal(v * uniform(rng, 0.9, 1.1)) + " " + unit;
  return "";
}

std::string run(const std::string& command) {
  std::string out;
  FILE* p = popen(command.c_str(), "r");
  REQUIRE(p != nullptr);
  char buf[65536];
  for (std::size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
  CHECK(pclose(p) != -1);
  return out;
}

}  // namespace

TEST_CASE("differential: every derivation perturbed, confirmed a second way, the same bytes with and without address randomisation",
          "[differential]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("kinergy_differential_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path requests = dir / "requests.jsonl";
  std::mt19937 rng(20261126);
  int n = 0;
  {
    std::ofstream out(requests);
    for (auto& f : kt::scene_files("derivations")) {
      const auto def = kinergy::scene::load_file(f);
      for (int k = 0; k < 5; ++k) {
        std::string set;
        for (auto& p : def.parameters) {
          const std::string v = perturbed(p.name, p.value.s, rng);
          if (!v.empty()) set += (set.empty() ? "" : ", ") + json_string(p.name) + ": " + json_string(v);
        }
        out << "{\"scene\": " << json_string(f) << ", \"id\": " << json_string(fs::path(f).filename().string() + "#" + std::to_string(k))
            << ", \"set\": {" << set << "}}\n";
        ++n;
      }
    }
  }
  const std::string cli = KINERGY_CLI;
  const std::string plain = run(cli + " batch " + requests.string() + " 2>/dev/null");
  const std::string fixed = run("setarch \"$(uname -m)\" -R " + cli + " batch " + requests.string() + " 2>/dev/null");
  if (!std::getenv("KINERGY_KEEP_DIFFERENTIAL")) fs::remove_all(dir);  // kept when set: the requests and both outputs
  else {
    std::ofstream(dir / "plain.jsonl") << plain;
    std::ofstream(dir / "fixed.jsonl") << fixed;
  }
  // the same bytes, with and without address randomisation (the first line that differs shown)
  {
    std::istringstream a(plain), b(fixed);
    std::string la, lb;
    while (std::getline(a, la) && std::getline(b, lb)) {
      INFO("with randomisation:    " << la << "\nwithout randomisation: " << lb);
      CHECK(la == lb);
      if (la != lb) break;
    }
    CHECK(plain.size() == fixed.size());
  }
  std::istringstream lines(plain);
  int ok = 0, refused = 0;
  for (std::string l; std::getline(lines, l);) {
    INFO(l);
    if (l.find("\"ok\": true") != std::string::npos) {
      ++ok;
      CHECK(l.find("\"confirmed\": [") != std::string::npos);  // each answer confirmed (or said why not)
      continue;
    }
    ++refused;
    // a refusal is an answer; these are not
    CHECK(l.find("is not confirmed by a simulation") == std::string::npos);
    CHECK(l.find("do not hold at the solution") == std::string::npos);
    CHECK(l.find("internal error") == std::string::npos);
  }
  CHECK(ok + refused == n);
  // most variants stay solvable: a perturbation is a new problem of the same kind, not a broken one
  CHECK(ok >= n * 3 / 4);
  WARN(ok << " of " << n << " variants solved and confirmed; " << refused << " refused");
}
