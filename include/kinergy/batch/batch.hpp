/// @file batch.hpp  Many scenes in one process: JSON Lines in, JSON Lines out.
///
/// Each input line is one request, a JSON object:
///   {"scene": "derivations/energy/sliding_rod.yaml"}          a scene file (relative to the
///                                                               working directory), or
///   {"yaml": "title: …\nparameters: …"}                        a scene inline;
/// with, optionally,
///   "id": any scalar                echoed back, to match results with requests;
///   "set": {"m": "2 kg", "L": 1.5}  parameter values replaced (as a scene writes them, units too);
///   "produce": ["solve", "verify", "derive", "latex"]   (default ["solve"]);
///   "digits": N                     significant digits of the values (default 15).
/// Each output line is one JSON object for the request on the same line number: "line", "id",
/// "ok", and the solution (as `kinergy solve --json` prints it, with the checks when asked), the
/// derivation's text or LaTeX; or, for a request that fails, "error" with its file, line, column,
/// message and fix. A failing request never stops the batch.
#pragma once
#include <cstddef>
#include <functional>
#include <iosfwd>
#include <string>

namespace kinergy::batch {

/// One request (the text of input line `number`) → its result, one line of JSON without the
/// newline. Never throws for bad input: every failure is a result with "ok": false.
std::string run_line(const std::string& request, std::size_t number);

struct Summary {
  std::size_t requests = 0, ok = 0, failed = 0;
};

/// Every non-blank line of `in` → a line of `out`, in order; `progress` after each.
Summary run(std::istream& in, std::ostream& out, const std::function<void(const Summary&)>& progress = {});

}  // namespace kinergy::batch
