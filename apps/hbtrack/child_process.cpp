#include "child_process.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>

extern char** environ;

namespace hbtrack::cli {

ChildTask hbtrack_task(const std::vector<std::string>& args, const std::string& log_path) {
  // The binary that is running, wherever it was installed or called from.
  return {"/proc/self/exe", args, log_path};
}

pid_t start_child(const ChildTask& task) {
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

int child_exit_code(int wait_status) {
  if (WIFEXITED(wait_status)) return WEXITSTATUS(wait_status);
  if (WIFSIGNALED(wait_status)) return 128 + WTERMSIG(wait_status);
  return -1;
}

int run_child(const ChildTask& task) {
  const pid_t pid = start_child(task);
  if (pid < 0) return -1;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;  // a signal to this process: the child got it too, wait for it
  return child_exit_code(status);
}

std::string child_error_line(const std::string& log_path) {
  const std::string prefix = "hbtrack: ";
  std::ifstream log(log_path);
  std::string line, last;
  while (std::getline(log, line))
    if (line.rfind(prefix, 0) == 0) last = line.substr(prefix.size());
  return last;
}

}  // namespace hbtrack::cli
