#pragma once
// Runs other hbtrack verbs as child processes of this one (the study's steps, the sweep's tasks):
// each step is the command a user could type, writes its own result folder, and a crash or a
// stop in one step cannot take the others' results with it. task_runner.hpp runs many.
#include <sys/types.h>

#include <string>
#include <vector>

namespace hbtrack::cli {

// One child: `program ARGS...` with stdout and stderr appended to `log_path`.
struct ChildTask {
  std::string program;
  std::vector<std::string> args;
  std::string log_path;
};

// `hbtrack ARGS...` (this same executable); python_package.hpp makes Python ones.
ChildTask hbtrack_task(const std::vector<std::string>& args, const std::string& log_path);

// Starts the child; its pid, or -1 when it could not be started.
pid_t start_child(const ChildTask& task);

// The exit code a waitpid status stands for: 128 + N when signal N ended the child.
int child_exit_code(int wait_status);

// Starts the child and waits for it: its exit code, -1 when it could not be started.
int run_child(const ChildTask& task);

// The one-line error an hbtrack child ended with: the last line of its log that starts with
// "hbtrack: ", without that prefix; "" when there is none.
std::string child_error_line(const std::string& log_path);

}  // namespace hbtrack::cli
