#include "common.hpp"

namespace kinergy::analyses {

std::vector<principles::Equation> equations_of(const principles::EnergyBalance& b) { return {b.equation}; }

std::vector<principles::Equation> equations_of(const principles::MomentumBalance& b) {
  std::vector<principles::Equation> out;
  for (auto& c : b.components) out.push_back(c.equation);
  return out;
}

std::vector<principles::Equation> equations_of(const principles::ImpactBalance& b) {
  std::vector<principles::Equation> out;
  for (auto* group : {&b.positions, &b.momentum, &b.restitution})
    for (auto& e : *group) out.push_back(e);
  return out;
}

}  // namespace kinergy::analyses
