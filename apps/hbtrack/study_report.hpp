#pragma once
// The page a person reads after `hbtrack study`: DIR/index.md, built from the study's
// summary.json (the numbers) and the figures it drew.
#include <string>

#include <nlohmann/json.hpp>

namespace hbtrack::cli {

void write_study_report(const std::string& dir, const nlohmann::json& summary);

}  // namespace hbtrack::cli
