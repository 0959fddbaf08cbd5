// Rank 0 coordinates and computes: between its own tasks it answers the other ranks, which ask
// for the next task by reporting the last one's result. Tasks are child processes (fork/exec
// from a rank is fine over the shm and tcp transports Open MPI uses on Debian), so a rank only
// waits: all MPI calls stay on the main thread, and waiting is polling with a short sleep rather
// than a blocking receive, which Open MPI implements by spinning on a core the tasks need.
#ifdef HBTRACK_MPI
#include "mpi_task_runner.hpp"

#include <mpi.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <map>
#include <thread>

#include "interruption.hpp"

namespace hbtrack::cli {

namespace {

enum Tag : int { kReady = 1, kResult = 2, kTask = 3, kRelease = 4 };

// How long an idle process sleeps between looks at its mailbox.
constexpr auto kPollInterval = std::chrono::milliseconds(1);

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Messages are '\0'-separated words.
std::string join_words(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& w : words) text.append(w).push_back('\0');
  return text;
}
std::vector<std::string> split_words(const std::string& text) {
  std::vector<std::string> words;
  for (size_t begin = 0; begin < text.size();) {
    const size_t end = text.find('\0', begin);
    words.push_back(text.substr(begin, end - begin));
    begin = end + 1;
  }
  return words;
}

void send_text(const std::string& text, int to, int tag) {
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, to, tag, MPI_COMM_WORLD);
}
std::string receive_text(const MPI_Status& probed) {
  int length = 0;
  MPI_Get_count(&probed, MPI_CHAR, &length);
  std::string text(static_cast<size_t>(length), '\0');
  MPI_Recv(text.data(), length, MPI_CHAR, probed.MPI_SOURCE, probed.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return text;
}
// A message waiting from `source`, or false.
bool message_waiting(int source, MPI_Status& status) {
  int flag = 0;
  MPI_Iprobe(source, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
  return flag != 0;
}

class MpiTaskRunner : public TaskRunner {
 public:
  explicit MpiTaskRunner(int size) : size_(size) {}
  ~MpiTaskRunner() override {
    // Every other rank reports once before it waits for work (kReady) and after each task.
    while (static_cast<int>(idle_.size()) < size_ - 1) {
      if (!collect_remote(nullptr, {})) std::this_thread::sleep_for(kPollInterval);
    }
    for (int rank : idle_) send_text("", rank, kRelease);
    MPI_Finalize();
  }

  std::vector<int> run(const std::vector<ChildTask>& tasks, const TaskFinished& finished) override {
    codes_.assign(tasks.size(), kTaskNotStarted);
    std::map<int, size_t> remote_running;  // rank -> task index
    pid_t local_pid = -1;
    size_t local_index = 0, next = 0;
    Clock::time_point local_start;
    for (;;) {
      bool progressed = false;
      // After SIGINT/SIGTERM no new task starts; the running ones got the signal too and stop.
      while (!interrupted() && next < tasks.size() && !idle_.empty()) {
        const int rank = idle_.back();
        idle_.pop_back();
        std::vector<std::string> words{std::to_string(next), tasks[next].program, tasks[next].log_path};
        words.insert(words.end(), tasks[next].args.begin(), tasks[next].args.end());
        send_text(join_words(words), rank, kTask);
        remote_running[rank] = next++;
      }
      if (!interrupted() && next < tasks.size() && local_pid < 0) {
        local_pid = start_child(tasks[next]);
        local_index = next++;
        local_start = Clock::now();
        if (local_pid < 0) report(local_index, -1, 0.0, finished);
        progressed = true;
      }
      if (local_pid >= 0) {
        int status = 0;
        if (waitpid(local_pid, &status, WNOHANG) == local_pid) {
          report(local_index, child_exit_code(status), seconds_since(local_start), finished);
          local_pid = -1;
          progressed = true;
        }
      }
      while (collect_remote(&remote_running, finished)) progressed = true;
      const bool nothing_left = next == tasks.size() || interrupted();
      if (nothing_left && local_pid < 0 && remote_running.empty()) break;
      if (!progressed) std::this_thread::sleep_for(kPollInterval);
    }
    return codes_;
  }
  int slots() const override { return size_; }
  std::string description() const override { return std::to_string(size_) + (size_ == 1 ? " MPI rank" : " MPI ranks"); }

 private:
  void report(size_t index, int code, double seconds, const TaskFinished& finished) {
    codes_[index] = code;
    if (finished) finished(index, code, seconds);
  }
  // Takes one message from another rank (a result, or ready for work); false when none waits.
  bool collect_remote(std::map<int, size_t>* running, const TaskFinished& finished) {
    MPI_Status status;
    if (!message_waiting(MPI_ANY_SOURCE, status)) return false;
    const std::string text = receive_text(status);
    if (status.MPI_TAG == kResult) {
      const std::vector<std::string> words = split_words(text);  // index, exit code, seconds
      report(std::stoul(words.at(0)), std::stoi(words.at(1)), std::stod(words.at(2)), finished);
      if (running) running->erase(status.MPI_SOURCE);
    }
    idle_.push_back(status.MPI_SOURCE);
    return true;
  }

  int size_;
  std::vector<int> idle_;  // ranks waiting for a task
  std::vector<int> codes_;
};

// The other ranks: run what rank 0 sends until it releases them.
void serve_tasks() {
  send_text("", 0, kReady);
  for (;;) {
    MPI_Status status;
    while (!message_waiting(0, status)) std::this_thread::sleep_for(kPollInterval);
    const std::string text = receive_text(status);
    if (status.MPI_TAG == kRelease) return;
    const std::vector<std::string> words = split_words(text);  // index, program, log path, args...
    const ChildTask task{words.at(1), std::vector<std::string>(words.begin() + 3, words.end()), words.at(2)};
    const auto t0 = Clock::now();
    const int code = run_child(task);
    send_text(join_words({words[0], std::to_string(code), std::to_string(seconds_since(t0))}), 0, kResult);
  }
}

}  // namespace

bool launched_by_mpi() {
  for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"})
    if (std::getenv(variable)) return true;
  return false;
}

std::unique_ptr<TaskRunner> start_mpi_task_runner() {
  MPI_Init(nullptr, nullptr);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (rank == 0) return std::make_unique<MpiTaskRunner>(size);
  serve_tasks();
  MPI_Finalize();
  return nullptr;
}

}  // namespace hbtrack::cli
#endif  // HBTRACK_MPI
