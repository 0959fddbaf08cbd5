// The evaluator: a shared constant system, this evaluator's parameter values and its workspace.
#include <stdexcept>
#include <string>

#include "hbtrack/hbm/harmonic_balance.hpp"

namespace hbtrack {

HarmonicBalance::HarmonicBalance(StructuralModel model, ElementList elements, ParameterSet parameters, HarmonicBalanceOptions options)
    : HarmonicBalance(std::make_shared<const HarmonicBalanceSystem>(std::move(model), std::move(elements), std::move(parameters),
                                                                    std::move(options))) {}

HarmonicBalance::HarmonicBalance(std::shared_ptr<const HarmonicBalanceSystem> system)
    : system_(std::move(system)), parameters_(system_->parameters()), workspace_(*system_) {}

void HarmonicBalance::set_parameter(int index, double value) {
  if (index < 0 || index >= parameters_.size()) throw std::out_of_range("parameter index " + std::to_string(index) + " out of range");
  parameters_.value(index) = value;
}

HarmonicBalance HarmonicBalance::with_parameter(int index, double value) const {
  HarmonicBalance changed(*this);
  changed.set_parameter(index, value);
  return changed;
}

}  // namespace hbtrack
