// The one table of effect kinds: a kind's name and the function that reads it.
// Adding a kind: its file in src/effects/ (defining read_NAME) and one line in the list below.
#include "common.hpp"

// X(name): the kinds, in the order messages list them
#define KINERGY_EFFECT_KINDS(X) \
  X(gravity)                    \
  X(spring)                     \
  X(torsion_spring)             \
  X(damper)                     \
  X(torsion_damper)             \
  X(couple)                     \
  X(force)                      \
  X(friction)                   \
  X(friction_couple)            \
  X(power)                      \
  X(pin)                        \
  X(constraint)                 \
  X(track)                      \
  X(cord)                       \
  X(contact)                    \
  X(impulse)                    \
  X(cord_pull)

namespace kinergy::effects {
#define KINERGY_DECLARE(k) std::shared_ptr<Effect> read_##k(EffectReader&, const EffectDef&);
KINERGY_EFFECT_KINDS(KINERGY_DECLARE)
#undef KINERGY_DECLARE
}  // namespace kinergy::effects

namespace kinergy::model {

const std::vector<EffectKind>& effect_kinds() {
#define KINERGY_ENTRY(k) EffectKind{#k, effects::read_##k},
  static const std::vector<EffectKind> table = {KINERGY_EFFECT_KINDS(KINERGY_ENTRY)};
#undef KINERGY_ENTRY
  return table;
}

}  // namespace kinergy::model

namespace kinergy::scene {

const std::vector<std::string>& effect_kinds() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (auto& k : model::effect_kinds()) n.push_back(k.name);
    return n;
  }();
  return names;
}

}  // namespace kinergy::scene
