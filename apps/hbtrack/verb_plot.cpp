// `hbtrack plot DIR [-o OUT]`: the figures of any result folder, made by the Python package
// hbtrack.plot (matplotlib) from the source tree; the folder type is detected there.
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "cli_common.hpp"

namespace hbtrack::cli {

namespace {

struct PlotOptions {
  std::string dir, out, units;
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
  std::vector<std::string> args{interpreter, "-m", "hbtrack.plot", o.dir};
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
  CLI::App* plot = app.add_subcommand("plot", "figures (PNG and PDF) of a result folder of any verb, by the Python package");
  plot->add_option("dir", options.dir, "result folder (frc, track, isolas, simulate, solve)")->required();
  plot->add_option("-o,--output", options.out, "folder for the figures (default: DIR)");
  plot->add_option("--units", options.units, "the model's length unit for the axis labels (e.g. m; default: model length unit)");
  verbs.push_back({plot, [] { return run_plot(options); }});
}

const VerbRegistrar registrar(add_plot_verb);

}  // namespace

}  // namespace hbtrack::cli
