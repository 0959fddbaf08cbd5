// hbtrack: command-line front end. Each analysis verb reads a case file, writes its results into
// the folder given with -o (contracts of the project's design notes) and exits non-zero with a one-line reason on
// stderr when it fails: 1 when the run failed (results kept), 2 for bad input, 3 otherwise.
#include <algorithm>
#include <csignal>
#include <cstdio>
#include <string>

#include "cli_common.hpp"
#include "resume_command.hpp"

namespace hbtrack::cli {
void on_signal(int);
}

namespace {
// A reason quotes what the user wrote (a dof name, a --set value), which may hold a newline or
// another control character: escaped, the reason stays one line (a dof name "a\nb" in an
// element gave a two-line "unknown dof", issue 39's hostile rerun).
std::string one_line(const std::string& reason) {
  std::string line;
  for (const char c : reason) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n') {
      line += "\\n";
    } else if (c == '\t') {
      line += "\\t";
    } else if (byte < 0x20 || byte == 0x7f) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
      line += escaped;
    } else {
      line += c;
    }
  }
  return line;
}
}  // namespace

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
    std::fprintf(stderr, "hbtrack: %s\n", one_line(e.reason).c_str());
    if (!e.next_step.empty()) std::fprintf(stderr, "%s\n", e.next_step.c_str());
    return 1;
  } catch (const hbtrack::CaseError& e) {
    std::fprintf(stderr, "hbtrack: %s\n", one_line(e.what()).c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hbtrack: %s\n", one_line(e.what()).c_str());
    return 3;
  }
  return 0;
}
