#include "child_process.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <map>

extern char** environ;

namespace hbtrack::cli {

namespace {

// Starts one task; its pid, or -1.
pid_t spawn(const ChildTask& task) {
  std::vector<std::string> words{task.program};
  words.insert(words.end(), task.args.begin(), task.args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, task.log_path.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  posix_spawn_file_actions_adddup2(&files, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, task.program.c_str(), &files, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  return spawned == 0 ? pid : -1;
}

int exit_code(int status) {
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

}  // namespace

ChildTask hbtrack_task(const std::vector<std::string>& args, const std::string& log_path) {
  // The binary that is running, wherever it was installed or called from.
  return {"/proc/self/exe", args, log_path};
}

ChildTask python_script_task(const std::string& script, const std::vector<std::string>& args, const std::string& log_path) {
  // Debian's interpreter: the one whose numpy and matplotlib the install script provides.
  std::vector<std::string> words{std::string(HBTRACK_PYTHON_DIR) + "/" + script};
  words.insert(words.end(), args.begin(), args.end());
  return {"/usr/bin/python3", words, log_path};
}

std::vector<int> run_tasks(const std::vector<ChildTask>& tasks, int workers, const TaskFinished& finished) {
  using Clock = std::chrono::steady_clock;
  std::vector<int> codes(tasks.size(), -1);
  std::map<pid_t, std::pair<size_t, Clock::time_point>> running;
  size_t next = 0;
  while (next < tasks.size() || !running.empty()) {
    while (next < tasks.size() && static_cast<int>(running.size()) < std::max(workers, 1)) {
      const pid_t pid = spawn(tasks[next]);
      if (pid < 0) {
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
      if (errno == EINTR) continue;  // a signal to the study: the children got it too and stop
      break;
    }
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    const size_t index = it->second.first;
    codes[index] = exit_code(status);
    if (finished) finished(index, codes[index], std::chrono::duration<double>(Clock::now() - it->second.second).count());
    running.erase(it);
  }
  return codes;
}

}  // namespace hbtrack::cli
