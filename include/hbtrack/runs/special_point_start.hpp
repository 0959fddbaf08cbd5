#pragma once
// Which special point of an earlier frc result a run starts from: track --lp/--ns/--pd and
// torus --ns (the K-th of a type), switch --point (the K-th of the list, a BP or a PD). The CLI
// reads the result from its folder, Python from a result dict; both choose the point here, from
// summary.json's special_points, so the two agree on the numbering and on the errors.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hbtrack/util/special_point_type.hpp"

namespace hbtrack::runs {

// Whether one of summary.json's special_points is of `type` (false for a type it does not name).
bool special_point_is(const nlohmann::json& special_point, SpecialPointType type);

// The indices into special_points of those of `type`, in increasing omega (ties in list order):
// the numbering of the figures, the paper and `track --lp K`, whatever order the continuation
// met them in (a downward sweep meets them from the highest omega).
std::vector<size_t> special_point_rows(const nlohmann::json& special_points, SpecialPointType type);

// Where an error says the point was asked and looked for: `keyword` the option ("--lp" or
// "lp"), `source` the result ("DIR/summary.json" or "the frc result").
struct SpecialPointRequest {
  std::string keyword;
  std::string source;
};

// The index into special_points (and so the row of special_states) of the k-th special point of
// `type` (from 1, in special_point_rows' order). CaseError when there is none.
size_t special_point_index(const nlohmann::json& special_points, SpecialPointType type, long k, const SpecialPointRequest& request);

// switch's point: special point `point` (from 1, in list order), a BP or a PD; its row of
// special_states and its neighbours' rows of states (the direction the NFRC goes through it).
// `state_rows`: the rows of the result's states. CaseError otherwise.
struct SwitchPoint {
  SpecialPointType type = SpecialPointType::branch_point;
  size_t special_row = 0;
  size_t before_row = 0, after_row = 0;
};
SwitchPoint switch_point(const nlohmann::json& special_points, long point, size_t state_rows, const SpecialPointRequest& request);

}  // namespace hbtrack::runs
