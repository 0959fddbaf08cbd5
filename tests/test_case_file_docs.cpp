// docs/case-file.md documents exactly the keys the case-file reader accepts: for each section
// with a key table, the keys of its table equal the reader's list of allowed keys (read from the
// reader's own error message for a key that is nowhere near a valid one), so neither can drift.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>

#include "case_key_probe.hpp"
#include "hbtrack/io/case_file.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_case_file_docs {

namespace {

// Section name -> the backquoted keys in the first column of its table.
std::map<std::string, KeySet> documented_keys() {
  std::ifstream in(hbtrack::test::source_path("docs/case-file.md"));
  std::map<std::string, KeySet> out;
  std::string line, section;
  const std::regex heading(R"(^## `\[([a-z_]+)\]`)"), key(R"(`([A-Za-z_][A-Za-z_0-9]*)`)");
  bool in_key_table = false;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_search(line, m, heading)) {
      section = m[1];
      in_key_table = false;
      continue;
    }
    if (line.rfind("## ", 0) == 0) section.clear();
    if (section.empty()) continue;
    if (line.rfind("| key |", 0) == 0) {
      in_key_table = true;
      continue;
    }
    if (!in_key_table || line.rfind("|---", 0) == 0) continue;
    if (line.rfind("| ", 0) != 0) {
      in_key_table = false;
      continue;
    }
    const std::string first_cell = line.substr(2, line.find(" |", 1) - 2);
    for (auto it = std::sregex_iterator(first_cell.begin(), first_cell.end(), key); it != std::sregex_iterator(); ++it)
      out[section].insert((*it)[1]);
  }
  return out;
}

}  // namespace

TEST(CaseFileDocs, EveryKeyTableListsExactlyTheKeysTheReaderAccepts) {
  const std::map<std::string, KeySet> documented = documented_keys();
  // The sections documented by a key table; [[forcing]], [[elements]] and [[outputs]] are
  // documented in prose (their keys depend on the shape or element type).
  for (const char* section :
       {"model", "rotation", "damping", "forcing_growth", "base_motion", "harmonic_balance", "continuation", "stability", "study"}) {
    ASSERT_TRUE(documented.count(section)) << "docs/case-file.md has no key table for [" << section << "]";
    EXPECT_EQ(documented.at(section), accepted_keys(section)) << "[" << section << "]";
  }
  EXPECT_EQ(documented.size(), 9u) << "a new key table: add its section above";
}

}  // namespace hbtrack_tests::file_case_file_docs
