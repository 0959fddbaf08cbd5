#pragma once
// What every hbtrack verb shares: registration, the uniform failure types, result-folder rows
// and the progress line (progress.hpp).
#include <CLI/CLI.hpp>
#include <chrono>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/results/result_tables.hpp"  // options_json, branch rows: shared with the Python module
#include "hbtrack/runs/case_system.hpp"
#include "interruption.hpp"
#include "progress.hpp"

namespace hbtrack::cli {

// Wall-clock timings for summary.json.
using Clock = std::chrono::steady_clock;
inline double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// A verb: its CLI11 sub-command and what runs when it was chosen (returns the exit code).
struct Verb {
  CLI::App* command;
  std::function<int()> run;
};
using VerbList = std::vector<Verb>;

// Failures of the run itself (results written, reason on stderr): exit code 1. Bad input is
// reported by throwing hbtrack::CaseError: exit code 2.
struct RunFailed {
  std::string reason;
  std::string next_step{};  // a line of its own after the reason: how to go on (resume_command.hpp)
};

// Options every analysis verb takes: CASE, -o DIR, --set NAME=VALUE..., -q, --progress-file.
struct CommonOptions {
  std::string case_path;
  std::string out_dir;
  std::vector<std::string> sets;
  bool quiet = false;
  std::string progress_file;  // where the progress goes as lines too (Progress::relay_to), "" for nowhere
};
void add_common_options(CLI::App* command, CommonOptions& options);

// --jobs N: independent tasks side by side on this machine (task_runner.hpp); `what` names them.
void add_jobs_option(CLI::App* command, int& jobs, const std::string& what);

// A number as text with `significant` digits (printf %g): 17 give the double back exactly, 10 or
// 12 read better in tables and command lines.
std::string number_text(double v, int significant = 10);

// The case's system, as every run builds it.
using runs::make_system;

// Verbs register themselves, one file each: `const VerbRegistrar registrar(add_my_verbs);`
// at namespace scope in the verb's file adds its sub-commands to the tool.
using VerbFactory = void (*)(CLI::App& app, VerbList& verbs);
std::vector<VerbFactory>& verb_factories();
struct VerbRegistrar {
  explicit VerbRegistrar(VerbFactory factory) { verb_factories().push_back(factory); }
};

}  // namespace hbtrack::cli
