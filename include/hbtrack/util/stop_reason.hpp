#pragma once
// Why a run or an analysis stopped: the `stop_reason` of the result structs, of summary.json and
// of the tracking checkpoint, named once in a ChoiceTable (util/choices.hpp gives to_string and
// parse_choice). The names are a file format: add, never rename (tests/test_choices.cpp lists
// them; docs/outputs.md says what each means).
//
// One enum, not one per domain: summary.json has a single `stop_reason` field whatever verb
// wrote it, and what reads result folders back (sweep, study, --resume) compares its values
// across verbs; `interrupted` and `converged` belong to several producers, and an analysis
// passes the engine's reason on as its own. A field of a result struct may therefore hold a
// name its producer never gives; the comments below say who gives which.
#include <iosfwd>
#include <string>
#include <string_view>

#include "hbtrack/util/choices.hpp"

namespace hbtrack {

enum class StopReason {
  running,  // not stopped yet: a struct's default, and summary.json while a verb runs
  // The continuation engine (continue_within): the bound it headed for, the other bound, back on
  // its first point, the point budget, the corrector failing down to step_min (or the branch
  // turning too sharply within it), the observer asking to stop, the wall-time limit, no first point.
  reached_end,
  left_range,
  closed,
  max_points,
  step_size_underflow,
  step_size_underflow_on_curvature,
  interrupted,  // also a steady-state integration, a sweep, a study (SIGINT/SIGTERM)
  time_limit,
  no_convergence_at_start,
  rejoined,  // period doubling: a leg back on the period-T branch
  // NS tracking: a leg ended where the NS frequency reached 0 or w/2 (a 1:1 or 1:2 resonance:
  // the curve meets a fold or a period-doubling curve and ends there).
  strong_resonance,
  not_started,  // limit-point tracking with no leg computed
  completed,    // a run of several parts (track, switch, isolas, sweep, study) that all ended as asked
  // Time integration to a steady state (integrate_to_steady_state and the integrators' failures).
  converged,  // also `solve`: Newton converged at the fixed frequency
  max_periods,
  diverged,
  newton_failure,
  integration_failure,
  // The verbs and Python.
  no_convergence,       // the single solve or the start of a branch (backbone, continue, switch) failed
  tasks_failed,         // sweep: a task left no finished result
  checks_failed,        // study: every step ran, a check failed
  stopped_by_callback,  // Python: the progress callback returned False
  // The torus branch (torus_branch.hpp): its size in theta2 reached zero, back on the periodic
  // branch at a Neimark-Sacker point.
  reached_ns_point,
};

template <>
struct ChoiceTable<StopReason> {
  static constexpr std::string_view field = "stop_reason";
  static constexpr ChoiceName<StopReason> names[] = {
      {StopReason::running, "running"},
      {StopReason::reached_end, "reached_end"},
      {StopReason::left_range, "left_range"},
      {StopReason::closed, "closed"},
      {StopReason::max_points, "max_points"},
      {StopReason::step_size_underflow, "step_size_underflow"},
      {StopReason::step_size_underflow_on_curvature, "step_size_underflow_on_curvature"},
      {StopReason::interrupted, "interrupted"},
      {StopReason::time_limit, "time_limit"},
      {StopReason::no_convergence_at_start, "no_convergence_at_start"},
      {StopReason::rejoined, "rejoined"},
      {StopReason::strong_resonance, "strong_resonance"},
      {StopReason::not_started, "not_started"},
      {StopReason::completed, "completed"},
      {StopReason::converged, "converged"},
      {StopReason::max_periods, "max_periods"},
      {StopReason::diverged, "diverged"},
      {StopReason::newton_failure, "newton_failure"},
      {StopReason::integration_failure, "integration_failure"},
      {StopReason::no_convergence, "no_convergence"},
      {StopReason::tasks_failed, "tasks_failed"},
      {StopReason::checks_failed, "checks_failed"},
      {StopReason::stopped_by_callback, "stopped_by_callback"},
      {StopReason::reached_ns_point, "reached_ns_point"},
  };
};

// A name read back from a file; throws std::invalid_argument "<field>: must be running, ...,
// got 'x'" for any other.
inline StopReason parse_stop_reason(const std::string& name, std::string_view field = ChoiceTable<StopReason>::field) {
  return parse_choice<StopReason>(name, field);
}

// The name, for test failure messages and logs.
std::ostream& operator<<(std::ostream& out, StopReason reason);

}  // namespace hbtrack
