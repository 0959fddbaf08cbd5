// `hbtrack plot DIR [DIR2 ...] [-o OUT]`: the figures of any result folder, or of several drawn
// over each other (an NFRC, its backbone, its switched branches), made by the Python package
// hbtrack.plot (matplotlib) from the source tree; the folder types are detected there.
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "cli_common.hpp"

namespace hbtrack::cli {

namespace {

struct PlotOptions {
  std::vector<std::string> dirs;
  std::string out, units;
};

int run_plot(const PlotOptions& o) {
  // The package needs no compiled part to plot: the source folder on PYTHONPATH is enough, and
  // it is known at build time. HBTRACK_PYTHON overrides the interpreter.
  std::string path = HBTRACK_PYTHON_PACKAGE_DIR;
  if (const char* existing = std::getenv("PYTHONPATH"); existing && *existing) {
    path += ":";
    path += existing;
  }
  setenv("PYTHONPATH", path.c_str(), 1);
  setenv("MPLBACKEND", "Agg", 0);
  const char* interpreter = std::getenv("HBTRACK_PYTHON");
  if (!interpreter || !*interpreter) interpreter = HBTRACK_PYTHON_INTERPRETER;
  std::vector<std::string> args{interpreter, "-m", "hbtrack.plot"};
  args.insert(args.end(), o.dirs.begin(), o.dirs.end());
  if (!o.out.empty()) args.insert(args.end(), {"-o", o.out});
  if (!o.units.empty()) args.insert(args.end(), {"--units", o.units});
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::fflush(nullptr);
  execv(interpreter, argv.data());
  std::string reason = "plot: cannot run ";
  reason += interpreter;
  reason += ": ";
  reason += std::strerror(errno);
  throw RunFailed{reason};
}

void add_plot_verb(CLI::App& app, VerbList& verbs) {
  static PlotOptions options;
  CLI::App* plot = app.add_subcommand(
      "plot", "figures (PNG and PDF) of a result folder of any verb, or of several drawn over each other, by the Python package");
  plot->add_option("dirs", options.dirs,
                   "result folder (frc, solve, track, isolas, simulate, sweep, backbone, continue, switch); several: drawn over each other")
      ->required();
  plot->add_option("-o,--output", options.out, "folder for the figures (default: the first DIR)");
  plot->add_option("--units", options.units, "the model's length unit for the axis labels (e.g. m; default: model length unit)");
  verbs.push_back({plot, [] { return run_plot(options); }});
}

const VerbRegistrar registrar(add_plot_verb);

}  // namespace

}  // namespace hbtrack::cli
