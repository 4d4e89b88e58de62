// The figures of a worked solution: the scene at its states, and the impulse–momentum diagram of
// each momentum analysis and each impact (momenta before + impulses = momenta after).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "kinergy/draw/figure.hpp"
#include "kinergy/emit/latex.hpp"
#include "kinergy/principles/kinetics.hpp"
#include "kinergy/principles/momentum.hpp"
#include "kinergy/problem.hpp"

namespace kinergy::emit {

/// The values a worked solution's figures are drawn with: the parameters' and the solved
/// unknowns', and a sample value for each parameter without one (draw::with_samples), said in
/// `samples`.
GiNaC::exmap figure_values(const Solution& s, std::string* samples = nullptr);

/// The scene at each of its states, at most three to a sheet; `left_out` gets the states that do
/// not fix every coordinate.
std::vector<draw::Sheet> state_sheets(const Solution& s, std::vector<std::string>& left_out);

/// The chapter's three panels for analysis `a` over the bodies `bodies`: the momenta at its first
/// state (m v̄ at each mass centre, Ī ω round it), the impulses `shown` that act on them (each
/// effect's at its point, named; an unknown reaction by its unknowns), the momenta at its second
/// state. `names`: TeX names of symbols that need them. None when a state cannot be drawn.
std::optional<draw::Sheet> momentum_diagram(const Solution& s, const model::Analysis& a, const std::vector<int>& bodies,
                                          const std::vector<principles::Shown>& shown, const std::vector<std::string>& held,
                                          const TexSymbols* names);

/// What a panel draws, to tell two alike: its marks where they are (to the micrometre), the owner,
/// kind and ink of every other stroke, and its labels' words — not the glyph size, which differs
/// between sheets of the same drawing.
std::string panel_print(const draw::Figure& f);

/// The supports that act on the set `bodies` from outside it: a pin, a track or a relation with a
/// party in the set and the other not (the ground, a fixed point, a body left out).
std::vector<std::string> outside_supports(const model::Model& m, const std::vector<int>& bodies);

/// A diagram and its equations cannot disagree: panel `panel` of `sheet` draws each effect of
/// `held` (the effects whose terms its equations hold, and the supports that act on its bodies
/// from outside their set, which an equation may drop). @throws std::logic_error naming those it
/// does not draw (a fault of kinergy's, not of the scene).
void check_diagram(const draw::Sheet& sheet, std::size_t panel, const std::vector<std::string>& held, const std::string& what);

/// Kinetics at a state, for the body of `acc`: its free-body diagram (each force of `loads` on it at its
/// point, named — a support's reaction by its unknowns — and each couple round its mass centre)
/// equal to its kinetic diagram (m ā at the mass centre along the acceleration solved, Ī α round
/// it). None when the state cannot be drawn.
std::optional<draw::Sheet> kinetic_diagram(const Solution& s, const model::Analysis& a, const principles::BodyAcceleration& acc,
                                           const std::vector<principles::BodyLoad>& loads, const TexSymbols* names);

}  // namespace kinergy::emit
