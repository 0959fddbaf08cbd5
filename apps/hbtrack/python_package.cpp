#include "python_package.hpp"

#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "cli_common.hpp"

namespace hbtrack::cli {

namespace fs = std::filesystem;

namespace {

bool holds_package(const fs::path& dir) {
  std::error_code e;
  return fs::is_regular_file(dir / "hbtrack" / "plot.py", e);
}

fs::path executable_dir() {
  std::error_code e;
  const fs::path exe = fs::read_symlink("/proc/self/exe", e);  // the real file, through any symlink to it
  return e ? fs::path() : exe.parent_path();
}

// The same folder, however it is spelled; false when either does not exist.
bool same_folder(const fs::path& a, const fs::path& b) {
  std::error_code e;
  return fs::equivalent(a, b, e);
}

}  // namespace

std::string python_package_dir() {
  const fs::path bin = executable_dir();
  if (bin.empty()) return "";
  // Installed: HBTRACK_PYTHON_FROM_BIN is cmake/install.cmake's package folder, relative to the
  // tool's bin folder (or absolute); "" when the build has no Python package to install.
  const std::string from_bin = HBTRACK_PYTHON_FROM_BIN;
  if (!from_bin.empty()) {
    const fs::path installed = (bin / from_bin).lexically_normal();
    if (holds_package(installed)) return installed.string();
  }
  if (same_folder(bin, HBTRACK_BUILD_DIR) && holds_package(HBTRACK_SOURCE_PYTHON_DIR)) return HBTRACK_SOURCE_PYTHON_DIR;
  return "";
}

ChildTask python_module_task(const std::string& module, const std::vector<std::string>& args, const std::string& log_path) {
  const std::string package = python_package_dir();
  const char* existing = std::getenv("PYTHONPATH");
  const bool has_path = existing && *existing;
  if (package.empty() && !has_path)
    throw RunFailed{"no Python package hbtrack beside " + executable_dir().string() +
                    " (install hbtrack with its Python package, or set PYTHONPATH to a folder holding it; docs/install.md)"};
  if (!package.empty()) {
    const std::string path = has_path ? package + ":" + existing : package;
    setenv("PYTHONPATH", path.c_str(), 1);
  }
  setenv("MPLBACKEND", "Agg", 0);
  const char* interpreter = std::getenv("HBTRACK_PYTHON");
  std::vector<std::string> words{"-m", module};
  words.insert(words.end(), args.begin(), args.end());
  return {interpreter && *interpreter ? interpreter : HBTRACK_PYTHON_INTERPRETER, words, log_path};
}

}  // namespace hbtrack::cli
