// Every figure of every derivation's worked solution, for the tests that look at all of them.
#pragma once
#include <string>

#include "../support/helpers.hpp"
#include "kinergy/emit/derive.hpp"
#include "kinergy/problem.hpp"

namespace kt {

/// fn(file, k, block) for figure k (from 1, as the LaTeX numbers them) of each derivation.
template <class F>
void each_figure(F fn) {
  for (const auto& file : scene_files("derivations")) {
    const auto d = kinergy::emit::derive(kinergy::solve_file(file));
    int k = 0;
    for (const auto& b : d.blocks)
      if (b.sheet) fn(file, ++k, b);
  }
}

}  // namespace kt
