/// @file digits.hpp  GiNaC's working precision (the global GiNaC::Digits) for a scope.
#pragma once
#include <ginac/ginac.h>

namespace kinergy::numerics {

/// Sets GiNaC::Digits for a scope and restores it at the scope's end, also when an exception
/// unwinds it (Ctrl-C from Python stops a computation where it is: common/interrupt.hpp), so that
/// what runs next starts from the precision it expects.
class DigitsScope {
public:
  explicit DigitsScope(long digits) : saved_(GiNaC::Digits) { GiNaC::Digits = digits; }
  ~DigitsScope() { GiNaC::Digits = saved_; }
  DigitsScope(const DigitsScope&) = delete;
  DigitsScope& operator=(const DigitsScope&) = delete;
  /// Change the precision within the scope (restored as before at its end).
  void set(long digits) const { GiNaC::Digits = digits; }

private:
  long saved_;
};

}  // namespace kinergy::numerics
