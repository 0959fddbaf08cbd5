#pragma once
// Runs other hbtrack verbs as child processes of this one (the study's steps): each step is the
// command a user could type, writes its own result folder, and a crash or a stop in one step
// cannot take the others' results with it. Independent steps run side by side.
#include <functional>
#include <string>
#include <vector>

namespace hbtrack::cli {

// One child: `program ARGS...` with stdout and stderr appended to `log_path`.
struct ChildTask {
  std::string program;
  std::vector<std::string> args;
  std::string log_path;
};

// `hbtrack ARGS...` (this same executable) and `/usr/bin/python3 python/SCRIPT ARGS...`.
ChildTask hbtrack_task(const std::vector<std::string>& args, const std::string& log_path);
ChildTask python_script_task(const std::string& script, const std::vector<std::string>& args, const std::string& log_path);

// Runs the tasks with at most `workers` at a time and returns each one's exit code (128 + N
// when signal N ended it, -1 when it could not be started). `finished(index, code, seconds)` is
// called as each one ends, in the order they end.
using TaskFinished = std::function<void(size_t index, int exit_code, double seconds)>;
std::vector<int> run_tasks(const std::vector<ChildTask>& tasks, int workers, const TaskFinished& finished = {});

}  // namespace hbtrack::cli
