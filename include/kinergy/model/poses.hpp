/// @file poses.hpp  Poses that cannot be: two bodies in one place at a state.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include <ginac/ginac.h>

namespace kinergy::model {

class Model;

/// The pairs of bodies that overlap where `num` places them (num: an expression of the
/// coordinates and parameters → its number there, NaN where it has none), in words ("rod and
/// disk overlap by 0.05 m"): outlines deeper in each other than a hundredth of the smaller body,
/// where nothing joins the two (a support or connector between them: a rod pinned on a disk, a
/// collar on its rod; an effect between them: a spring, friction of one against the other) and
/// neither has its centre on the other's (disks on one shaft, a ring laid on a turntable: planes
/// one behind the other). Particles and wheels known by a radius of gyration alone have no
/// outline to tell.
std::vector<std::string> overlapping(const Model& m, const std::function<double(const GiNaC::ex&)>& num);

/// The same at state `state` of values `values` (state symbols → numbers, the parameters'
/// included): each coordinate at its value there. None where the state leaves one without a number.
std::vector<std::string> overlapping_at(const Model& m, int state, const GiNaC::exmap& values);

}  // namespace kinergy::model
