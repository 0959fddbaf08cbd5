#pragma once
// Debian's single-threaded OpenBLAS (libopenblas-serial) is not safe to call from several threads
// at once: its buffer allocation races. Python users run NFRCs side by side in threads
// (examples/python/sweep_threads.py), where concurrent dgemm/dgetrf calls gave slightly different
// branches 1 run in 3 (python/tests/test_sweep.py). Every OpenBLAS call takes this lock.
#include <mutex>

namespace hbtrack {

inline std::mutex& openblas_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace hbtrack
