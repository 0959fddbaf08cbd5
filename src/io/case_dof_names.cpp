#include "case_dof_names.hpp"

#include <nlohmann/json.hpp>

#include <set>
#include <string_view>

#include "hbtrack/io/input_file.hpp"
#include "utf8_validation.hpp"

namespace hbtrack {

namespace {

// A line of a names file, quoted in an error: at most 60 characters.
std::string quoted(std::string_view line) { return "'" + std::string(line.substr(0, 60)) + (line.size() > 60 ? "...'" : "'"); }

// One name per line; blank lines and `#` comments (whole lines or after a name) are skipped.
std::vector<std::string> names_from_text(const CaseReader& in, const toml::value& where, const std::string& field, const std::string& path,
                                         const std::string& text) {
  if (const std::size_t bad = first_invalid_utf8(text); bad != std::string_view::npos)
    in.fail(&where, field, path + ": not valid UTF-8 (byte " + std::to_string(bad) + ")");
  std::vector<std::string> names;
  std::string_view all(text);
  if (all.substr(0, 3) == "\xEF\xBB\xBF") all.remove_prefix(3);  // a UTF-8 byte-order mark (Windows editors) is not part of the first name
  std::size_t start = 0;
  for (long line = 1; start <= all.size(); ++line) {
    const std::size_t end = std::min(all.find('\n', start), all.size());
    std::string_view name = all.substr(start, end - start);
    start = end + 1;
    name = name.substr(0, name.find('#'));
    const std::size_t first = name.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) continue;
    name = name.substr(first, name.find_last_not_of(" \t\r") + 1 - first);
    for (const char ch : name)
      if (static_cast<unsigned char>(ch) <= 0x20 || ch == 0x7f)
        in.fail(&where, field,
                path + ":" + std::to_string(line) + ": " + quoted(name) +
                    " is not one name (one name per line, without blanks or control characters)");
    names.emplace_back(name);
  }
  return names;
}

// The "dof_names" array of a summary.json written by `hbtrack reduce`.
std::vector<std::string> names_from_json(const CaseReader& in, const toml::value& where, const std::string& field, const std::string& path,
                                         const std::string& text) {
  try {
    // The JSON parser recurses once per bracket, as the TOML one: same limit.
    check_toml_nesting(text, path);
  } catch (const CaseError& e) {
    in.fail(&where, field, e.what());
  }
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) in.fail(&where, field, path + ": not valid JSON");
  const auto names = j.is_object() ? j.find("dof_names") : j.end();
  if (!j.is_object() || names == j.end() || !names->is_array())
    in.fail(&where, field,
            path + ": no \"dof_names\" array (expected the summary.json of hbtrack reduce, or a .txt file with one name per line)");
  std::vector<std::string> out;
  for (std::size_t i = 0; i < names->size(); ++i) {
    if (!(*names)[i].is_string()) in.fail(&where, field, path + ": dof_names[" + std::to_string(i) + "] is not a string");
    out.push_back((*names)[i].get<std::string>());
  }
  return out;
}

std::vector<std::string> names_from_file(const CaseReader& in, const toml::value& table, const std::string& field) {
  in.check_keys(table, field, {"file"});
  const toml::value& file = in.require(table, "file", field + ".file");
  const std::string path = in.resolve(in.string(file, field + ".file")).string();
  std::string text;
  try {
    text = read_bounded_file(path, kMaxDofNamesFileBytes, "a dof-names file");
  } catch (const CaseError& e) {
    in.fail(&file, field + ".file", e.what());
  }
  if (std::filesystem::path(path).extension() == ".json") return names_from_json(in, file, field + ".file", path, text);
  return names_from_text(in, file, field + ".file", path, text);
}

}  // namespace

std::string column_name_problem(const std::string& what, const std::string& name) {
  // Dof and parameter names head CSV columns (states.csv: NAME_c1, ...; continue's parameter)
  // that export, --from and read_result split at commas and lines.
  if (name.empty()) return "a " + what + " is empty";
  bool bad = false;
  std::string shown;  // control characters as \xNN: the error stays one line
  for (const char ch : name) {
    const auto byte = static_cast<unsigned char>(ch);
    bad = bad || byte < 0x20 || byte == 0x7f || ch == ',' || ch == '"';
    if (byte < 0x20 || byte == 0x7f) {
      static const char* hex = "0123456789abcdef";
      shown += std::string("\\x") + hex[byte >> 4] + hex[byte & 15];
    } else {
      shown += ch;
    }
  }
  if (bad)
    return what + " " + quoted(std::string_view(shown)) + " holds a comma, a double quote or a control character (it heads CSV columns)";
  return "";
}

std::vector<std::string> numbered_dof_names(int n) {
  std::vector<std::string> names;
  names.reserve(static_cast<std::size_t>(std::max(n, 0)));
  // Appended, not "x" + std::to_string(i): GCC 12 reports a false -Wstringop-overflow on that at -O3.
  for (int i = 1; i <= n; ++i) names.emplace_back(1, 'x').append(std::to_string(i));
  return names;
}

std::vector<std::string> read_dof_names(const CaseReader& in, const toml::value& dofs, const std::string& field) {
  std::vector<std::string> names;
  if (dofs.is_table()) {
    names = names_from_file(in, dofs, field);
    if (names.empty())
      in.fail(&dofs.at("file"), field + ".file", "names no dof (one name per line; blank lines and # comments are skipped)");
  } else if (dofs.is_string() || dofs.is_array()) {
    names = in.strings(dofs, field);
    if (names.empty()) in.fail(&dofs, field, "needs at least one dof name");
  } else {
    in.fail(&dofs, field, "expected an array of dof names, a dof count N (names x1 .. xN) or { file = \"names.txt\" }");
  }
  std::set<std::string> seen;
  for (const auto& name : names) {
    if (const std::string problem = column_name_problem("dof name", name); !problem.empty()) in.fail(&dofs, field, problem);
    if (!seen.insert(name).second) in.fail(&dofs, field, "dof name '" + name + "' appears twice");
  }
  return names;
}

}  // namespace hbtrack
