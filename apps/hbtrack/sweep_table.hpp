#pragma once
// The sweep's folders and its merged table: DIR/tasks/NNNN/ per task (the frc result, or with
// --track nfrc/ and track_lpK/ inside), and DIR/sweep.csv with one row per task, read back from
// the task folders so that a rerun that skipped finished tasks writes the same table.
#include <optional>
#include <string>
#include <vector>

#include "sweep_definition.hpp"

namespace hbtrack::cli {

// DIR/tasks/0007 (four digits, more when the sweep has more tasks).
std::string task_folder(const std::string& dir, size_t index, size_t count);

// A result folder whose summary.json says the run ended by itself: a rerun keeps it. Runs
// killed ("running") or stopped by a signal or a time limit are not finished.
bool finished_result(const std::string& folder);

// How a task that left no finished result is shown: it failed (ran in this invocation), or it
// has not run yet (the sweep was stopped before).
enum class Unfinished { kPending, kError };

// Writes DIR/sweep.csv: task, the parameters, status (the NFRC's stop_reason), points, the peak
// of max_NAME over the branch for every output and the omega of the first one's, the number of
// limit points and each one's omega and max of the first output; with tracking, each limit
// point's curve (stop reason, points) and the located extrema of the parameter along them.
void write_sweep_table(const std::string& dir, const SweepGrid& grid, const std::vector<std::string>& outputs,
                       const std::optional<SweepTracking>& tracking, const std::vector<Unfinished>& unfinished);

}  // namespace hbtrack::cli
