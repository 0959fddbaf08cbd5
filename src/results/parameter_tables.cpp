#include "hbtrack/results/parameter_tables.hpp"

#include <nlohmann/json.hpp>

#include "hbtrack/results/result_tables.hpp"

namespace hbtrack {

using nlohmann::json;

std::vector<std::string> parameter_branch_header(const CaseDefinition& c, const std::string& parameter) {
  std::vector<std::string> h = branch_header(c);
  h.insert(h.begin() + 1, parameter);
  return h;
}

std::vector<double> parameter_branch_row(const ParameterBranchPoint& p) {
  std::vector<double> row = branch_row(p.recorded);
  row.insert(row.begin() + 1, p.parameter);
  return row;
}

json parameter_continuation_options(const std::string& parameter, double omega, double start, double end) {
  return {{"parameter", parameter}, {"omega", omega}, {"range", {start, end}}};
}

void add_parameter_branch_summary(json& summary, const CaseDefinition& c, const HarmonicBalance& hbm, const ParameterBranchResult& r,
                                  int parameter) {
  const auto& s = r.continuation.summary;
  const std::string& name = hbm.parameters().names()[static_cast<size_t>(parameter)];
  add_continuation_counts(summary, s);
  summary["options"]["continuation"]["length_scale"] = r.length_scale;
  summary["outputs"] = outputs_json(c);
  const double omega = summary["options"]["continue"]["omega"].get<double>();
  HarmonicBalance at_point(hbm);  // the outputs of each point at its own value
  json special = json::array();
  for (const auto& sp : r.continuation.special_points) {
    json j = {{"type", to_string(sp.type)}, {"index", sp.index}, {"omega", omega}, {name, sp.lambda}, {"located", sp.located}};
    j["parameters"] = summary["options"]["parameters"];
    j["parameters"][name] = sp.lambda;
    at_point.set_parameter(parameter, sp.lambda);
    add_outputs(j, c, record_point(at_point, sp.u, omega, c.outputs));
    special.push_back(j);
  }
  summary["special_points"] = special;
}

}  // namespace hbtrack
