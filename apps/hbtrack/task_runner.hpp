#pragma once
// Where the independent tasks of a verb run (the study's steps, the sweep's tasks). Every task is
// a child process (child_process.hpp) writing its own folder, so the runner only hands out
// commands and collects exit codes: up to --jobs at a time on this machine, or, under mpirun,
// one at a time on every rank, handed out by rank 0 as ranks become free.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "child_process.hpp"

namespace hbtrack::cli {

// Called on the coordinating process as each task ends, in the order they end.
using TaskFinished = std::function<void(size_t index, int exit_code, double seconds)>;

// Exit code of a task that was never started: the run was interrupted (SIGINT/SIGTERM) first.
constexpr int kTaskNotStarted = -2;

class TaskRunner {
 public:
  virtual ~TaskRunner() = default;
  // Runs every task and returns each one's exit code (128 + N when signal N ended it, -1 when it
  // could not be started, kTaskNotStarted after an interruption).
  virtual std::vector<int> run(const std::vector<ChildTask>& tasks, const TaskFinished& finished = {}) = 0;
  virtual int slots() const = 0;                // tasks running at once
  virtual std::string description() const = 0;  // "2 local workers", "3 MPI ranks"
};

// Up to `jobs` children at a time on this machine (0: one per core).
std::unique_ptr<TaskRunner> make_local_runner(int jobs);

// The runner of this process. Started by mpirun (and built with MPI): rank 0 gets a runner that
// spreads the tasks over all ranks, and every other rank serves tasks inside this call until
// rank 0's runner is destroyed, then gets nullptr: its verb has nothing more to do. Otherwise a
// local runner with `jobs` workers.
std::unique_ptr<TaskRunner> start_task_runner(int jobs);

}  // namespace hbtrack::cli
