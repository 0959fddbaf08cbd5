// hbtrack: command-line front end. Each analysis verb reads a case file, writes its results into
// the folder given with -o (contracts of the project's design notes) and exits non-zero with a one-line reason on
// stderr when it fails: 1 when the run failed (results kept), 2 for bad input, 3 otherwise.
#include <algorithm>
#include <csignal>
#include <cstdio>

#include "cli_common.hpp"
#include "resume_command.hpp"

namespace hbtrack::cli {
void on_signal(int);
}

int main(int argc, char** argv) {
  using namespace hbtrack::cli;
  CLI::App app{"hbtrack: nonlinear forced response of structures with contact and friction by harmonic balance"};
  app.require_subcommand(1);
  remember_command_line(argc, argv);
  VerbList verbs;
  for (VerbFactory add_verbs : verb_factories()) add_verbs(app, verbs);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    // Bad flags are bad input: one line and exit 2, like every other input error.
    std::string reason = e.what();
    std::replace(reason.begin(), reason.end(), '\n', ' ');
    std::fprintf(stderr, "hbtrack: %s (see hbtrack --help)\n", reason.c_str());
    return 2;
  }
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  // A file-size limit (ulimit -f) kills with SIGXFSZ by default (exit 153, a temporary file left
  // behind); ignored, the write fails with EFBIG and the checked writes report it: exit 3.
  std::signal(SIGXFSZ, SIG_IGN);
  try {
    for (const Verb& v : verbs)
      if (v.command->parsed()) return v.run();
  } catch (const RunFailed& e) {
    std::fprintf(stderr, "hbtrack: %s\n", e.reason.c_str());
    if (!e.next_step.empty()) std::fprintf(stderr, "%s\n", e.next_step.c_str());
    return 1;
  } catch (const hbtrack::CaseError& e) {
    std::fprintf(stderr, "hbtrack: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hbtrack: %s\n", e.what());
    return 3;
  }
  return 0;
}
