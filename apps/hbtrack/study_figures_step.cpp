#include "study_figures_step.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "child_process.hpp"
#include "hbtrack/results/results_writer.hpp"
#include "cli_common.hpp"
#include "python_package.hpp"

namespace hbtrack::cli {

nlohmann::json draw_study_figures(const std::string& dir, const std::string& units, bool quiet) {
  ensure_directory(dir + "/figures");
  std::vector<std::string> args{dir};
  if (!units.empty()) args.insert(args.end(), {"--units", units});
  int code = -1;
  try {
    code = run_child(python_module_task("hbtrack.study_figures", args, dir + "/figures/log.txt"));
  } catch (const RunFailed& no_package) {
    if (!quiet) std::fprintf(stderr, "study: no figures: %s\n", no_package.reason.c_str());
    return nlohmann::json::array();
  }
  nlohmann::json made = nlohmann::json::array();
  if (code == 0) {
    std::vector<std::string> files;
    for (const auto& f : std::filesystem::directory_iterator(dir + "/figures"))
      if (f.path().extension() == ".png") files.push_back("figures/" + f.path().filename().string());
    std::sort(files.begin(), files.end());
    for (const auto& f : files) made.push_back(f);
  } else if (!quiet) {
    std::fprintf(stderr, "study: no figures (exit %d, see %s/figures/log.txt)\n", code, dir.c_str());
  }
  return made;
}

}  // namespace hbtrack::cli
