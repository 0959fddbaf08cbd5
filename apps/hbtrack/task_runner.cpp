#include "task_runner.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <map>
#include <thread>

#include "interruption.hpp"
#include "mpi_task_runner.hpp"

namespace hbtrack::cli {

namespace {

class LocalTaskRunner : public TaskRunner {
 public:
  explicit LocalTaskRunner(int jobs) : jobs_(jobs > 0 ? jobs : std::max(1, static_cast<int>(std::thread::hardware_concurrency()))) {}

  std::vector<int> run(const std::vector<ChildTask>& tasks, const TaskFinished& finished) override {
    std::vector<int> codes(tasks.size(), kTaskNotStarted);
    using Clock = std::chrono::steady_clock;
    std::map<pid_t, std::pair<size_t, Clock::time_point>> running;
    size_t next = 0;
    while (running.size() > 0 || (next < tasks.size() && !interrupted())) {
      // After SIGINT/SIGTERM no new task starts; the running ones got the signal too and stop.
      while (next < tasks.size() && static_cast<int>(running.size()) < jobs_ && !interrupted()) {
        const pid_t pid = start_child(tasks[next]);
        if (pid < 0) {
          codes[next] = -1;
          if (finished) finished(next, -1, 0.0);
        } else {
          running[pid] = {next, Clock::now()};
        }
        ++next;
      }
      if (running.empty()) continue;
      int status = 0;
      const pid_t pid = waitpid(-1, &status, 0);
      if (pid < 0) {
        if (errno == EINTR) continue;
        break;
      }
      const auto it = running.find(pid);
      if (it == running.end()) continue;
      const size_t index = it->second.first;
      codes[index] = child_exit_code(status);
      if (finished) finished(index, codes[index], std::chrono::duration<double>(Clock::now() - it->second.second).count());
      running.erase(it);
    }
    return codes;
  }
  int slots() const override { return jobs_; }
  std::string description() const override { return std::to_string(jobs_) + (jobs_ == 1 ? " local worker" : " local workers"); }

 private:
  int jobs_;
};

}  // namespace

std::unique_ptr<TaskRunner> make_local_runner(int jobs) { return std::make_unique<LocalTaskRunner>(jobs); }

std::unique_ptr<TaskRunner> start_task_runner(int jobs) {
#ifdef HBTRACK_MPI
  if (launched_by_mpi()) return start_mpi_task_runner();
#endif
  return make_local_runner(jobs);
}

}  // namespace hbtrack::cli
