/// @file app.hpp  The application layer: what the command line, the Python module, batch and
/// sweep all do with a scene, written once — set a parameter, name a state, take a simulation's
/// start from a solved scene, put the worked solution on one page with its motions. The windows
/// onto it (src/cli, python/, src/batch) read their own arguments and print; the rest is here.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "kinergy/emit/derive.hpp"
#include "kinergy/problem.hpp"
#include "kinergy/scene/scene.hpp"
#include "kinergy/simulate/simulate.hpp"

namespace kinergy::app {

/// Parameter `name` of a scene as written. @throws InputError naming the scene's parameters when
/// it has none of that name (`verb`: what the caller does with it, for the fix: "set", "sweep").
const scene::ParameterDef& parameter(const scene::SceneDef& def, const std::string& name, const std::string& verb = "set");

/// Set parameter `name` to `text`, as a scene writes a value ("2 kg", "30 deg", "9.81").
/// @throws InputError when the scene has no such parameter, when the text is no quantity, or when
/// it is of another kind than the scene writes (a mass for a length), naming both.
void set_parameter(scene::SceneDef& def, const std::string& name, const std::string& text);
/// The unit parameter `name` is written in ("m", "deg", "" for a pure number): a bare number
/// given for it is in that unit.
std::string written_unit(const scene::SceneDef& def, const std::string& name);

/// The index of state `name` ("" : the first). @throws InputError when there is none.
int state_index(const model::Model& m, const std::string& name);

/// A simulation's start at state `start`: every coordinate and rate as a number, given there or
/// found by an analysis of the solved scene (`sol`; none: the scene's given values alone).
/// @throws SceneError at the state, naming what it does not fix.
simulate::State start_values(const model::Model& m, const Solution* sol, int start);

/// The worked solution as one self-contained HTML page, with the motion of each analysis that
/// can be simulated animated (`samples` frames each).
std::string derivation_page(const Solution& s, const emit::Derivation& d, int samples = 200);

}  // namespace kinergy::app
