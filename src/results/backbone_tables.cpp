#include "hbtrack/results/backbone_tables.hpp"

#include <nlohmann/json.hpp>

#include "hbtrack/results/result_tables.hpp"

namespace hbtrack {

using nlohmann::json;

std::vector<std::string> backbone_header(const CaseDefinition& c, const std::vector<int>& harmonics) {
  std::vector<std::string> h{"amplitude", "omega", "damping_ratio", "xi"};
  for (const auto& o : c.outputs) {
    for (const char* kind : {"max_", "min_"}) {
      std::string column = kind;  // appended, not operator+ or reassigned: GCC 12's false -Wrestrict at -O3
      column += o.name;
      h.push_back(column);
    }
    for (int j : harmonics) {
      std::string column = "h";
      column += harmonic_label(j, c.harmonic_balance.subharmonic);
      column += '_';
      column += o.name;
      h.push_back(column);
    }
  }
  return h;
}

std::vector<double> backbone_row(const BackbonePoint& p) {
  std::vector<double> row{p.amplitude, p.omega, p.damping_ratio, p.xi};
  for (size_t i = 0; i < p.recorded.outputs.size(); ++i) {
    row.push_back(p.recorded.outputs[i].max);
    row.push_back(p.recorded.outputs[i].min);
    row.insert(row.end(), p.harmonics[i].data(), p.harmonics[i].data() + p.harmonics[i].size());
  }
  return row;
}

std::vector<std::string> backbone_state_header(int unknowns) { return state_header(unknowns); }

std::vector<double> backbone_state_row(const BackbonePoint& p, const Eigen::VectorXd& u, int unknowns) {
  return state_row(p.omega, p.amplitude * u.head(unknowns));
}

json backbone_options_json(const BackboneOptions& o) { return {{"mode", o.mode}, {"range", {o.amplitude_start, o.amplitude_end}}}; }

void add_backbone_summary(json& summary, const CaseDefinition& c, HarmonicBalance& hbm, const BackboneResult& r) {
  const auto& s = r.continuation.summary;
  add_continuation_counts(summary, s);
  summary["linear_mode"] = {{"omega", r.linear_omega}, {"xi", r.linear_xi}, {"damping_ratio", r.linear_xi / (2 * r.linear_omega)}};
  summary["outputs"] = outputs_json(c);
  json special = json::array();
  for (const auto& sp : r.continuation.special_points) {
    const BackbonePoint p = backbone_point(hbm, sp.u, sp.lambda, c.outputs);
    json j = {{"type", to_string(sp.type)}, {"index", sp.index}, {"located", sp.located},
              {"amplitude", p.amplitude},   {"omega", p.omega},  {"damping_ratio", p.damping_ratio}};
    add_outputs(j, c, p.recorded);
    special.push_back(j);
  }
  summary["special_points"] = special;
}

}  // namespace hbtrack
