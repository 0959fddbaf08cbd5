// The fuzzers' corpora (fuzz/corpus/TARGET, minimized from clean 10-minute runs) and seeds
// (fuzz/seeds/TARGET, with every past finding as regression-*) replayed through the readers the
// fuzz targets call (fuzz/fuzz_*.cpp): each input loads or is refused with a one-line
// std::runtime_error, and the sanitizer pass of the suite runs them under ASan + UBSan. A change
// to a reader that breaks an input the fuzzers once explored shows here, not only when someone
// fuzzes again.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "hbtrack/io/blade_sections_reader.hpp"
#include "hbtrack/io/calculix_input_nodes.hpp"
#include "hbtrack/io/calculix_reader.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/io/mat_file.hpp"
#include "hbtrack/io/matrix_market.hpp"
#include "hbtrack/model/section_blade.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_fuzz_corpora {

namespace fs = std::filesystem;

namespace {

using Reader = std::function<void(const std::string& path)>;

// Every file of fuzz/corpus/TARGET and fuzz/seeds/TARGET, copied to a file with the suffix the
// fuzz target gives its input, and read by each reader. Returns the number of inputs.
int replay(const std::string& target, const std::string& suffix, const std::vector<Reader>& readers) {
  const fs::path copy = fs::temp_directory_path() / ("hbtrack_corpus_" + std::to_string(::getpid()) + "_" + target + suffix);
  int inputs = 0;
  for (const std::string folder : {"fuzz/corpus/", "fuzz/seeds/"}) {
    const fs::path dir = hbtrack::test::source_path(folder + target);
    if (!fs::is_directory(dir)) continue;
    for (const auto& entry : fs::directory_iterator(dir)) {
      if (!entry.is_regular_file()) continue;
      fs::copy_file(entry.path(), copy, fs::copy_options::overwrite_existing);
      ++inputs;
      for (const Reader& read : readers) {
        try {
          read(copy.string());
        } catch (const std::runtime_error& e) {
          const std::string message = e.what();
          EXPECT_EQ(message.find('\n'), std::string::npos) << entry.path() << ": " << message;
          EXPECT_FALSE(message.empty()) << entry.path();
        }
        // Any other exception escapes: the test fails naming it (gtest catches it).
      }
    }
  }
  fs::remove(copy);
  return inputs;
}

}  // namespace

TEST(FuzzCorpora, CaseFileInputsLoadOrGiveOneLineErrors) {
  const int n = replay("case_file", ".toml", {[](const std::string& p) { hbtrack::load_case(p); }});
  EXPECT_GT(n, 100);
}

TEST(FuzzCorpora, MatrixMarketInputsLoadOrGiveOneLineErrors) {
  const int n = replay(
      "matrix_market", ".mtx",
      {[](const std::string& p) { hbtrack::read_matrix_market_sparse(p); }, [](const std::string& p) { hbtrack::read_matrix_market(p); }});
  EXPECT_GE(n, 5);
}

TEST(FuzzCorpora, MatFileInputsLoadOrGiveOneLineErrors) {
  const int n = replay("mat_file", ".mat",
                       {[](const std::string& p) { hbtrack::read_mat_variable_sparse(p, "K"); },
                        [](const std::string& p) { hbtrack::read_mat_variable(p, "K"); }});
  EXPECT_GE(n, 8);
}

TEST(FuzzCorpora, CalculixInputsLoadOrGiveOneLineErrors) {
  const int n = replay(
      "calculix", ".sti",
      {[](const std::string& p) { hbtrack::read_calculix_matrix(p); }, [](const std::string& p) { hbtrack::read_calculix_dof_map(p); },
       [](const std::string& p) { hbtrack::read_calculix_input_nodes(p); }});
  EXPECT_GE(n, 3);
}

// As fuzz_sections.cpp and make-blade: the table, then the blade built from it, whose geometry
// checks refuse with std::invalid_argument (make-blade's bad input, one line too).
TEST(FuzzCorpora, SectionTablesLoadOrGiveOneLineErrors) {
  const int n = replay("sections", ".csv", {[](const std::string& p) {
                         const hbtrack::BladeSections sections = hbtrack::read_blade_sections(p);
                         try {
                           hbtrack::generate_section_blade(sections, hbtrack::SectionBladeOptions{});
                         } catch (const std::invalid_argument& e) {
                           throw std::runtime_error(e.what());
                         }
                       }});
  EXPECT_GE(n, 10);
}

// The seeds meant to load still do, so the fuzzers start inside the readers' accepting paths:
// the templates expand (several nodes, per_node lists), the cut-down rotor 67 tables mesh.
TEST(FuzzCorpora, TheValidSeedsLoad) {
  const auto seed = [](const std::string& name) { return hbtrack::test::source_path("fuzz/seeds/" + name); };
  EXPECT_EQ(hbtrack::load_case(seed("case_file/templates_tip_contact.toml")).elements.size(), 4u);
  EXPECT_EQ(hbtrack::load_case(seed("case_file/templates_many_nodes.toml")).elements.size(), 10u);
  for (const char* table : {"rotor67_hub_casing.csv", "rotor67_three_surfaces.csv", "rotor67_four_points.csv", "subnormal_thickness.csv"}) {
    const hbtrack::SectionBlade blade = hbtrack::generate_section_blade(
        hbtrack::read_blade_sections(seed(std::string("sections/") + table)), hbtrack::SectionBladeOptions{});
    EXPECT_EQ(blade.rotation.sense, -1) << table;
  }
}

}  // namespace hbtrack_tests::file_fuzz_corpora
