/// @file sections.hpp  The sections of a derivation an analysis kind writes itself into.
#pragma once
#include "kinergy/model/model.hpp"
#include "kinergy/principles/momentum.hpp"
#include "kinergy/principles/principles.hpp"

namespace kinergy::emit {

class Sections {
public:
  virtual ~Sections() = default;
  virtual void section(int k, const model::Analysis& a, const principles::EnergyBalance& b) = 0;
  virtual void section(int k, const model::Analysis& a, const principles::MomentumBalance& mb) = 0;
  virtual void section(int k, const model::Analysis& a, const principles::ImpactBalance& ib) = 0;
};

}  // namespace kinergy::emit
