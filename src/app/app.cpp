// The application layer: what every window onto kinergy does with a scene, once.
#include "kinergy/app/app.hpp"

#include <cmath>

#include "kinergy/common/error.hpp"
#include "kinergy/confirm/check.hpp"
#include "kinergy/draw/animation.hpp"
#include "kinergy/units/units.hpp"

namespace kinergy::app {

const scene::ParameterDef& parameter(const scene::SceneDef& def, const std::string& name, const std::string& verb) {
  std::string names;
  for (auto& p : def.parameters) {
    if (p.name == name) return p;
    names += (names.empty() ? "" : ", ") + p.name;
  }
  throw InputError("the scene has no parameter '" + name + "'", verb + " one of its parameters: " + names);
}

namespace {

/// "a length", "a mass", "a pure number (or an angle)", "a quantity in N": for messages.
std::string kind_of(const units::Dimension& d) {
  using units::Dimension;
  if (d.dimensionless()) return "a pure number (or an angle)";
  if (d == Dimension::length()) return "a length";
  if (d == Dimension::mass()) return "a mass";
  if (d == Dimension::time()) return "a time";
  return "a quantity in " + units::si_name(d);
}

}  // namespace

void set_parameter(scene::SceneDef& def, const std::string& name, const std::string& text) {
  const scene::ParameterDef& p = parameter(def, name);
  // checked here, where it is given, not at the scene's line when the scene is solved
  units::Quantity now, was;
  try {
    now = units::parse_quantity(text);
  } catch (const InputError& e) {
    throw InputError("the value '" + text + "' for '" + name + "' is no quantity: " + e.what(), e.fix());
  }
  try {
    was = units::parse_quantity(p.value.s);
  } catch (const InputError&) {
    was = now;  // (the scene's own text is checked where it is read)
  }
  if (now.unit.dim != was.unit.dim)
    throw InputError("the value '" + text + "' for '" + name + "' is " + kind_of(now.unit.dim) + ", but the scene writes '" + name + ": " +
                         p.value.s + "', " + kind_of(was.unit.dim),
                     "give '" + name + "' in a unit of the same kind" + (was.unit.text.empty() ? std::string(" (a pure number)") : " (e.g. " + was.unit.text + ")"));
  def.parameters[static_cast<std::size_t>(&p - def.parameters.data())].value.s = text;
}

std::string written_unit(const scene::SceneDef& def, const std::string& name) {
  try {
    return units::parse_quantity(parameter(def, name).value.s).unit.text;
  } catch (const InputError&) {
    return "";
  }
}

int state_index(const model::Model& m, const std::string& name) {
  if (name.empty()) return 0;
  const int s = m.state_index(name);
  if (s < 0) throw InputError("there is no state '" + name + "'", "name a state of the scene's 'states'");
  return s;
}

simulate::State start_values(const model::Model& m, const Solution* sol, int start) {
  if (m.states.empty())
    throw SceneError({m.file, 1, 1}, "the scene has no states to start from", "add a state with every coordinate and rate");
  simulate::State s0 = sol ? simulate::state_values(*sol, start) : simulate::state_values(m, {}, m.parameter_values(), start);
  const auto& st = m.states[static_cast<std::size_t>(start)];
  for (std::size_t i = 0; i < m.coords.size(); ++i) {
    if (!std::isnan(s0.q[i]) && !std::isnan(s0.qd[i])) continue;
    const std::string what = std::isnan(s0.q[i]) ? m.coords[i].name : m.coords[i].name + "_dot";
    if (!sol)
      throw SceneError(st.pos, "state '" + st.name + "' does not give " + what + " as a number", "give every coordinate and rate at the start state");
    throw SceneError(st.pos, "state '" + st.name + "' does not fix " + what + ", and no analysis finds it",
                     "give it at that state, or start from another");
  }
  return s0;
}

std::string derivation_page(const Solution& s, const emit::Derivation& d, int samples) {
  // a player for the motion of each analysis that can be simulated
  std::vector<std::string> players;
  const auto values = simulate::simulation_values(s);
  const auto motions = simulate::motions(s, samples);
  for (std::size_t i = 0; i < motions.size(); ++i)
    players.push_back("<h3>" + motions[i].title + "</h3>\n" +
                      draw::animation_fragment(s.model, values, motions[i], "motion-" + std::to_string(i + 1)));
  return emit::html(d, players);
}

}  // namespace kinergy::app
