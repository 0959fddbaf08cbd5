#pragma once
// Where the figures come from: `hbtrack plot` and the study's figures run modules of the Python
// package hbtrack (pure Python and matplotlib, no compiled part needed). An installed tool uses
// the package `cmake --install` put under its own prefix; a tool run from its build tree uses the
// source tree it was built from. The source tree is never used by an installed tool, so a
// prefix copied or moved elsewhere keeps drawing with its own package.
#include <string>
#include <vector>

#include "child_process.hpp"

namespace hbtrack::cli {

// The folder that holds the package (…/site-packages, whose hbtrack/ it is), or "" when
// neither the install nor the build tree has one beside the running executable.
std::string python_package_dir();

// `python3 -m MODULE ARGS...` with that folder first on PYTHONPATH (set in this process's
// environment, which the child inherits) and matplotlib's non-interactive backend unless one is
// chosen. HBTRACK_PYTHON overrides the interpreter. Throws RunFailed when no package is found
// and PYTHONPATH does not name one either.
ChildTask python_module_task(const std::string& module, const std::vector<std::string>& args, const std::string& log_path);

}  // namespace hbtrack::cli
