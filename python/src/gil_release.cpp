#include "gil_release.hpp"

#include <unistd.h>

namespace hbtrack::python {

bool interpreter_exiting() {
#if PY_VERSION_HEX >= 0x030D0000
  return Py_IsFinalizing() != 0;
#else
  return _Py_IsFinalizing() != 0;
#endif
}

GilRelease::GilRelease() : state_(PyEval_SaveThread()) {}

GilRelease::~GilRelease() noexcept(false) {
  if (interpreter_exiting())
    for (;;) pause();  // the process is ending; exit() does not wait for this thread
  PyEval_RestoreThread(state_);
}

}  // namespace hbtrack::python
