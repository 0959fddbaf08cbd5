#pragma once
// Runs the hbtrack executable as a user would, for the command-line tests.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <random>
#include <nlohmann/json.hpp>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace hbtrack::test {

// A folder for one test's results, per process (ctest runs tests in parallel processes): absent,
// or created empty.
inline std::filesystem::path fresh_temp_dir(const std::string& name, bool create = false) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / (name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  if (create) std::filesystem::create_directories(dir);
  return dir;
}

// A fixture whose tests write into a folder of their own, created before each test and removed
// after it; random in name, so that tests of one process and of parallel processes never meet.
class ScratchFolderTest : public ::testing::Test {
 protected:
  explicit ScratchFolderTest(std::string prefix) : prefix_(std::move(prefix)) {}
  void SetUp() override {
    std::random_device entropy;
    dir_ = std::filesystem::temp_directory_path() / (prefix_ + "_" + std::to_string(entropy()) + std::to_string(entropy()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string prefix_;
  std::filesystem::path dir_;
};

// A result folder's JSON file (summary.json, a checkpoint), parsed.
inline nlohmann::json read_json(const std::filesystem::path& p) { return nlohmann::json::parse(std::ifstream(p)); }

struct CliRun {
  int exit_code;
  std::string err;  // everything the command wrote to stderr
};

// `hbtrack ARGS` with stdout discarded. One stderr file per call and process: ctest runs the
// tests in parallel processes.
inline CliRun run_cli(const std::string& args) {
  static int calls = 0;
  const std::filesystem::path err =
      std::filesystem::temp_directory_path() / ("hbtrack_cli_stderr_" + std::to_string(getpid()) + "_" + std::to_string(calls++) + ".txt");
  // Appended, not one chain of +: GCC 12 at -O1 reports a false -Warray-bounds on the chain where
  // it inlines this function (a test file that calls it once or twice).
  std::string cmd = HBTRACK_CLI;
  cmd += ' ';
  cmd += args;
  cmd += " 2> " + err.string() + " > /dev/null";
  const int status = std::system(cmd.c_str());
  std::stringstream ss;
  ss << std::ifstream(err).rdbuf();
  std::error_code ignored;
  std::filesystem::remove(err, ignored);
  return {WEXITSTATUS(status), ss.str()};
}

// `hbtrack ARGS...` started in the background (output discarded, or stderr into `err_file`), for
// tests that signal it. In its own process group when asked, so that the test can signal it with
// its children.
inline pid_t spawn_cli(const std::vector<std::string>& args, bool own_process_group = false, const std::string& err_file = "/dev/null") {
  std::vector<std::string> argv_storage{HBTRACK_CLI};
  argv_storage.insert(argv_storage.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_storage) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  if (own_process_group) {
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&attributes, 0);
  }
  pid_t pid = -1;
  if (posix_spawn(&pid, argv[0], &actions, &attributes, argv.data(), environ) != 0) pid = -1;
  posix_spawnattr_destroy(&attributes);
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

// The exit code of a spawned run (waits for it); -1 when it did not exit normally.
inline int wait_for_exit(pid_t pid) {
  int status = 0;
  if (waitpid(pid, &status, 0) != pid || !WIFEXITED(status)) return -1;
  return WEXITSTATUS(status);
}

// Lines of a text file (0 when it does not exist).
inline int count_lines(const std::filesystem::path& p) {
  std::ifstream in(p);
  int n = 0;
  for (std::string line; std::getline(in, line);) ++n;
  return n;
}

// A whole file as a string, for byte-for-byte comparisons.
inline std::string file_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The column names of a CSV file's header line.
inline std::vector<std::string> csv_header(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::string line, cell;
  std::getline(in, line);
  std::vector<std::string> cells;
  std::stringstream ss(line);
  while (std::getline(ss, cell, ',')) cells.push_back(cell);
  return cells;
}

// The data rows of a numeric CSV file, each as {column name: value}.
inline std::vector<std::map<std::string, double>> csv_records(const std::filesystem::path& p) {
  const std::vector<std::string> header = csv_header(p);
  std::ifstream in(p);
  std::string line, cell;
  std::getline(in, line);
  std::vector<std::map<std::string, double>> rows;
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::map<std::string, double> row;
    for (size_t c = 0; c < header.size() && std::getline(ss, cell, ','); ++c) row[header[c]] = std::stod(cell);
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace hbtrack::test
