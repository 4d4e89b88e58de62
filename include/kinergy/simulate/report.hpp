/// @file report.hpp  A simulation run as text (the end state, impacts, switches and the energy
/// audit), as CSV (t, q, q̇, T, V, E per sample) and as a plot drawn by gnuplot.
#pragma once
#include <string>

#include "kinergy/model/model.hpp"
#include "kinergy/simulate/simulate.hpp"

namespace kinergy::simulate {

/// The summary a user reads: end state, impacts with their energy loss, what switched, and the
/// energy audit (drift for a conservative scene, the work of each effect otherwise).
std::string text(const model::Model& m, const Run& r);

/// The run for tools, as one JSON object: the end state (each coordinate and rate by name, the
/// gaps of the surfaces its bodies may leave among them), every switch (leaves, strikes, rests,
/// slack, taut, lets go, slips, sticks) and impact at its instant, the log and the energy audit.
/// Numbers with 17 significant digits (null where not finite); nothing that varies from run to run.
std::string json(const model::Model& m, const Run& r);

/// `t,q…,q_dot…,T,V,E` with a header line, one row per sample (17 significant digits).
std::string csv(const model::Model& m, const Run& r);

/// Coordinates and energy against time, drawn by gnuplot into FILE.svg or FILE.png.
/// @throws InputError when gnuplot is missing or fails, or the extension is neither.
void plot(const model::Model& m, const Run& r, const std::string& file);

}  // namespace kinergy::simulate
