#pragma once
// The case-file reader's list of the keys a section accepts, read from its own error message for
// a key nowhere near a valid one: the source of truth the tests of the other lists of option
// names compare with (docs/case-file.md, summary.json's options, with_overrides, Python).
#include <gtest/gtest.h>

#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "hbtrack/io/case_file.hpp"
#include "test_support.hpp"

namespace hbtrack_tests {

using KeySet = std::set<std::string>;

// The reader's allowed keys of a section, from "unknown key (expected one of: a, b, c)".
inline KeySet accepted_keys(const std::string& section) {
  const std::string probe = section + ".qqqqqqqqqqqqqqqqqqqqqqqq=1";
  try {
    hbtrack::load_case(hbtrack::test::source_path("examples/duffing.toml"), {probe});
  } catch (const hbtrack::CaseError& e) {
    const std::string msg = e.what();
    const std::string marker = "expected one of: ";
    const size_t at = msg.find(marker);
    if (at == std::string::npos) {
      ADD_FAILURE() << section << ": " << msg;
      return {};
    }
    KeySet keys;
    std::stringstream list(msg.substr(at + marker.size(), msg.find(')', at) - at - marker.size()));
    for (std::string k; std::getline(list, k, ',');) keys.insert(k.substr(k.find_first_not_of(' ')));
    return keys;
  }
  ADD_FAILURE() << section << ": the reader accepted an unknown key";
  return {};
}

}  // namespace hbtrack_tests
