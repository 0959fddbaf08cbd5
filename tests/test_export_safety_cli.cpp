// `hbtrack export` writes its file whole or not at all, never over the folder's own files, and
// reads the folder's summary.json bounded (issue 39).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

#include "cli_support.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_export_safety_cli {

namespace fs = std::filesystem;

using hbtrack::test::CliRun;
using hbtrack::test::file_bytes;
using hbtrack::test::run_cli;

namespace {

// One Duffing result folder for the tests of this file (about 50 points: results.mat ~ 30 KB).
const fs::path& duffing_folder() {
  static const fs::path dir = [] {
    const fs::path d = hbtrack::test::fresh_temp_dir("hbtrack_export_safety_frc");
    EXPECT_EQ(run_cli("frc " + hbtrack::test::source_path("examples/duffing.toml") + " -q -o " + d.string()).exit_code, 0);
    return d;
  }();
  return dir;
}

// `hbtrack ARGS` under `ulimit -f BLOCKS` (512-byte blocks): a full disk. The exit code, or 128 +
// the signal that killed it.
CliRun run_with_file_size_limit(int blocks, const std::string& args) {
  const fs::path err = hbtrack::test::fresh_temp_dir("hbtrack_export_safety_err");
  const std::string command = "sh -c \"ulimit -f " + std::to_string(blocks) + "; exec " + std::string(HBTRACK_CLI) + " " + args + "\" 2> " +
                              err.string() + " > /dev/null";
  const int status = std::system(command.c_str());
  std::stringstream text;
  text << std::ifstream(err).rdbuf();
  fs::remove(err);
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return {code, text.str()};
}

}  // namespace

// Under a file-size limit the .mat export wrote a truncated file and said it succeeded (libmatio
// does not check its writes); the HDF5 export reported the failure, then segfaulted in HDF5's exit
// handler (exit 139). Both now exit 3 in one line and leave no file.
TEST(ExportSafety, AFileSizeLimitGivesExit3AndNoFile) {
  const fs::path dir = duffing_folder();
  for (const std::string format : {"mat", "h5"}) {
    const fs::path out = dir / ("limited." + format);
    const CliRun r = run_with_file_size_limit(8, "export " + dir.string() + " -q --format " + format + " -o " + out.string());
    EXPECT_EQ(r.exit_code, 3) << format << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(out)) << format << ": a partial file was left";
    for (const auto& entry : fs::directory_iterator(dir))
      EXPECT_EQ(entry.path().string().find("limited." + format + "."), std::string::npos) << "scratch file left: " << entry.path();
  }
  // Without the limit the same export is whole.
  EXPECT_EQ(run_cli("export " + dir.string() + " -q -o " + (dir / "whole.mat").string()).exit_code, 0);
}

// `export DIR -o DIR/branch.csv` replaced the branch with a .mat file, exit 0.
TEST(ExportSafety, TheFoldersOwnFilesAreNotReplaced) {
  const fs::path dir = duffing_folder();
  for (const char* own : {"branch.csv", "summary.json", ""}) {
    const fs::path target = dir / own;
    const std::string before = fs::is_regular_file(target) ? file_bytes(target) : "";
    const CliRun r = run_cli("export " + dir.string() + " -q -o " + target.string());
    EXPECT_EQ(r.exit_code, 2) << own << ": " << r.err;
    EXPECT_NE(r.err.find("whose own files it would replace"), std::string::npos) << r.err;
    if (!before.empty()) {
      EXPECT_EQ(file_bytes(target), before) << own << " was changed";
    }
  }
}

// A summary.json nested 100 000 deep segfaulted export (both formats); a malformed one gave the
// JSON library's message. Both are one line naming the file, exit 2.
TEST(ExportSafety, ADeeplyNestedOrMalformedSummaryIsBadInput) {
  const fs::path dir = hbtrack::test::fresh_temp_dir("hbtrack_export_safety_deep", true);
  {
    std::ofstream out(dir / "summary.json");
    out << "{\"verb\": \"frc\", \"x\": " << std::string(100000, '[') << std::string(100000, ']') << "}";
  }
  for (const char* format : {"mat", "h5"}) {
    const CliRun r = run_cli("export " + dir.string() + " -q --format " + std::string(format));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find((dir / "summary.json").string() + ":1: arrays or objects nested deeper than 64 levels"), std::string::npos)
        << r.err;
  }
  std::ofstream(dir / "summary.json") << "{\"verb\": \"frc\", \"points\": 3,, }";
  const CliRun r = run_cli("export " + dir.string() + " -q");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("summary.json: not valid JSON (parse error at line 1, column 29"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("json.exception"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

// A summary.json that is valid JSON but no object (an array, a number, a string, null) was
// exported as if it were a result, exit 0 (issue 39's hostile rerun); `track --from` read it by key.
TEST(ExportSafety, ASummaryThatIsNotAnObjectIsBadInput) {
  const fs::path dir = hbtrack::test::fresh_temp_dir("hbtrack_export_safety_not_an_object", true);
  const std::string duffing = hbtrack::test::source_path("examples/duffing.toml");
  for (const std::string text : {"[]", "1", "\"frc\"", "null"}) {
    std::ofstream(dir / "summary.json") << text;
    for (const std::string format : {"mat", "h5"}) {
      const CliRun r = run_cli("export " + dir.string() + " -q --format " + format);
      EXPECT_EQ(r.exit_code, 2) << text << ": " << r.err;
      EXPECT_NE(r.err.find((dir / "summary.json").string() + ": not a result summary of hbtrack (a JSON object expected"),
                std::string::npos)
          << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
      EXPECT_FALSE(fs::exists(dir / ("results." + format))) << text;
    }
    const CliRun track = run_cli("track " + duffing + " -q --from " + dir.string() + " --lp 1 --param amplitude --range 0.1:2 -o " +
                                 (dir / "track").string());
    EXPECT_EQ(track.exit_code, 2) << text << ": " << track.err;
    EXPECT_EQ(std::count(track.err.begin(), track.err.end(), '\n'), 1) << track.err;
    EXPECT_FALSE(fs::exists(dir / "track"));
  }
}

// A sweep folder: export read sweep.csv's text column `status` as a number and stopped at its first
// cell ("'max_points' is not a finite number"). Now one line says why, names the task folders
// that export does take, and nothing is written; a task's folder exports.
TEST(ExportSafety, ASweepFolderIsRefusedInOneLineNamingItsTaskFolders) {
  const fs::path dir = hbtrack::test::fresh_temp_dir("hbtrack_export_safety_sweep");
  const std::string duffing = hbtrack::test::source_path("examples/duffing.toml");
  ASSERT_EQ(run_cli("sweep " + duffing + " -q --set continuation.max_points=4 --param amplitude --values 1,2 --jobs 1 -o " + dir.string())
                .exit_code,
            0);
  for (const char* format : {"mat", "h5"}) {
    const CliRun r = run_cli("export " + dir.string() + " -q --format " + std::string(format));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find((dir / "sweep.csv").string() + ": a sweep's table, with text columns (status)"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("export a task's folder (" + dir.string() + "/tasks/NNNN)"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(dir / ("results." + std::string(format))));
  }
  EXPECT_EQ(run_cli("export " + (dir / "tasks" / "0001").string() + " -q").exit_code, 0);
  EXPECT_TRUE(fs::exists(dir / "tasks" / "0001" / "results.mat"));
}

}  // namespace hbtrack_tests::file_export_safety_cli
