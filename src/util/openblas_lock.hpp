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

#ifdef HBTRACK_OPENBLAS
extern "C" void openblas_set_num_threads(int threads);

// The target is one core: a threaded OpenBLAS would also compete with the caller's threads. Set
// once, before a kernel's first call.
inline void use_one_openblas_thread() {
  static const bool set = (openblas_set_num_threads(1), true);
  (void)set;
}
#endif

}  // namespace hbtrack
