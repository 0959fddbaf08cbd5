#pragma once
// The branches `hbtrack study` computes beside the nominal NFRC when its [study] section asks
// (docs/study.md): the backbone of each listed mode (`hbtrack backbone`, into backbone_modeK/)
// and the branch born at each BP and PD point of the NFRC (`hbtrack switch`, into switch_bpK/ or
// switch_pdK/, K the point's number in nfrc/summary.json). The study runs them as its other
// steps; what they found goes into its summary, page and NFRC figure.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hbtrack/io/case_file.hpp"

namespace hbtrack::cli {

// A verb run into the study's folder `folder` (the study adds --set, -q and -o).
struct BranchStep {
  std::string folder;
  std::vector<std::string> args;
};

std::vector<BranchStep> backbone_steps(const std::vector<StudyBackbone>& backbones, const std::string& case_path);

// The switch at special point `point` (1-based) of the NFRC in nfrc_dir; nothing for an LP, NS.
bool switchable(const nlohmann::json& special_point);
BranchStep switch_step(const std::string& case_path, const std::string& nfrc_dir, const nlohmann::json& special_point, int point);

// The earlier switched branch (its folder under study_dir) that already passes through this
// special point of the nominal NFRC, or "": the two BPs of one pitchfork branch, the two PDs
// of one period-doubling band give one branch, followed once. A branch passes through the point
// when a segment between two of its rows comes within `omega_relative` of it in omega (relative
// to it) and `output_relative` in the max of every output (relative to the output's largest
// max along the NFRC), the two scaled distances combined as one Euclidean distance <= 1.
std::string switched_branch_through(const std::string& study_dir, const std::vector<std::string>& switched_folders,
                                    const nlohmann::json& special_point, const std::vector<OutputDof>& outputs, double omega_relative,
                                    double output_relative);

// The study summary's entries: what each step found (its folder's summary.json), for the page.
nlohmann::json backbone_entry(const std::string& study_dir, const BranchStep& step, const StudyBackbone& backbone);
nlohmann::json switch_entry(const std::string& study_dir, const std::string& folder, const nlohmann::json& special_point, int point);

}  // namespace hbtrack::cli
