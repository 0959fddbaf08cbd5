// `hbtrack plot DIR [DIR2 ...] [-o OUT]`: the figures of any result folder, or of several drawn
// over each other (an NFRC, its backbone, its switched branches), made by the Python package
// hbtrack.plot (matplotlib; python_package.hpp says which copy of it); the folder types are
// detected there.
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <vector>

#include "cli_common.hpp"
#include "python_package.hpp"

namespace hbtrack::cli {

namespace {

// The options of `python -m hbtrack.plot`, passed on as given (python/hbtrack/plot.py checks them).
struct PlotOptions {
  std::vector<std::string> dirs;
  std::string out, units, model_units, point;
  std::vector<std::string> labels;
  double zoom = -1;  // < 0: Python's default
  bool norm = false, no_zoom = false, titles = false, quiet = false;
};

int run_plot(const PlotOptions& o) {
  std::vector<std::string> args = o.dirs;
  if (!o.out.empty()) args.insert(args.end(), {"-o", o.out});
  if (!o.units.empty()) args.insert(args.end(), {"--units", o.units});
  if (!o.model_units.empty()) args.insert(args.end(), {"--model-units", o.model_units});
  if (!o.point.empty()) args.insert(args.end(), {"--point", o.point});
  if (o.zoom >= 0) args.insert(args.end(), {"--zoom", number_text(o.zoom, 17)});
  for (const std::string& label : o.labels) args.insert(args.end(), {"--label", label});
  if (o.norm) args.emplace_back("--norm");
  if (o.no_zoom) args.emplace_back("--no-zoom");
  if (o.titles) args.emplace_back("--titles");
  if (o.quiet) args.emplace_back("--quiet");
  ChildTask python = python_module_task("hbtrack.plot", args, "");
  std::vector<std::string> words{python.program};
  words.insert(words.end(), python.args.begin(), python.args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  std::fflush(nullptr);
  execv(python.program.c_str(), argv.data());
  throw RunFailed{"plot: cannot run " + python.program + ": " + std::strerror(errno)};
}

void add_plot_verb(CLI::App& app, VerbList& verbs) {
  static PlotOptions options;
  CLI::App* plot = app.add_subcommand(
      "plot", "figures (PNG and PDF) of a result folder of any verb, or of several drawn over each other, by the Python package");
  plot->add_option("dirs", options.dirs,
                   "result folder (frc, solve, track, isolas, simulate, sweep, backbone, continue, switch); several: drawn over each other")
      ->required();
  plot->add_option("-o,--output", options.out, "folder for the figures (default: the first DIR)");
  plot->add_option("--units", options.units,
                   "unit of lengths in the figures: m, cm, mm, um, nm or in convert from --model-units; other text only labels the axes");
  plot->add_option("--model-units", options.model_units, "the unit of the model's lengths (default m)");
  plot->add_flag("--norm", options.norm, "NFRC of ||r(t)||_inf = max(|max|, |min|), all outputs in one axes (the paper's Fig. 3)");
  plot->add_option("--zoom", options.zoom, "zoom on where the response exceeds this fraction of its peak (default 0.1)")
      ->check(CLI::Range(0.0, 1.0));
  plot->add_flag("--no-zoom", options.no_zoom, "the NFRC's whole range, not zoomed on the resonance");
  plot->add_option("--point", options.point, "the Fourier figure's point: a row of branch.csv or LPk (default LP1)");
  plot->add_flag("--titles", options.titles, "titles on the figures (default none)");
  plot->add_flag("-q,--quiet", options.quiet, "do not list the files written (errors are still reported)");
  plot->add_option("--label", options.labels, "NAME=TEXT: describe output NAME in the figures (repeatable)")->allow_extra_args(false);
  verbs.push_back({plot, [] { return run_plot(options); }});
}

const VerbRegistrar plot_registrar(add_plot_verb);

}  // namespace

}  // namespace hbtrack::cli
