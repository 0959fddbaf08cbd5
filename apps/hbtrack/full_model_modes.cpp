#include "full_model_modes.hpp"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "hbtrack/io/json_file.hpp"

namespace hbtrack::cli {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::vector<std::string> names_of(const json& j) {
  std::vector<std::string> names;
  if (j.is_array())
    for (const json& n : j) names.push_back(n.is_string() ? n.get<std::string>() : "?");
  return names;
}

}  // namespace

FullModelModes full_model_modes(const CaseDefinition& c) {
  FullModelModes m;
  try {
    const fs::path dofs_file = c.dofs_file;
    if (dofs_file.extension() != ".json") return m;
    const json reduce = read_json_file(dofs_file.string(), "the dof names' summary.json");
    if (!reduce.is_object() || reduce.value("verb", "") != "reduce" || !reduce.contains("full_model")) return m;
    m.reduce_summary = dofs_file.lexically_normal().string();
    for (const json& w : reduce["full_model"].value("natural_frequencies", json::array())) m.frequencies.push_back(w.get<double>());
    m.names = names_of(reduce["full_model"].value("mode_types", json()));
    const fs::path blade_summary = dofs_file.parent_path() / "full_model_summary.json";
    if (m.names.empty() && fs::exists(blade_summary)) {
      const json blade = read_json_file(blade_summary.string(), "make-blade's summary");
      if (blade.is_object() && blade.value("verb", "") == "make-blade") m.names = names_of(blade.value("mode_types", json()));
    }
  } catch (const std::exception&) {  // an unreadable or other summary: nothing to add to the modes
  }
  return m;
}

}  // namespace hbtrack::cli
