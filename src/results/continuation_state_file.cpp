#include "hbtrack/results/continuation_state_file.hpp"

#include <fstream>
#include <stdexcept>

#include "hbtrack/io/json_file.hpp"
#include "hbtrack/results/results_writer.hpp"

namespace hbtrack {

namespace {

using nlohmann::json;

constexpr int kFormat = 1;            // an NFRC (frc) checkpoint
constexpr int kTrackingFormat = 101;  // a tracking (track) checkpoint: not resumable as an NFRC

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
          {"jacobian_evaluations", s.jacobian_evaluations},
          {"residual_evaluations", s.residual_evaluations},
          {"chord_iterations", s.chord_iterations},
          {"factorizations", s.factorizations},
          {"corners_stepped_over", s.corners_stepped_over}};
}

json state_json(const ContinuationState& state) {
  json special = json::array();
  for (const SpecialPoint& sp : state.special_points) {
    json j = point_json(sp.u, sp.lambda, sp.tangent);
    j["type"] = to_string(sp.type);
    j["index"] = sp.index;
    j["located"] = sp.located;
    j["decided_by"] = sp.decided_by;
    special.push_back(j);
  }
  json first = point_json(state.first.u, state.first.lambda, state.first.tangent);
  first["newton_iterations"] = state.first.newton_iterations;
  return {{"points", state.points},
          {"x", vector_json(state.x)},
          {"x_before", vector_json(state.x_before)},
          {"tangent", vector_json(state.tangent)},
          {"unknown_scale", vector_json(state.unknown_scale)},
          {"step", state.step},
          {"step_cut", state.step_cut},
          {"farthest", state.farthest},
          {"test_values", state.test_values},
          {"bp_log_det", state.bp_log_det},
          {"earlier_test_values", state.earlier_test_values},
          {"earlier_distance", state.earlier_distance},
          {"monitor_verdict", state.monitor_verdict},
          {"first", first},
          {"first_scale", vector_json(state.first_scale)},
          {"first_parameter_scale", state.first_parameter_scale},
          {"special_points", special},
          {"summary", summary_json(state.summary)}};
}

ContinuationSummary summary_from_json(const json& summary) {
  ContinuationSummary s;
  s.points = summary.at("points").get<int>();
  s.newton_iterations = summary.at("newton_iterations").get<int>();
  s.failed_steps = summary.at("failed_steps").get<int>();
  s.step_halvings = summary.at("step_halvings").get<int>();
  s.jacobian_evaluations = summary.at("jacobian_evaluations").get<int>();
  // Counters added after the first checkpoints were written: 0 when absent.
  s.residual_evaluations = summary.value("residual_evaluations", 0);
  s.chord_iterations = summary.value("chord_iterations", 0);
  s.factorizations = summary.value("factorizations", 0);
  s.corners_stepped_over = summary.value("corners_stepped_over", 0);
  return s;
}

// The named value (a stop reason, a special point's type) at object[key]; an unknown name is a
// std::runtime_error naming `where` (read_checkpoint prefixes it with the path).
template <NamedChoice Choice>
Choice choice_from_json(const json& object, const char* key, const std::string& where) {
  try {
    return parse_choice<Choice>(object.at(key).get<std::string>(), where + "." + key);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(e.what());
  }
}

ContinuationState state_from_json(const json& j) {
  ContinuationState s;
  s.points = j.at("points").get<int>();
  s.x = json_vector(j.at("x"));
  s.x_before = json_vector(j.at("x_before"));
  s.tangent = json_vector(j.at("tangent"));
  s.unknown_scale = json_vector(j.at("unknown_scale"));
  s.step = j.at("step").get<double>();
  // Absent from checkpoints written before the step controller remembered cuts: false, as
  // the controller that wrote them behaved.
  s.step_cut = j.value("step_cut", false);
  s.farthest = j.at("farthest").get<double>();
  s.test_values = j.at("test_values").get<std::vector<double>>();
  s.bp_log_det = j.at("bp_log_det").get<double>();
  // Absent from checkpoints written before monitors could skip points: no history, so the
  // resumed run evaluates its monitor at its next two points.
  s.earlier_test_values = j.value("earlier_test_values", std::vector<double>());
  s.earlier_distance = j.value("earlier_distance", 0.0);
  s.monitor_verdict = j.value("monitor_verdict", 0);
  const json& first = j.at("first");
  s.first = BranchPoint{json_vector(first.at("u")), first.at("lambda").get<double>(), json_vector(first.at("tangent")),
                        first.at("newton_iterations").get<int>(), 0.0};
  s.first_scale = json_vector(j.at("first_scale"));
  s.first_parameter_scale = j.at("first_parameter_scale").get<double>();
  for (const json& sp : j.at("special_points"))
    s.special_points.push_back(SpecialPoint{
        choice_from_json<SpecialPointType>(sp, "type", "state.special_points[" + std::to_string(s.special_points.size()) + "]"),
        sp.at("index").get<int>(), sp.at("located").get<bool>(), sp.at("lambda").get<double>(), json_vector(sp.at("u")),
        json_vector(sp.at("tangent")), sp.value("decided_by", std::string())});
  s.summary = summary_from_json(j.at("summary"));
  if (s.points < 1 || s.x.size() < 1 || s.x.size() != s.tangent.size() || s.unknown_scale.size() + 1 != s.x.size())
    throw std::runtime_error("inconsistent state");
  return s;
}

