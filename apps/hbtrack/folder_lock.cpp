#include "folder_lock.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <set>
#include <stdexcept>

#include "hbtrack/io/case_file.hpp"

namespace hbtrack::cli {

namespace {

std::string lock_path(const std::string& dir) { return dir + "/.hbtrack.lock"; }

// Open-file-description locks (Linux): held by the open file, not the process, so no other
// open/close of the file in this process releases them, and they are not inherited by children.
struct flock whole_file(short type) {
  struct flock l {};
  l.l_type = type;
  l.l_whence = SEEK_SET;
  return l;
}

long pid_in(int fd) {
  char text[32] = {};
  const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
  if (n <= 0) return -1;
  char* end = nullptr;
  const long pid = std::strtol(text, &end, 10);
  return end != text && pid > 0 ? pid : -1;
}

}  // namespace

void lock_result_folder(const std::string& dir) {
  static std::set<std::string> held;  // the descriptors stay open until the process ends
  std::error_code ec;
  const std::string key = std::filesystem::weakly_canonical(dir, ec).string();
  if (held.count(key)) return;
  const std::string path = lock_path(dir);
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error(path + ": cannot open for writing: " + std::strerror(errno));
  struct flock l = whole_file(F_WRLCK);
  if (::fcntl(fd, F_OFD_SETLK, &l) != 0) {
    const int error = errno;
    const long owner = pid_in(fd);
    ::close(fd);
    // A file system without record locks (some network or FUSE mounts): run unguarded, as before.
    if (error != EAGAIN && error != EACCES) return;
    throw CaseError("-o: " + dir + " is being written by another hbtrack run" + (owner > 0 ? " (pid " + std::to_string(owner) + ")" : "") +
                    "; wait for it to end or stop it");
  }
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size()))
    throw std::runtime_error(path + ": cannot write: " + std::strerror(errno));
  held.insert(key);
}

long result_folder_owner(const std::string& dir) {
  const int fd = ::open(lock_path(dir).c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return 0;
  struct flock l = whole_file(F_WRLCK);
  long owner = 0;
  if (::fcntl(fd, F_OFD_GETLK, &l) == 0 && l.l_type != F_UNLCK) owner = pid_in(fd);
  ::close(fd);
  return owner;
}

}  // namespace hbtrack::cli
