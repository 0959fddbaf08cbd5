#pragma once
// The tori `hbtrack study` computes with [study] torus (docs/study.md): the quasi-periodic
// response born in each unstable band of the nominal NFRC between two Neimark-Sacker points
// (`hbtrack torus CASE --from DIR/nfrc --ns K --range LO:HI`, into torus_nsK/), started at the
// band's lower NS point and expected to close at the other. The study runs them beside its
// backbones; what they found goes into its summary, page and figures.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hbtrack/io/case_file.hpp"

namespace hbtrack::cli {

// One torus step: the verb run into the study's folder `folder` (the study adds --set, -q and -o),
// from NS point `ns` (K in increasing omega, as `torus --ns K` counts) across its band to NS
// point `other_ns`.
struct TorusStep {
  std::string folder;
  std::vector<std::string> args;
  int ns = 0, other_ns = 0;
};

// The bands of the NFRC in nfrc_dir (its summary's special_points, its branch.csv's stability):
// two NS points consecutive along the branch with every row between them unstable. The range is
// the case's omega range, [omega_lo, omega_hi].
std::vector<TorusStep> torus_steps(const std::string& case_path, const std::string& nfrc_dir, const nlohmann::json& special_points,
                                   const StudyTorus& torus, double omega_lo, double omega_hi);

// The study summary's entry of a torus step: its NS points, and either why it was skipped (the
// torus refused the case: `skipped`, the verb's one-line reason) or what its folder holds (points,
// stop reason, where it ended and the NS point it closed at, the envelope of every output).
nlohmann::json torus_entry(const std::string& study_dir, const TorusStep& step, const nlohmann::json& special_points,
                           const std::vector<OutputDof>& outputs, const nlohmann::json& step_record);

}  // namespace hbtrack::cli
