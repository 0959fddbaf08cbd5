#pragma once
// The tables of a branch in omega, as frc, isolas and switch write them: branch (outputs per
// point), states (every dof's harmonics), stability (the Floquet exponents, when computed),
// element_forces (on request), the raw unknowns for a sink that keeps them, and at the end the
// special points' states.
#include <memory>
#include <vector>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/runs/result_sink.hpp"

namespace hbtrack::runs {

class BranchTables {
 public:
  // `rows_kept`: the points of a stopped run this one resumes (0 for a new run).
  BranchTables(const CaseDefinition& c, HarmonicBalance& hbm, ResultSink& sink, bool element_forces, bool resumed = false,
               int rows_kept = 0);
  void append(const BranchPoint& p, const RecordedPoint& rec);
  // special_states (and special_unknowns), in summary order: `track` starts from a limit point's.
  void append_special_points(const std::vector<SpecialPoint>& points);
  int points() const { return point_; }

 private:
  HarmonicBalance& hbm_;
  ResultSink& sink_;
  std::unique_ptr<TableSink> branch_, states_, unknowns_, stability_, forces_;
  int point_;
};

}  // namespace hbtrack::runs
