#pragma once
// Runs the hbtrack executable as a user would, for the command-line tests.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace hbtrack::test {

struct CliRun {
  int exit_code;
  std::string err;  // everything the command wrote to stderr
};

// `hbtrack ARGS` with stdout discarded. One stderr file per call and process: ctest runs the
// tests in parallel processes.
inline CliRun run_cli(const std::string& args) {
  static int calls = 0;
  const std::filesystem::path err = std::filesystem::temp_directory_path() /
                                    ("hbtrack_cli_stderr_" + std::to_string(getpid()) + "_" + std::to_string(calls++) + ".txt");
  const std::string cmd = std::string(HBTRACK_CLI) + " " + args + " 2> " + err.string() + " > /dev/null";
  const int status = std::system(cmd.c_str());
  std::stringstream ss;
  ss << std::ifstream(err).rdbuf();
  std::error_code ignored;
  std::filesystem::remove(err, ignored);
  return {WEXITSTATUS(status), ss.str()};
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

}  // namespace hbtrack::test
