#pragma once
// The case-file reader's toolkit, shared by the readers of the case's sections (case_file.cpp,
// case_elements.cpp): a TOML reader whose every error is one line
// "<file>:<line>: <field>: <rule>", with did-you-mean suggestions.
#include <toml.hpp>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "hbtrack/io/case_file.hpp"
#include "hbtrack/util/choices.hpp"
#include "toml_long_lines.hpp"

namespace hbtrack {

// The candidate nearest to `word` by edit distance, or "" when none is close.
std::string nearest(const std::string& word, const std::vector<std::string>& candidates);
// "a, b, c".
std::string join(const std::vector<std::string>& words);

// Reads one case file, keeping the file name and field path for every error message.
class CaseReader {
 public:
  // `lines`: the file's line of each line the parser read (break_long_toml_lines), for messages.
  explicit CaseReader(std::string file, LineMap lines = {}) : file_(std::move(file)), lines_(std::move(lines)) {}

  [[noreturn]] void fail(const toml::value* where, const std::string& field, const std::string& rule) const {
    std::string loc = file_;
    if (where) {
      const auto l = where->location();
      if (l.line() > 0 && l.file_name() != "unknown file" && l.file_name() != "--set")
        loc += ":" + std::to_string(lines_.original(static_cast<long>(l.line())));
      if (l.file_name() == "--set") loc = "--set";
    }
    throw CaseError(loc + ": " + (field.empty() ? "" : field + ": ") + rule);
  }

  const toml::value* find(const toml::value& table, const std::string& key) const {
    if (!table.is_table() || !table.contains(key)) return nullptr;
    return &table.at(key);
  }
  const toml::value& require(const toml::value& table, const std::string& key, const std::string& field) const {
    const toml::value* v = find(table, key);
    if (!v) fail(&table, field, "missing (required)");
    return *v;
  }
  const toml::value& table(const toml::value& v, const std::string& field) const {
    if (!v.is_table()) fail(&v, field, "expected a table");
    return v;
  }
  void check_keys(const toml::value& table_value, const std::string& field, const std::vector<std::string>& allowed) const {
    for (const auto& [key, value] : table_value.as_table()) {
      if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
      const std::string guess = nearest(key, allowed);
      fail(&value, field.empty() ? key : field + "." + key,
           "unknown key" + (guess.empty() ? " (expected one of: " + join(allowed) + ")" : " (did you mean '" + guess + "'?)"));
    }
  }
  double number(const toml::value& v, const std::string& field) const {
    double x = 0;
    if (v.is_integer())
      x = static_cast<double>(v.as_integer());
    else if (v.is_floating())
      x = v.as_floating();
    else
      fail(&v, field, "expected a number");
    if (!std::isfinite(x)) fail(&v, field, "must be finite");
    return x;
  }
  int integer(const toml::value& v, const std::string& field) const {
    if (!v.is_integer()) fail(&v, field, "expected an integer");
    const auto i = v.as_integer();
    if (i < -2147483647 || i > 2147483647) fail(&v, field, "integer out of range");
    return static_cast<int>(i);
  }
  std::string string(const toml::value& v, const std::string& field) const {
    if (!v.is_string()) fail(&v, field, "expected a string");
    return v.as_string().str;
  }
  double number_or(const toml::value& t, const std::string& key, const std::string& field, double fallback) const {
    const toml::value* v = find(t, key);
    return v ? number(*v, field) : fallback;
  }
  int integer_or(const toml::value& t, const std::string& key, const std::string& field, int fallback) const {
    const toml::value* v = find(t, key);
    return v ? integer(*v, field) : fallback;
  }
  std::string string_or(const toml::value& t, const std::string& key, const std::string& field, std::string fallback) const {
    const toml::value* v = find(t, key);
    return v ? string(*v, field) : fallback;
  }
  // A named choice (util/choices.hpp): an unknown name fails with the choice's own message.
  template <NamedChoice Choice>
  Choice choice_or(const toml::value& t, const std::string& key, Choice fallback) const {
    const toml::value* v = find(t, key);
    if (!v) return fallback;
    const std::string field(ChoiceTable<Choice>::field);
    try {
      return parse_choice<Choice>(string(*v, field));
    } catch (const std::invalid_argument& e) {
      fail(v, "", e.what());
    }
  }
  Eigen::VectorXd vector(const toml::value& v, const std::string& field) const {
    if (!v.is_array()) fail(&v, field, "expected an array of numbers");
    const auto& a = v.as_array();
    Eigen::VectorXd out(static_cast<Eigen::Index>(a.size()));
    for (size_t i = 0; i < a.size(); ++i) out(static_cast<Eigen::Index>(i)) = number(a[i], field + "[" + std::to_string(i) + "]");
    return out;
  }
  std::vector<std::string> strings(const toml::value& v, const std::string& field) const {
    if (v.is_string()) return {v.as_string().str};
    if (!v.is_array()) fail(&v, field, "expected a string or an array of strings");
    std::vector<std::string> out;
    for (size_t i = 0; i < v.as_array().size(); ++i) out.push_back(string(v.as_array()[i], field + "[" + std::to_string(i) + "]"));
    return out;
  }
  std::filesystem::path resolve(const std::string& relative) const {
    const std::filesystem::path p(relative);
    return p.is_absolute() ? p : std::filesystem::path(file_).parent_path() / p;
  }

  // A matrix: inline rows, {diagonal = [...]}, {file = "K.mtx"} or {file = "m.mat", variable = "K"};
  // n >= 0 requires n x n.
  Eigen::MatrixXd matrix(const toml::value& v, const std::string& field, int n) const;

 private:
  std::string file_;
  LineMap lines_;
};

// The index of the dof named by v ("unknown dof" with a suggestion otherwise).
int dof_index(const CaseReader& in, const StructuralModel& m, const toml::value& v, const std::string& field);
// A property: a number, a parameter name, or {parameter = "mu", scale = 1, offset = 0}.
ParameterBinding binding(const CaseReader& in, const CaseDefinition& c, const toml::value& v, const std::string& field);

// The case file's readers of its settings, shared by load_case and with_overrides
// (case_settings.cpp): the [harmonic_balance], [continuation] and [stability] sections onto c,
// the checks of those settings against the model, and `--set NAME=VALUE` onto a document.
void read_settings(const CaseReader& in, const toml::value& root, CaseDefinition& c);
void check_stability_supported(const CaseReader& in, const toml::value& root, const CaseDefinition& c);
void check_forcing_within_harmonics(const CaseReader& in, const toml::value& root, const CaseDefinition& c);
void apply_overrides(const CaseReader& in, toml::value& root, const std::vector<std::string>& overrides);

}  // namespace hbtrack
