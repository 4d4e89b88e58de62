// The application layer: what every window onto kinergy does with a scene, once.
#include "kinergy/app/app.hpp"

#include <cmath>

#include "kinergy/common/error.hpp"
#include "kinergy/confirm/check.hpp"
#include "kinergy/draw/animation.hpp"

namespace kinergy::app {

const scene::ParameterDef& parameter(const scene::SceneDef& def, const std::string& name, const std::string& verb) {
  std::string names;
  for (auto& p : def.parameters) {
    if (p.name == name) return p;
    names += (names.empty() ? "" : ", ") + p.name;
  }
  throw InputError("the scene has no parameter '" + name + "'", verb + " one of its parameters: " + names);
}

void set_parameter(scene::SceneDef& def, const std::string& name, const std::string& text) {
  const scene::ParameterDef& p = parameter(def, name);
  def.parameters[static_cast<std::size_t>(&p - def.parameters.data())].value.s = text;
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
