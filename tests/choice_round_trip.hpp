#pragma once
// The checks every named choice's table gets (util/choices.hpp): tests/test_choices.cpp for the
// settings and stop reasons, tests/test_special_point_type.cpp for the special points' types.
#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "hbtrack/util/choices.hpp"

namespace hbtrack_tests {

// Each value, to its name and back; the names in table order; every enumerator listed once (the
// table's values are 0, 1, ... as the enums declare them, without gaps or repeats, so an
// enumerator left out of its table fails here).
template <class Choice>
std::vector<std::string> round_trip_names() {
  std::vector<std::string> names;
  std::set<std::string> seen;
  int expected_value = 0;
  for (const hbtrack::ChoiceName<Choice>& entry : hbtrack::ChoiceTable<Choice>::names) {
    EXPECT_EQ(static_cast<int>(entry.value), expected_value++) << entry.name;
    const std::string name = hbtrack::to_string(entry.value);
    EXPECT_EQ(hbtrack::parse_choice<Choice>(name), entry.value) << name;
    EXPECT_TRUE(seen.insert(name).second) << name << " appears twice";
    names.push_back(name);
  }
  return names;
}

// The message parse_choice gives for `name`, or "no error".
template <class Choice>
std::string error_for(const std::string& name) {
  try {
    hbtrack::parse_choice<Choice>(name);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace hbtrack_tests
