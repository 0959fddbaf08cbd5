#include "cli_common.hpp"

#include <csignal>
#include <cstdio>

namespace hbtrack::cli {

namespace {
volatile std::sig_atomic_t g_interrupted = 0;
}  // namespace

std::vector<VerbFactory>& verb_factories() {
  static std::vector<VerbFactory> factories;  // constructed on first use, before any registrar runs
  return factories;
}

void on_signal(int) { g_interrupted = 1; }
bool interrupted() { return g_interrupted != 0; }

void add_common_options(CLI::App* command, CommonOptions& o) {
  command->add_option("case", o.case_path, "case file (TOML)")->required();
  command->add_option("-o,--output", o.out_dir, "output folder (created if missing)")->required();
  command->add_option("--set", o.sets, "override NAME=VALUE: a named parameter or a dotted case key")->take_all();
  command->add_flag("-q,--quiet", o.quiet, "no progress line or closing report");
  command
      ->add_option("--progress-file", o.progress_file,
                   "append the progress (point, fraction of the range, seconds) to FILE as lines, even with -q (how `hbtrack study` shows "
                   "its steps')")
      ->type_name("FILE");
}

void add_jobs_option(CLI::App* command, int& jobs, const std::string& what) {
  const CLI::Validator non_negative(
      [](std::string& text) { return text.find_first_not_of("0123456789") == std::string::npos ? "" : "must be >= 0 (0: one per core)"; },
      "");
  command->add_option("--jobs", jobs, what + " side by side on this machine (0: one per core; under mpirun: one per rank)")
      ->type_name("INT")
      ->capture_default_str()
      ->check(non_negative);
}

std::string number_text(double v, int significant) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", significant, v);
  return buf;
}

}  // namespace hbtrack::cli
