#include "hbtrack/results/torus_tables.hpp"

#include "hbtrack/results/result_tables.hpp"

namespace hbtrack {

using nlohmann::json;

std::vector<std::string> torus_branch_header(const CaseDefinition& c) {
  std::vector<std::string> h{"omega", "omega2", "size"};
  for (const OutputDof& o : c.outputs) h.insert(h.end(), {"max_" + o.name, "min_" + o.name});
  return h;
}

std::vector<double> torus_branch_row(const TorusPoint& p) {
  std::vector<double> row{p.omega, p.omega2, p.size};
  for (const TorusEnvelope& e : p.envelope) row.insert(row.end(), {e.max, e.min});
  return row;
}

std::vector<std::string> torus_state_header(const TorusBasis& basis, const std::vector<std::string>& dof_names) {
  std::vector<std::string> h{"omega", "omega2"};
  for (int c = 0; c < basis.coefficients(); ++c) {
    const auto [k1, k2] = basis.pair(basis.pair_of(c));
    std::string label = "h0";
    if (c > 0) {
      label = c % 2 ? "c" : "s";  // 2p - 1 the cosine, 2p the sine
      label.append(std::to_string(k1)).append("_").append(std::to_string(k2));
    }
    for (const std::string& dof : dof_names) h.push_back(dof + "_" + label);
  }
  return h;
}

std::vector<double> torus_state_row(const TorusPoint& p) {
  std::vector<double> row{p.omega, p.omega2};
  row.insert(row.end(), p.u.data(), p.u.data() + p.u.size() - 1);
  return row;
}

void add_torus_summary(json& summary, const CaseDefinition& c, const TorusBranchResult& r, const TorusOptions& o) {
  add_continuation_counts(summary, r.summary);
  summary["stop_reason"] = to_string(r.stop_reason);
  summary["points"] = r.points.size();
  json& t = summary["options"]["torus"];
  t["harmonics"] = {o.h1, o.h2};
  t["samples"] = {o.n1, o.n2};
  t["range"] = {o.omega_min, o.omega_max};
  t["start_fraction"] = o.start_fraction;
  t["phase_condition"] = {{"pair", {r.k1, r.k2}}, {"dof", c.model.dof_names[static_cast<size_t>(r.phase_dof)]}};
  summary["ns_point"] = {{"omega", r.omega_ns}, {"ns_frequency", r.nu}};
  if (!r.points.empty())
    summary["end"] = {{"omega", r.points.back().omega}, {"omega2", r.points.back().omega2}, {"size", r.points.back().size}};
  summary["stability"] = "not decided (the torus' Lyapunov exponents are not computed)";
  json special = json::array();
  for (const SpecialPoint& sp : r.special_points) {
    if (sp.type != SpecialPointType::limit_point) continue;  // a fold in omega; the engine's other tests mean nothing here
    special.push_back({{"type", to_string(sp.type)},
                       {"index", sp.index + 1},
                       {"omega", sp.lambda},
                       {"located", sp.located},
                       {"omega2", sp.u(sp.u.size() - 1)}});
  }
  summary["special_points"] = special;
}

}  // namespace hbtrack
