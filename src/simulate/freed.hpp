/// @file freed.hpp  (private) A scene whose surfaces that only push can let their bodies go: the
/// model the simulator integrates when it follows a body off a floor, a wall or a dome.
#pragma once
#include <string>
#include <vector>

#include <ginac/ginac.h>

#include "kinergy/model/model.hpp"
#include "kinergy/simulate/equations.hpp"

namespace kinergy::simulate {

/// The scene's model with one more coordinate for each surface that only pushes (a one-sided
/// track) whose body can be freed: its gap s, the body carried off the surface by s n̂ (n̂ the way
/// the surface pushes, at the place the coordinates keep the point), so that s = 0 is the scene's
/// own motion and s > 0 the body apart from the surface. The scene's coordinates keep their
/// places, first; the gaps follow, named `<track>_gap`.
struct Freed {
  model::Model m;
  /// A surface whose body may leave it: the track (by effect index), its gap coordinate, and
  /// whether it is the only such surface of its body (its gap is then that coordinate exactly).
  struct Surface {
    int effect = -1;
    GiNaC::realsymbol s;
    bool alone = true;
    int rolling = -1;  ///< the relation with mu_s that rolls the body on it (a constraint effect), or −1
  };
  std::vector<Surface> surfaces;  ///< in the order of the effects
  /// Surfaces whose bodies cannot be freed, each with why ("'wheel' rolls: its coordinates tie its
  /// turning to its place"): a run stops where one of those bodies leaves.
  std::vector<std::pair<int, std::string>> kept;
};

/// Free what can be freed among the one-sided tracks that act (`on`, by effect; empty: all). A
/// body is freed when nothing else holds it that the shift would break — no other body moves with
/// its coordinates, no pin, relation or guide holds it — and, shifted, its coordinates move it
/// every way a free body moves (x, y and its angle; a particle x and y): then its flight is the
/// scene's physics with nothing added. A relation with mu_s whose `normal` is one of the body's
/// surfaces, between the body and a fixed party (rolling on it), goes with that surface: held
/// while the body is on it and sticks, dropped (the body slides, or flies) otherwise. `values`: the parameters (for that test, at sample
/// coordinates).
Freed free_surfaces(const model::Model& m, const std::vector<bool>& on, const GiNaC::exmap& values);

/// The contact of freed surface `effect` in the freed model: its gap, the gap's rate (and the
/// slip's, across n̂), its restitution (−1: not said).
ContactTerm surface_contact(const Freed& f, const Freed::Surface& s);

}  // namespace kinergy::simulate
