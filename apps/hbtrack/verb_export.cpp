// `hbtrack export DIR [-o FILE.mat]`: a result folder as one MATLAB .mat file (mat_export.hpp).
#include <cstdio>

#include "cli_common.hpp"
#include "mat_export.hpp"

namespace hbtrack::cli {

namespace {

struct ExportOptions {
  std::string dir, out, format = "mat";
  bool quiet = false;
};

int run_export(const ExportOptions& o) {
  if (o.format != "mat") throw CaseError("--format: must be mat, got '" + o.format + "'");
  const std::string path = o.out.empty() ? o.dir + "/results.mat" : o.out;
  const std::vector<std::string> names = export_result_folder(o.dir, path);
  if (!o.quiet) {
    std::string listed;
    for (const std::string& n : names) listed += (listed.empty() ? "" : ", ") + n;
    std::fprintf(stderr, "export: %s -> %s\n", listed.c_str(), path.c_str());
  }
  return 0;
}

void add_export_verb(CLI::App& app, VerbList& verbs) {
  static ExportOptions options;
  CLI::App* e = app.add_subcommand("export", "a result folder as one MATLAB .mat file (tables as structs, special points, summary)");
  e->add_option("dir", options.dir, "result folder of any verb")->required();
  e->add_option("-o,--output", options.out, "the .mat file to write (default: DIR/results.mat)");
  e->add_option("--format", options.format, "mat (MATLAB v5: MATLAB, Octave, scipy.io.loadmat)");
  e->add_flag("-q,--quiet", options.quiet, "no summary line on stderr");
  verbs.push_back({e, [] { return run_export(options); }});
}

const VerbRegistrar registrar(add_export_verb);

}  // namespace

}  // namespace hbtrack::cli
