#pragma once
// What a run reports as it goes, and how its caller stops it: the command line's progress line,
// --time-limit and Ctrl-C (apps/hbtrack/cli_monitor.hpp); Python's progress callback and
// KeyboardInterrupt (python/src/python_monitor.hpp). The default watches nothing and never stops.
#include <string>

#include "hbtrack/analysis/nfrc.hpp"  // RecordedPoint
#include "hbtrack/util/stop_reason.hpp"

namespace hbtrack::runs {

// One accepted point of a run.
struct PointProgress {
  int index = 0;                           // from 0, counted over the whole run
  double omega = 0;                        // rad/s
  double value = 0;                        // the run's own variable: omega, the tracked or continued parameter
  int leg = 0;                             // the leg of a tracking curve (1 or 2), 0 for a run without legs
  double fraction = -1;                    // of the run's range covered so far (hbtrack::Coverage), -1 without one
  const RecordedPoint* outputs = nullptr;  // the point's outputs, when the run records them
};

class RunMonitor {
 public:
  virtual ~RunMonitor() = default;
  // After every accepted point: false stops the run there (the engine reports "interrupted").
  virtual bool point(const PointProgress& /*p*/) { return true; }
  // After every integrated period (from 0) of a time integration, with the change of the outputs
  // from the previous one, the time at its end and the part of the period budget used: false
  // stops the integration there ("interrupted").
  virtual bool period(int /*period*/, double /*change*/, double /*time*/, double /*fraction*/) { return true; }
  // The stop reason of a run this monitor may have stopped, as the summary names it:
  // "time_limit", "stopped_by_callback", ... (the engine says "interrupted").
  virtual StopReason stop_reason(StopReason engine_reason) const { return engine_reason; }
};

}  // namespace hbtrack::runs
