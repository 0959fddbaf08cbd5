#pragma once
// The SIGINT/SIGTERM flag (cli_common.cpp sets it), alone in a light header: the task runners
// check it between tasks without the command-line headers.

namespace hbtrack::cli {

// Set by SIGINT/SIGTERM: long runs stop cleanly with stop_reason "interrupted".
bool interrupted();

}  // namespace hbtrack::cli
