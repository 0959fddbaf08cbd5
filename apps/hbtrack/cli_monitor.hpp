#pragma once
// How the verbs watch a run (runs/run_monitor.hpp): the progress line on a terminal and in a
// --progress-file (progress.hpp), and the stops that Ctrl-C and --time-limit ask for
// (stop_request.hpp), reported as "interrupted" / "time_limit".
#include <vector>

#include "hbtrack/runs/run_monitor.hpp"
#include "progress.hpp"
#include "stop_request.hpp"

namespace hbtrack::cli {

class CliMonitor final : public runs::RunMonitor {
 public:
  // `progress` was made with the run's range (a Progress knows how to show it).
  CliMonitor(Progress& progress, StopRequest& stop, const std::vector<OutputDof>& outputs)
      : progress_(progress), stop_(stop), outputs_(outputs) {}
  bool point(const runs::PointProgress& p) override {
    const RecordedPoint none{};
    const RecordedPoint& rec = p.outputs ? *p.outputs : none;
    if (p.leg > 0)
      progress_.update(p.index, p.omega, p.value, p.leg, rec, outputs_);
    else
      progress_.update(p.index, p.omega, rec, outputs_);
    return !stop_.requested();
  }
  StopReason stop_reason(StopReason reason) const override { return stop_.reason(reason); }

 private:
  Progress& progress_;
  StopRequest& stop_;
  const std::vector<OutputDof>& outputs_;
};

}  // namespace hbtrack::cli
