// `hbtrack export DIR [--format mat|h5] [-o FILE]`: a result folder as one MATLAB .mat file
// (mat_export.hpp) or one HDF5 file (h5_export.hpp).
#include <cstdio>
#include <filesystem>

#include "cli_common.hpp"
#include "h5_export.hpp"
#include "mat_export.hpp"

namespace hbtrack::cli {

namespace {

struct ExportOptions {
  std::string dir, out, format = "mat";
  bool quiet = false;
};

// -o DIR/branch.csv (or summary.json) replaced the very file the export reads: inside DIR only a
// .mat or .h5 file may be written (DIR/results.mat is the default, written again on each export).
void refuse_the_folders_own_files(const std::string& dir, const std::string& out) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path target = fs::weakly_canonical(out, ec);
  const fs::path folder = fs::weakly_canonical(dir, ec);
  const std::string extension = target.extension().string();
  if (!ec && (target == folder || (target.parent_path() == folder && extension != ".mat" && extension != ".h5")))
    throw CaseError("-o: " + out + " is inside " + dir + ", whose own files it would replace; give a .mat or .h5 file, or one elsewhere");
}

int run_export(const ExportOptions& o) {
  if (o.format != "mat" && o.format != "h5") throw CaseError("--format: must be mat or h5, got '" + o.format + "'");
  const std::string path = o.out.empty() ? o.dir + "/results." + o.format : o.out;
  refuse_the_folders_own_files(o.dir, path);
  const std::vector<std::string> names = o.format == "h5" ? export_result_folder_h5(o.dir, path) : export_result_folder(o.dir, path);
  if (!o.quiet) {
    std::string listed;
    for (const std::string& n : names) listed += (listed.empty() ? "" : ", ") + n;
    std::fprintf(stderr, "export: %s -> %s\n", listed.c_str(), path.c_str());
  }
  return 0;
}

void add_export_verb(CLI::App& app, VerbList& verbs) {
  static ExportOptions options;
  CLI::App* e = app.add_subcommand("export", "a result folder as one MATLAB .mat or HDF5 file (tables, special points, summary)");
  e->add_option("dir", options.dir, "result folder of any verb")->required();
  e->add_option("-o,--output", options.out, "the file to write (default: DIR/results.mat, or DIR/results.h5 with --format h5)");
  e->add_option("--format", options.format,
                "mat (MATLAB v5: MATLAB, Octave, scipy.io.loadmat, the default) or h5 (HDF5: h5py, h5read, Julia)");
  e->add_flag("-q,--quiet", options.quiet, "no summary line on stderr");
  verbs.push_back({e, [] { return run_export(options); }});
}

const VerbRegistrar export_registrar(add_export_verb);

}  // namespace

}  // namespace hbtrack::cli
