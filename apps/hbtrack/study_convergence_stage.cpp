// The study's convergence stage (study.hpp): the events recomputed with more harmonics and samples.
#include <map>

#include "cli_common.hpp"
#include "result_folder.hpp"
#include "study.hpp"
#include "study_comparisons.hpp"
#include "study_curves.hpp"
#include "study_plan.hpp"

namespace hbtrack::cli {

using nlohmann::json;

namespace {
// A verb's arguments with the convergence's harmonics and samples set.
std::vector<std::string> with_refinement(const CaseDefinition& c, std::vector<std::string> args) {
  args.insert(args.end(), {"--set", "harmonic_balance.harmonics=" + std::to_string(c.study.convergence_harmonics), "--set",
                           "harmonic_balance.samples=" + std::to_string(c.study.convergence_samples)});
  return args;
}
}  // namespace

std::optional<Step> Study::refined_nfrc_step() const {
  if (c_.study.convergence_harmonics <= 0) return std::nullopt;
  return Step{"converged/nfrc", with_refinement(c_, {"frc", o_.common.case_path, "--set", "stability.method=none"}), false};
}

// Each tracking curve again from the refined NFRC's limit point nearest the original's, and the
// events compared.
bool Study::convergence_tracking() {
  stage_ = kConvergence;
  const int h = c_.study.convergence_harmonics, n = c_.study.convergence_samples;
  const json refined = read_summary(dir_ + "/converged/nfrc");
  json report = {{"harmonics", h},
                 {"samples", n},
                 {"limit_points",
                  compare_limit_points(summary_["nfrc"]["special_points"], refined.value("special_points", json::array()), first_output())},
                 {"tracking", json::array()}};
  std::vector<Step> steps;
  std::vector<const StudyTrack*> which;
  for (const StudyTrack& t : tracked_)
    for (const auto& curve : entries_[t.parameter]["curves"]) {
      if (!curve.contains("folder")) continue;
      if (curve.value("lp", 0) == 0) continue;  // an added family's (started from a validation NFRC), an NS or PD curve
      const size_t lp = nearest_limit_point(refined.value("special_points", json::array()), curve.value("omega", 0.0));
      if (lp == 0) continue;
      const std::string folder = "converged/" + curve.value("folder", std::string());
      steps.push_back({folder,
                       with_refinement(c_, {"track", o_.common.case_path, "--from", dir_ + "/converged/nfrc", "--lp", std::to_string(lp),
                                            "--param", t.parameter, "--range", number_text(t.min) + ":" + number_text(t.max), "--set",
                                            "continuation.max_points=" + std::to_string(c_.study.max_points)}),
                       false});
      which.push_back(&t);
    }
  if (!run_steps(steps)) return false;
  std::map<std::string, std::vector<TrackingCurve>> refined_curves;
  for (size_t i = 0; i < steps.size(); ++i)
    refined_curves[which[i]->parameter].push_back(
        read_tracking_curve_folder(dir_ + "/" + steps[i].folder, which[i]->parameter, first_output()));
  for (const StudyTrack& t : tracked_)
    report["tracking"].push_back(
        {{"parameter", t.parameter},
         {"extrema", compare_extrema(entries_[t.parameter]["extrema"], refined_curves[t.parameter], first_output())}});
  summary_["convergence"] = report;
  save();
  return true;
}

}  // namespace hbtrack::cli