// The leg's stop_reason, one of the names; another is bad input naming the field (a
// std::runtime_error, which read_checkpoint prefixes with the path).
StopReason stop_reason_from_json(const json& leg, const std::string& where) {
  return choice_from_json<StopReason>(leg, "stop_reason", where);
}

// Parses path as a checkpoint of `format`; read(document) builds the result. Errors name the path.
template <class Read>
auto read_checkpoint(const std::string& path, int format, Read read) {
  if (!std::ifstream(path)) throw std::runtime_error(path + ": cannot open (no checkpoint: the run stopped before its first step)");
  // Bounded in size and depth before parsing: settings nested 200 000 deep overflowed the stack.
  const json document = read_json_file(path, "a checkpoint");
  try {
    if (document.at("format").get<int>() != format)
      throw std::runtime_error("format " + document.at("format").dump() + " is not " + std::to_string(format));
    return read(document);
  } catch (const json::exception& e) {
    throw std::runtime_error(path + ": not a checkpoint: " + e.what());
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
}

}  // namespace

void write_continuation_state(const std::string& path, const ContinuationState& state, const nlohmann::json& settings,
                              const nlohmann::json& tallies) {
  write_json_atomically(path, {{"format", kFormat}, {"settings", settings}, {"state", state_json(state)}, {"tallies", tallies}});
}

SavedContinuation read_continuation_state(const std::string& path) {
  return read_checkpoint(path, kFormat, [](const json& document) {
    const json tallies = document.value("tallies", json::object());
    if (!tallies.is_object()) throw std::runtime_error("tallies: expected an object");
    return SavedContinuation{state_from_json(document.at("state")), document.at("settings"), tallies};
  });
}

void write_tracking_state(const std::string& path, const FoldTrackingState& state, const nlohmann::json& settings) {
  json borders = json::array();
  for (const Eigen::VectorXd& b : state.borders) borders.push_back(vector_json(b));
  json legs = json::array();
  for (const ContinuationSummary& leg : state.finished_legs) {
    json j = summary_json(leg);
    j["stop_reason"] = to_string(leg.stop_reason);
    j["wall_s"] = leg.wall_s;
    legs.push_back(j);
  }
  json extrema = json::array();
  for (const FoldExtremum& e : state.extrema)
    extrema.push_back({{"type", to_string(e.type)},
                       {"located", e.located},
                       {"x", vector_json(e.x)},
                       {"omega", e.omega},
                       {"parameter", e.parameter},
                       {"index", e.index}});
  const json tracking = {{"leg", state.leg},   {"leg_offset", state.leg_offset},       {"curve_points", state.curve_points},
                         {"borders", borders}, {"lambda_slopes", state.lambda_slopes}, {"finished_legs", legs},
                         {"extrema", extrema}};
  write_json_atomically(
      path, {{"format", kTrackingFormat}, {"settings", settings}, {"tracking", tracking}, {"state", state_json(state.continuation)}});
}

SavedTracking read_tracking_state(const std::string& path) {
  return read_checkpoint(path, kTrackingFormat, [](const json& document) {
    SavedTracking saved;
    saved.settings = document.at("settings");
    FoldTrackingState& s = saved.state;
    const json& t = document.at("tracking");
    s.leg = t.at("leg").get<int>();
    s.leg_offset = t.at("leg_offset").get<int>();
    s.curve_points = t.at("curve_points").get<int>();
    for (const json& b : t.at("borders")) s.borders.push_back(json_vector(b));
    s.lambda_slopes = t.at("lambda_slopes").get<std::vector<double>>();
    for (const json& leg : t.at("finished_legs")) {
      ContinuationSummary summary = summary_from_json(leg);
      summary.stop_reason = stop_reason_from_json(leg, "tracking.finished_legs[" + std::to_string(s.finished_legs.size()) + "]");
      summary.wall_s = leg.at("wall_s").get<double>();
      s.finished_legs.push_back(summary);
    }
    for (const json& e : t.at("extrema")) {
      FoldExtremum x;
      x.type = choice_from_json<CurveExtremumType>(e, "type", "tracking.extrema[" + std::to_string(s.extrema.size()) + "]");
      x.located = e.at("located").get<bool>();
      x.x = json_vector(e.at("x"));
      x.omega = e.at("omega").get<double>();
      x.parameter = e.at("parameter").get<double>();
      x.index = e.at("index").get<int>();
      s.extrema.push_back(std::move(x));
    }
    s.continuation = state_from_json(document.at("state"));
    if (s.leg < 1 || s.leg > 2 || s.curve_points < 0 || s.lambda_slopes.size() != static_cast<size_t>(s.continuation.points) ||
        s.finished_legs.size() != static_cast<size_t>(s.leg - 1))
      throw std::runtime_error("inconsistent tracking state");
    return saved;
  });
}

}  // namespace hbtrack
