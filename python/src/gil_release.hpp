#pragma once
// Computations run with the GIL released, so that other Python threads go on. A thread that
// comes back to Python while the interpreter exits (a daemon thread) is ended by CPython with
// pthread_exit, whose forced unwinding through a noexcept C++ frame aborts the whole process
// ("terminate called without an active exception", exit 134). So such a thread never asks for
// the GIL again: it stops its computation and waits for the process to end.
#include <Python.h>

namespace hbtrack::python {

// True once the interpreter has begun to exit; callable without the GIL.
bool interpreter_exiting();

// Releases the GIL for its scope, and takes it back at the end unless the interpreter is
// exiting: then the thread blocks until the process ends.
class GilRelease {
 public:
  GilRelease();
  ~GilRelease() noexcept(false);  // taking the GIL back may end the thread (a forced unwind)
  GilRelease(const GilRelease&) = delete;
  GilRelease& operator=(const GilRelease&) = delete;

 private:
  PyThreadState* state_;
};

}  // namespace hbtrack::python
