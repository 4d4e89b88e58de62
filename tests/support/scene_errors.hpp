/// @file scene_errors.hpp  Helpers for tests of bad scenes: places in a scene text, one-line
/// error form, solving a text and catching its SceneError.
#pragma once
#include <catch2/catch.hpp>

#include <algorithm>
#include <optional>
#include <regex>
#include <string>

#include "kinergy/common/error.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/scene/scene.hpp"

namespace kt_errors {

using Catch::Matchers::Contains;

struct Pos {
  int line, col;
};

/// Line and column of character `k` of `needle`, the only occurrence in `text`.
inline Pos at(const std::string& text, const std::string& needle, std::size_t k = 0) {
  auto i = text.find(needle);
  INFO("needle: " << needle);
  REQUIRE(i != std::string::npos);
  REQUIRE(text.find(needle, i + 1) == std::string::npos);
  i += k;
  int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(i), '\n'));
  auto nl = text.rfind('\n', i == 0 ? 0 : i - 1);
  int col = static_cast<int>(nl == std::string::npos || i == 0 ? i + 1 : i - nl);
  return {line, col};
}

/// `text` with the first `from` replaced by `to`.
inline std::string edit(std::string text, const std::string& from, const std::string& to) {
  auto i = text.find(from);
  INFO("edit: " << from);
  REQUIRE(i != std::string::npos);
  return text.replace(i, from.size(), to);
}

inline const std::string kDash = " \u2014 ";

/// True when `s` shows a NaN or an internal error, which bad input must never produce.
inline bool looks_broken(const std::string& s) {
  static const std::regex nan("\\bnan\\b", std::regex::icase);
  return std::regex_search(s, nan) || s.find("internal error") != std::string::npos;
}

/// The one-line form of an error: prefix, what is wrong, " — ", a non-empty fix.
inline void check_form(const kinergy::SceneError& e, const std::string& file) {
  std::string w = e.what();
  INFO(w);
  std::string prefix = file + ":" + std::to_string(e.pos().line) + ":" + std::to_string(e.pos().col) + ": ";
  CHECK(w.rfind(prefix, 0) == 0);
  CHECK(e.pos().line >= 1);
  CHECK(e.pos().col >= 1);
  CHECK(w.find('\n') == std::string::npos);
  auto dash = w.find(kDash);
  REQUIRE(dash != std::string::npos);
  CHECK(w.substr(dash + kDash.size()) == e.fix());
  CHECK(!e.fix().empty());
  CHECK(!e.problem().empty());
  CHECK(w == prefix + e.problem() + kDash + e.fix());
  CHECK_FALSE(looks_broken(w));
}

/// Load and solve a scene; the SceneError it ends with, if any. Any other exception fails the test.
inline std::optional<kinergy::SceneError> error_of(const std::string& text) {
  try {
    kinergy::solve_scene(kinergy::scene::load_string(text, "bad.yaml"));
  } catch (const kinergy::SceneError& e) {
    return e;
  }
  return std::nullopt;
}

/// The scene fails at `p` with `phrase` in what is wrong (and `fix_phrase` in the fix).
inline void expect_error(const std::string& text, Pos p, const std::string& phrase, const std::string& fix_phrase = "") {
  INFO("scene:\n" << text);
  auto e = error_of(text);
  REQUIRE(e.has_value());
  INFO("error: " << e->what());
  CHECK(e->pos().file == "bad.yaml");
  CHECK(e->pos().line == p.line);
  CHECK(e->pos().col == p.col);
  CHECK_THAT(e->problem(), Contains(phrase));
  if (!fix_phrase.empty()) CHECK_THAT(e->fix(), Contains(fix_phrase));
  check_form(*e, "bad.yaml");
}

/// The scene solves without error.
inline void expect_ok(const std::string& text) {
  INFO("scene:\n" << text);
  auto e = error_of(text);
  INFO("error: " << (e ? e->what() : ""));
  CHECK_FALSE(e.has_value());
}

}  // namespace kt_errors
