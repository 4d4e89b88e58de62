// The one table of analysis kinds. Adding a kind: its file in src/analyses/ (defining NAME()) and
// one line in the list below.
#include "kinergy/model/analysis.hpp"

// X(name): the kinds, in the order messages list them
#define KINERGY_ANALYSIS_KINDS(X) \
  X(energy)                       \
  X(momentum)                     \
  X(angular_momentum)             \
  X(impact)                       \
  X(kinetics)

namespace kinergy::analyses {
#define KINERGY_DECLARE(k) const model::AnalysisKind& k();
KINERGY_ANALYSIS_KINDS(KINERGY_DECLARE)
#undef KINERGY_DECLARE
}  // namespace kinergy::analyses

namespace kinergy::model {

const std::vector<const AnalysisKind*>& analysis_kinds() {
#define KINERGY_ENTRY(k) &analyses::k(),
  static const std::vector<const AnalysisKind*> table = {KINERGY_ANALYSIS_KINDS(KINERGY_ENTRY)};
#undef KINERGY_ENTRY
  return table;
}

}  // namespace kinergy::model
