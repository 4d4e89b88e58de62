/// @file contact.hpp  The contact effect: two parties that may strike along a normal, with
/// restitution e (an impact analysis names its contacts and reads them as this type).
#pragma once
#include "kinergy/model/effect.hpp"

namespace kinergy::effects {

class Contact : public model::Effect {
public:
  model::PointRef a, b;  ///< parties: body points, bodies, fixed points or ground
  GiNaC::ex nx = 0, ny = 0;  ///< unit normal from a into b
  GiNaC::ex e = 0;           ///< coefficient of restitution
  bool stick = false;        ///< rough: no sliding after the impact

  static std::shared_ptr<model::Effect> read(model::EffectReader& r, const scene::EffectDef& ed);
  /// J n̂ + Jt t̂ on b, −that on a, in impacts
  std::optional<model::Reaction> reaction(const model::Model&) const override;
  void draw(const model::Model& m, const draw::At& at, draw::Figure& f) const override;
};

/// Effect `i` of the model, which must be a contact (checked when the model was built).
const Contact& contact(const model::Model& m, int i);
/// The effect as a contact, or nullptr.
const Contact* as_contact(const model::Effect& e);

}  // namespace kinergy::effects
