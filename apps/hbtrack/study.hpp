#pragma once
// `hbtrack study` (verb_study.cpp): the paper's whole analysis of one case, as the verbs a user
// would run by hand, each a child process writing its own result folder under DIR. The stages are
// this class's methods, one file per group: verb_study.cpp (running steps, the nominal NFRC, the
// switched branches, the figures), study_tracking_stage.cpp (tracking, added families),
// study_validation_stage.cpp (validation NFRCs, isolas, simulations), study_convergence_stage.cpp.
#include <algorithm>
#include <map>
#include <optional>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/results/results_writer.hpp"
#include "study_comparisons.hpp"
#include "study_curves.hpp"
#include "study_plan.hpp"
#include "task_runner.hpp"

namespace hbtrack::cli {

struct StudyOptions {
  CommonOptions common;
  std::vector<std::string> only;  // restrict the tracked parameters
  int jobs = 0;                   // steps side by side; 0: one per core
  std::string units;              // the model's length unit, for the figures' labels
  std::string resume;             // a stopped study's folder to go on in (study_resume.hpp)
};

class Study {
  using json = nlohmann::json;

 public:
  Study(const StudyOptions& o, const CaseDefinition& c, TaskRunner& runner) : o_(o), c_(c), dir_(o.common.out_dir), runner_(runner) {
    for (const StudyTrack& t : c_.study.track)
      if (o_.only.empty() || std::find(o_.only.begin(), o_.only.end(), t.parameter) != o_.only.end()) tracked_.push_back(t);
  }

  int run();

 private:
  // Runs independent steps side by side; false when the study cannot go on.
  bool run_steps(const std::vector<Step>& steps);
  bool stop(const std::string& reason);
  // What summary.json's steps recorded of the step in `folder` (its last run), or an empty object.
  const json& step_record(const std::string& folder) const;
  void save() const { write_json_atomically(dir_ + "/summary.json", summary_); }
  std::string first_output() const { return c_.outputs.empty() ? "" : c_.outputs.front().name; }
  double case_value(const std::string& name) const { return c_.parameters.value(c_.parameters.find(name)); }

  bool nominal();

  // Beside the NFRC, as [study] asks: the backbones and the tori side by side (study_tori.hpp),
  // then the branch of each BP and PD in turn, a point that an earlier switched branch passes
  // through not switched again.
  bool branches();

  // Round k follows the k-th limit point in every parameter at once; a limit point that already
  // lies on an earlier curve of the same parameter (the two folds of one cusp) is not tracked again.
  bool tracking();

  void add_curve(const StudyTrack& t, size_t lp, double omega, const std::string& folder);

  // With [study] track_ns_pd: every NS and PD point of the nominal NFRC followed in every
  // parameter (`track_P_nsK/`, `track_P_pdK/`), listed with the curves but kept out of the
  // validation and isola searches, which are about limit points.
  bool ns_pd_tracking();

  // NFRCs from the linear solution next to every extremum (or at both ends of a range without
  // one), the tracking curves' limit points located at the same values, and the time
  // integration: all independent of each other.
  bool validation_and_simulation();

  struct Probe {
    const StudyTrack* track;
    double value;
    std::string tag;
  };

  // A validation NFRC that left through the start of its range (its branch turned back past
  // omega_start) is computed again over a range widened beyond the start by one range width (at
  // most to 5 % of it): the branch then runs through its turning point there and on, and every
  // limit point it meets is compared.
  bool continue_validations_beyond_the_range();

  void compare(const Probe& p);

  // A validation NFRC's limit point on no tracking curve belongs to a family no limit point of the
  // nominal NFRC leads to: it is tracked from that NFRC (`track_P_addedK/`, at most
  // study.max_added_curves per parameter, one per parameter at a time so that a second limit
  // point of the same family is not tracked twice), then the crossings at every validation value
  // of P are located again with every curve (`crossings_P_J_all/`) and the NFRCs compared again.
  bool added_families();

  // Limit points of the tracking curves that no NFRC from the linear solution passes announce
  // isolated branches: `isolas` follows each until it closes.
  bool isolas();

  // Where the resonance's time integration starts: the nominal NFRC's largest stable response
  // (point, -1: no integration) and the LP K that ends its stable stretch (0: none, or the NFRC
  // has no stability; the integration then starts from the point itself).
  struct ResonanceStart {
    size_t fold = 0;
    long point = -1;
  };
  ResonanceStart resonance_start() const;

  void compare_simulation();

  // The paper's Fig. 12 (a stable point of an isolated branch, integrated in time) and the
  // convergence stage's refined NFRC, side by side: neither reads the other, and the integration
  // would otherwise hold one core alone for minutes. Then the convergence's tracking curves.
  bool isola_simulation_and_convergence();
  struct IsolaSimulation {
    Step step;
    std::string from;     // the isola's folder
    cli::BranchPoint at;  // the isola's stable point
  };
  std::optional<IsolaSimulation> isola_simulation_step() const;
  void record_isola_simulation(const IsolaSimulation& run);

  // Every event recomputed with more harmonics and samples: the nominal NFRC (this step), then
  // each tracking curve from the refined NFRC's limit point nearest the original's.
  std::optional<Step> refined_nfrc_step() const;
  bool convergence_tracking();

  // Figures are a convenience: a missing matplotlib costs the pictures, not the study.
  void figures();

  const StudyOptions& o_;
  const CaseDefinition& c_;
  const std::string dir_;
  TaskRunner& runner_;
  std::vector<StudyTrack> tracked_;
  json summary_;
  json limit_points_ = json::array();
  std::map<std::string, json> entries_;  // per tracked parameter: curves, extrema, validations
  std::map<std::string, std::vector<TrackingCurve>> curves_;
  std::vector<Probe> probes_;
  std::map<std::string, std::string> crossings_folder_;  // a probe's crossings located again with added curves
  std::set<std::string> tried_;                          // "folder#K": limit points an added curve started from
  std::string stop_reason_;
  Stage stage_ = kNominal;
  std::map<std::string, json> previous_;  // resuming: the stopped study's ended steps, by folder
};

}  // namespace hbtrack::cli
