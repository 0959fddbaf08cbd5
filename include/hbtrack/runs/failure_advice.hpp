#pragma once
// What a continuation that stopped early tried, and what to change: one sentence per stop
// reason, for the message of `frc` (and the summary's "advice").
#include <string>

#include "hbtrack/continuation/continuation.hpp"

namespace hbtrack::runs {

// last_lambda: the parameter of the last accepted point (the start when there is none).
std::string continuation_failure_advice(const ContinuationSummary& s, const ContinuationOptions& o, double last_lambda);

}  // namespace hbtrack::runs
