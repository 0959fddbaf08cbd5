#include "hbtrack/runs/branch_tables.hpp"

#include "hbtrack/results/element_force_table.hpp"
#include "hbtrack/results/result_tables.hpp"
#include "hbtrack/results/state_columns.hpp"

namespace hbtrack::runs {

BranchTables::BranchTables(const CaseDefinition& c, HarmonicBalance& hbm, ResultSink& sink, bool element_forces, bool resumed,
                           int rows_kept)
    : hbm_(hbm), sink_(sink), point_(rows_kept) {
  const TableStart start{resumed, rows_kept};
  branch_ = sink.table("branch", branch_header(c), start);
  states_ = sink.table("states", dof_state_header(hbm), start);
  if (sink.keeps_unknowns()) unknowns_ = sink.table("unknowns", state_header(hbm.unknowns()), start);
  // Several rows per point (its Floquet exponents), so resumed by point index.
  if (c.nfrc.stability.enabled()) stability_ = sink.table("stability", stability_header(), {resumed, rows_kept, true});
  if (element_forces) forces_ = sink.table("element_forces", element_force_header(hbm), start);
}

void BranchTables::append(const BranchPoint& p, const RecordedPoint& rec) {
  branch_->append(branch_row(rec));
  states_->append(dof_state_row(hbm_, p.lambda, p.u));
  if (unknowns_) unknowns_->append(state_row(p.lambda, p.u));
  if (forces_) forces_->append(element_force_row(hbm_, p.lambda, p.u));
  if (stability_)
    for (const auto& row : stability_rows(point_, rec)) stability_->append(row);
  ++point_;
}

void BranchTables::append_special_points(const std::vector<SpecialPoint>& points) {
  const auto states = sink_.table("special_states", dof_state_header(hbm_));
  std::unique_ptr<TableSink> unknowns;
  if (sink_.keeps_unknowns()) unknowns = sink_.table("special_unknowns", state_header(hbm_.unknowns()));
  for (const auto& sp : points) {
    states->append(dof_state_row(hbm_, sp.lambda, sp.u));
    if (unknowns) unknowns->append(state_row(sp.lambda, sp.u));
  }
}

}  // namespace hbtrack::runs
