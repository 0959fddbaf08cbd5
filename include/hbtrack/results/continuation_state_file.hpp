#pragma once
// The checkpoint of a continuation run (DIR/checkpoint.json): the engine's state between two
// steps and the settings it was computed with, so `--resume DIR` can go on exactly where the run
// stopped. Numbers are stored as JSON's shortest round-trip decimals: reading gives back the
// same doubles, bit for bit.
#include <nlohmann/json.hpp>
#include <string>

#include "hbtrack/analysis/fold_tracking.hpp"
#include "hbtrack/continuation/continuation.hpp"

namespace hbtrack {

// Writes {"format", "settings", "state", "tallies"} to path atomically (temp file + rename).
// `tallies` are the run's own counts over the points the state covers (frc: the stability
// methods), which a resumed run adds its own to.
void write_continuation_state(const std::string& path, const ContinuationState& state, const nlohmann::json& settings,
                              const nlohmann::json& tallies = nlohmann::json::object());

struct SavedContinuation {
  ContinuationState state;
  nlohmann::json settings;
  nlohmann::json tallies;  // an object; empty in checkpoints written before tallies
};
// Throws std::runtime_error "<path>: <what is wrong>" for a missing or malformed file.
SavedContinuation read_continuation_state(const std::string& path);

// The same for a limit-point tracking run (`track`): its leg, borders and finished legs too.
void write_tracking_state(const std::string& path, const FoldTrackingState& state, const nlohmann::json& settings);
struct SavedTracking {
  FoldTrackingState state;
  nlohmann::json settings;
};
SavedTracking read_tracking_state(const std::string& path);

}  // namespace hbtrack
