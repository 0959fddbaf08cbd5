#include "stop_request.hpp"

namespace hbtrack::cli {

StopRequest::StopRequest(double time_limit_s) : time_limit_s_(time_limit_s) {}

bool StopRequest::requested() {
  if (interrupted()) return true;
  if (time_limit_s_ > 0 && seconds_since(start_) > time_limit_s_) timed_out_ = true;
  return timed_out_;
}

StopReason StopRequest::reason(StopReason engine_reason) const {
  return engine_reason == StopReason::interrupted && timed_out_ && !interrupted() ? StopReason::time_limit : engine_reason;
}

void add_time_limit_option(CLI::App* command, double& seconds) {
  command->add_option("--time-limit", seconds, "stop cleanly after this many seconds of wall-clock time (stop_reason time_limit)")
      ->check(CLI::NonNegativeNumber);
}

}  // namespace hbtrack::cli
