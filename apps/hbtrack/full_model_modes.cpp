#include "full_model_modes.hpp"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

namespace hbtrack::cli {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

json read_json_file(const fs::path& path) {
  std::ifstream in(path);
  if (!in) return json();
  return json::parse(in, nullptr, /*allow_exceptions=*/false);
}

// The [model] dofs file of a case that load_case read already: `dofs = { file = "..." }` or
// `dofs.file = "..."` on one line, as reduce's cases write it ("" for another form). A text
// search, not a second TOML reader in the tool.
fs::path dofs_file_of(const std::string& case_path) {
  static const std::regex kDofsFile(R"re(^\s*dofs\s*(=\s*\{\s*file|\.file)\s*=\s*"([^"]+)")re");
  std::ifstream in(case_path);
  bool in_model = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind('[', 0) == 0) in_model = line.rfind("[model]", 0) == 0;
    std::smatch m;
    if (in_model && std::regex_search(line, m, kDofsFile)) return fs::path(case_path).parent_path() / m[2].str();
  }
  return {};
}

std::vector<std::string> names_of(const json& j) {
  std::vector<std::string> names;
  if (j.is_array())
    for (const json& n : j) names.push_back(n.is_string() ? n.get<std::string>() : "?");
  return names;
}

}  // namespace

FullModelModes full_model_modes(const std::string& case_path) {
  FullModelModes m;
  try {
    const fs::path dofs_file = dofs_file_of(case_path);
    if (dofs_file.empty()) return m;
    const json reduce = read_json_file(dofs_file);
    if (!reduce.is_object() || reduce.value("verb", "") != "reduce" || !reduce.contains("full_model")) return m;
    m.reduce_summary = dofs_file.lexically_normal().string();
    for (const json& w : reduce["full_model"].value("natural_frequencies", json::array())) m.frequencies.push_back(w.get<double>());
    m.names = names_of(reduce["full_model"].value("mode_types", json()));
    if (m.names.empty()) {
      const json blade = read_json_file(dofs_file.parent_path() / "full_model_summary.json");
      if (blade.is_object() && blade.value("verb", "") == "make-blade") m.names = names_of(blade.value("mode_types", json()));
    }
  } catch (const std::exception&) {  // no dofs file, inline dofs, another layout: nothing to add
  }
  return m;
}

}  // namespace hbtrack::cli
