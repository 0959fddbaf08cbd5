#include "hbtrack/io/continuation_state_file.hpp"

#include <fstream>
#include <stdexcept>

#include "hbtrack/io/results_writer.hpp"

namespace hbtrack {

namespace {

using nlohmann::json;

constexpr int kFormat = 1;

json vector_json(const Eigen::VectorXd& v) { return std::vector<double>(v.data(), v.data() + v.size()); }

Eigen::VectorXd json_vector(const json& j) {
  const std::vector<double> values = j.get<std::vector<double>>();
  return Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
}

json point_json(const Eigen::VectorXd& u, double lambda, const Eigen::VectorXd& tangent) {
  return {{"u", vector_json(u)}, {"lambda", lambda}, {"tangent", vector_json(tangent)}};
}

json summary_json(const ContinuationSummary& s) {
  return {{"points", s.points},
          {"newton_iterations", s.newton_iterations},
          {"failed_steps", s.failed_steps},
          {"step_halvings", s.step_halvings},
          {"jacobian_evaluations", s.jacobian_evaluations}};
}

}  // namespace

void write_continuation_state(const std::string& path, const ContinuationState& state, const nlohmann::json& settings) {
  json special = json::array();
  for (const SpecialPoint& sp : state.special_points) {
    json j = point_json(sp.u, sp.lambda, sp.tangent);
    j["type"] = sp.type;
    j["index"] = sp.index;
    j["located"] = sp.located;
    special.push_back(j);
  }
  json first = point_json(state.first.u, state.first.lambda, state.first.tangent);
  first["newton_iterations"] = state.first.newton_iterations;
  const json document = {{"format", kFormat},
                         {"settings", settings},
                         {"state",
                          {{"points", state.points},
                           {"x", vector_json(state.x)},
                           {"x_before", vector_json(state.x_before)},
                           {"tangent", vector_json(state.tangent)},
                           {"unknown_scale", vector_json(state.unknown_scale)},
                           {"step", state.step},
                           {"farthest", state.farthest},
                           {"test_values", state.test_values},
                           {"bp_log_det", state.bp_log_det},
                           {"first", first},
                           {"first_scale", vector_json(state.first_scale)},
                           {"first_parameter_scale", state.first_parameter_scale},
                           {"special_points", special},
                           {"summary", summary_json(state.summary)}}}};
  write_json_atomically(path, document);
}

SavedContinuation read_continuation_state(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open (no checkpoint: the run stopped before its first step)");
  try {
    const json document = json::parse(in);
    if (document.at("format").get<int>() != kFormat)
      throw std::runtime_error("format " + document.at("format").dump() + " is not " + std::to_string(kFormat));
    const json& j = document.at("state");
    SavedContinuation saved;
    saved.settings = document.at("settings");
    ContinuationState& s = saved.state;
    s.points = j.at("points").get<int>();
    s.x = json_vector(j.at("x"));
    s.x_before = json_vector(j.at("x_before"));
    s.tangent = json_vector(j.at("tangent"));
    s.unknown_scale = json_vector(j.at("unknown_scale"));
    s.step = j.at("step").get<double>();
    s.farthest = j.at("farthest").get<double>();
    s.test_values = j.at("test_values").get<std::vector<double>>();
    s.bp_log_det = j.at("bp_log_det").get<double>();
    const json& first = j.at("first");
    s.first = BranchPoint{json_vector(first.at("u")), first.at("lambda").get<double>(), json_vector(first.at("tangent")),
                          first.at("newton_iterations").get<int>(), 0.0};
    s.first_scale = json_vector(j.at("first_scale"));
    s.first_parameter_scale = j.at("first_parameter_scale").get<double>();
    for (const json& sp : j.at("special_points"))
      s.special_points.push_back(SpecialPoint{sp.at("type").get<std::string>(), sp.at("index").get<int>(), sp.at("located").get<bool>(),
                                              sp.at("lambda").get<double>(), json_vector(sp.at("u")), json_vector(sp.at("tangent"))});
    const json& summary = j.at("summary");
    s.summary.points = summary.at("points").get<int>();
    s.summary.newton_iterations = summary.at("newton_iterations").get<int>();
    s.summary.failed_steps = summary.at("failed_steps").get<int>();
    s.summary.step_halvings = summary.at("step_halvings").get<int>();
    s.summary.jacobian_evaluations = summary.at("jacobian_evaluations").get<int>();
    if (s.points < 1 || s.x.size() < 1 || s.x.size() != s.tangent.size() || s.unknown_scale.size() + 1 != s.x.size())
      throw std::runtime_error("inconsistent state");
    return saved;
  } catch (const json::exception& e) {
    throw std::runtime_error(path + ": not a checkpoint: " + e.what());
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
}

}  // namespace hbtrack
