#pragma once
// The study's last stage: its figures, drawn by the Python package (hbtrack.study_figures) into
// DIR/figures. A convenience: without matplotlib or the package the study keeps its numbers.
#include <nlohmann/json.hpp>
#include <string>

namespace hbtrack::cli {

// The PNG files drawn (relative to dir, sorted); empty when the package is missing or failed,
// which is said on stderr unless quiet. `units`: the model's length unit for the labels ("" none).
nlohmann::json draw_study_figures(const std::string& dir, const std::string& units, bool quiet);

}  // namespace hbtrack::cli
