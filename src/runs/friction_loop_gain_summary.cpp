#include "hbtrack/runs/friction_loop_gain_summary.hpp"

#include <cstdio>

namespace hbtrack::runs {

using nlohmann::json;

namespace {

// "n4" of "n4_r" and "n4_t"; "" when the names share no node prefix.
std::string shared_node(const std::string& a, const std::string& b) {
  const size_t i = a.rfind('_'), j = b.rfind('_');
  if (i == std::string::npos || i == 0 || i != j || a.compare(0, i, b, 0, j) != 0) return "";
  return a.substr(0, i);
}

json or_null(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

}  // namespace

std::vector<FrictionLoopGain> case_friction_loop_gains(const CaseDefinition& c, double omega_a, double omega_b) {
  return friction_loop_gains(c.model, c.elements, c.parameters.values(), omega_a, omega_b);
}

json friction_loop_gain_json(const std::vector<FrictionLoopGain>& gains) {
  json out = json::array();
  for (const FrictionLoopGain& g : gains) {
    const bool computed = g.note.empty();
    json e = {{"element", g.element},
              {"type", g.type},
              {"normal_dof", g.normal_dof},
              {"tangential_dof", g.tangential_dof},
              {"sense", g.sense},
              {"sense_from", g.sense_from_law ? "law" : "worse"},
              {"mu", g.mu},
              {"contact_stiffness", g.stiffness > 0 ? json(g.stiffness) : json(nullptr)},
              {"flexibility_nn", computed ? json(g.flexibility_nn) : json(nullptr)},
              {"flexibility_nt", computed ? json(g.flexibility_nt) : json(nullptr)},
              {"ratio", computed ? json(g.ratio) : json(nullptr)},
              {"gain", or_null(g.gain)},
              {"self_energising", g.self_energising},
              {"critical_stiffness", or_null(g.critical_stiffness)}};
    if (const std::string node = shared_node(g.normal_dof, g.tangential_dof); !node.empty()) e["node"] = node;
    if (!computed) e["note"] = g.note;
    out.push_back(std::move(e));
  }
  return out;
}

std::vector<std::string> friction_loop_gain_warnings(const std::vector<FrictionLoopGain>& gains) {
  std::vector<std::string> warnings;
  for (const FrictionLoopGain& g : gains) {
    if (!g.self_energising) continue;
    char line[512];
    const std::string at = "elements[" + std::to_string(g.element) + "] (" + g.type + " " + g.normal_dof + ", " + g.tangential_dof + ")";
    if (g.gain)
      std::snprintf(line, sizeof line,
                    "%s: friction loop gain k G_nn (ratio - 1) = %.3g > 1 (ratio mu G_nt / G_nn = %.3g, k = %.3g): friction pushes "
                    "the node into the contact more than the contact pushes it out, so the rigid limit is ill-posed there "
                    "(Painleve-type) and the contact stiffness sets the result",
                    at.c_str(), *g.gain, g.ratio, g.stiffness);
    else
      std::snprintf(line, sizeof line,
                    "%s: friction ratio mu G_nt / G_nn = %.3g > 1 on a rigid contact: friction pushes the node into the contact "
                    "more than the contact pushes it out: an ill-posed (Painleve-type) contact, whose solutions may not exist or be unique",
                    at.c_str(), g.ratio);
    warnings.emplace_back(line);
  }
  return warnings;
}

}  // namespace hbtrack::runs
