// Each setting is named in several lists: the case-file reader's, summary.json's options
// (options_json), with_overrides' copy of the settings (the Python runs' keywords), the Python
// option classes (python/tests/test_option_lists.py) and docs/case-file.md
// (test_case_file_docs.cpp). The reader's list is the source of truth: a key added to one list
// only fails here, naming the list that lacks it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "case_key_probe.hpp"
#include "hbtrack/hbm/harmonic_balance.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/results/result_tables.hpp"
#include "test_support.hpp"

namespace hbtrack_tests::file_option_lists {

using namespace hbtrack;
using nlohmann::json;

// The sections whose keys are settings of a run (the model, forcing and elements are the case's).
const std::vector<std::string> kSettingSections{"harmonic_balance", "continuation", "stability"};

const std::string kDuffing = test::source_path("examples/duffing.toml");

json settings_of(const CaseDefinition& c) {
  const HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  return options_json(c, hbm);
}

KeySet keys_of(const json& object) {
  KeySet keys;
  for (const auto& [key, value] : object.items()) keys.insert(key);
  return keys;
}

// `--set SECTION.KEY=...` with a value other than `now` (how summary.json writes the current
// one) that the reader takes on the example and that changes summary.json's options: another
// name of a choice, the other boolean, a nearby number. Empty when none was found.
std::string changed_setting(const std::string& key, const json& now) {
  std::vector<std::string> candidates;
  // A table of settings (harmonic_balance.adaptive, written when on): one the example takes.
  if (key == "harmonic_balance.adaptive") candidates.push_back("{min=3, max=9, add_above=1e-3, drop_below=1e-5}");
  if (now.is_boolean()) candidates.push_back(now.get<bool>() ? "false" : "true");
  if (now.is_number_integer()) candidates.push_back(std::to_string(now.get<long>() + 1));
  if (now.is_number_float()) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", now.get<double>() == 0 ? 1.0 : 0.9 * now.get<double>());
    candidates.push_back(text);
  }
  if (now.is_string()) {
    // The other names, from the reader's message for a name that is none of them.
    try {
      load_case(kDuffing, {key + "=\"qqqqqqqq\""});
    } catch (const CaseError& e) {
      std::string names = e.what();
      names = names.substr(names.find("must be ") + 8);
      names = names.substr(0, names.find(", got"));
      for (const std::string separator : {" or ", ", "})
        for (size_t at; (at = names.find(separator)) != std::string::npos;) names.replace(at, separator.size(), "|");
      for (size_t start = 0, end; start <= names.size(); start = end + 1) {
        end = std::min(names.find('|', start), names.size());
        if (names.substr(start, end - start) != now.get<std::string>())
          candidates.push_back("\"" + names.substr(start, end - start) + "\"");
      }
    }
  }
  const json plain = settings_of(load_case(kDuffing));
  for (const std::string& value : candidates) {
    try {
      // Written as what it resolves to ("auto" condensation as the method chosen): one that
      // changes summary.json's options, so that losing it shows.
      if (settings_of(load_case(kDuffing, {key + "=" + value})) != plain) return key + "=" + value;
    } catch (const CaseError&) {
      continue;  // not valid on this example (a method it cannot use): the next one
    }
  }
  return "";
}

// summary.json records every setting the reader accepts, under the same key (the writer may add
// what it derived: the unknowns and retained dofs of the harmonic balance).
TEST(OptionLists, SummaryWritesEverySettingTheReaderAccepts) {
  json written = settings_of(load_case(kDuffing, {"harmonic_balance.subharmonic=2"}));  // written when not 1
  // Written when on, which a subharmonic refuses: from a run of its own.
  written["harmonic_balance"]["adaptive"] =
      settings_of(load_case(kDuffing, {"harmonic_balance.adaptive={min=3, max=9}"})).at("harmonic_balance").at("adaptive");
  for (const std::string& section : kSettingSections) {
    KeySet keys = keys_of(written.at(section));
    if (section == "harmonic_balance") {
      for (const char* derived : {"unknowns", "retained_dofs"}) EXPECT_EQ(keys.erase(derived), 1u) << derived;
    }
    EXPECT_EQ(keys, accepted_keys(section)) << "options_json (src/results/result_tables.cpp) against the reader's [" << section << "]";
  }
}

// with_overrides copies the settings into a document its reader reads back: a key missing from
// the copy would fall back to its default on every Python run given keywords.
TEST(OptionLists, OverridesOnACaseKeepEverySettingTheReaderAccepts) {
  const json plain = settings_of(load_case(kDuffing));
  for (const std::string& section : kSettingSections)
    for (const std::string& key : accepted_keys(section)) {
      const json& now = plain.at(section).contains(key) ? plain.at(section).at(key) : json(1);  // subharmonic: written when not 1
      const std::string set = changed_setting(section + "." + key, now);
      ASSERT_FALSE(set.empty()) << section << "." << key << ": no other value the example takes";
      const CaseDefinition changed = load_case(kDuffing, {set});
      EXPECT_EQ(settings_of(with_overrides(changed, {"amplitude=1.5"})), settings_of(load_case(kDuffing, {set, "amplitude=1.5"})))
          << set << ": lost by with_overrides (src/io/case_settings.cpp)";
    }
}

}  // namespace hbtrack_tests::file_option_lists
