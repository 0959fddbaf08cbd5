#pragma once
// The command that goes on with a stopped run, printed when Ctrl-C, SIGTERM or --time-limit stop
// a resumable verb (frc, track, sweep, study): the command line as the user typed it, so that it
// keeps their --set, --only and paths.
#include <string>

namespace hbtrack::cli {

// Kept from main() for the messages below.
void remember_command_line(int argc, const char* const* argv);

// The typed command, each argument quoted for a POSIX shell where it needs it.
std::string typed_command();

// The typed command with -o/--output DIR and --resume DIR dropped and `--resume DIR` appended.
std::string resume_command(const std::string& dir);

// "REASON: resume with: COMMAND" for a stop a rerun goes past (interrupted, time_limit); "" for
// any other reason, which a rerun would meet again.
std::string resume_advice(const std::string& stop_reason, const std::string& command);

// A word as a POSIX shell reads it back: as is when it is plain, else in single quotes.
std::string shell_quoted(const std::string& word);

}  // namespace hbtrack::cli
