#pragma once
// Why a long run stops before its end: SIGINT/SIGTERM (stop_reason "interrupted") or the
// --time-limit wall clock ("time_limit"). Checked at every accepted point.
#include <string>

#include "cli_common.hpp"
#include "hbtrack/util/stop_reason.hpp"

namespace hbtrack::cli {

class StopRequest {
 public:
  explicit StopRequest(double time_limit_s);  // 0: no limit
  // True once a signal arrived or the time is up: the observer returns !requested().
  bool requested();
  // The engine reports a stop asked by its observer as "interrupted"; this names which one.
  StopReason reason(StopReason engine_reason) const;

 private:
  Clock::time_point start_ = Clock::now();
  double time_limit_s_;
  bool timed_out_ = false;
};

// Adds --time-limit SECONDS to a verb.
void add_time_limit_option(CLI::App* command, double& seconds);

}  // namespace hbtrack::cli
