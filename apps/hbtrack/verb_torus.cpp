// `hbtrack torus`: the quasi-periodic response born at a Neimark-Sacker point of a frc result,
// continued in omega (a branch of tori computed by two-frequency harmonic balance).
#include <cstdio>
#include <utility>

#include "cli_common.hpp"
#include "cli_monitor.hpp"
#include "hbtrack/runs/torus.hpp"
#include "result_folder.hpp"
#include "result_folder_sink.hpp"
#include "special_point_start.hpp"

namespace hbtrack::cli {

namespace {

struct TorusCliOptions {
  CommonOptions common;
  std::string from, ns, range, harmonics, samples;
  double time_limit = 0;
};

// "A,B" as two integers >= min (the flag named in errors).
std::pair<long, long> integer_pair(const std::string& flag, const std::string& text, long min) {
  const size_t comma = text.find(',');
  if (comma == std::string::npos) throw CaseError(flag + ": expected two integers A,B, got '" + text + "'");
  return {parse_integer(flag, text.substr(0, comma), min), parse_integer(flag, text.substr(comma + 1), min)};
}

int run_torus(const TorusCliOptions& o) {
  const auto t0 = Clock::now();
  const long k = parse_integer("--ns", o.ns, 1);
  const size_t colon = o.range.find(':');
  if (colon == std::string::npos) throw CaseError("--range: expected LO:HI, got '" + o.range + "'");
  runs::TorusRunOptions run;
  run.omega_min = parse_number("--range", o.range.substr(0, colon));
  run.omega_max = parse_number("--range", o.range.substr(colon + 1));
  if (!(run.omega_min < run.omega_max)) throw CaseError("--range: must be LO:HI with LO < HI, got '" + o.range + "'");
  if (!o.harmonics.empty()) {
    const auto [h1, h2] = integer_pair("--harmonics", o.harmonics, 1);
    run.h1 = static_cast<int>(h1);
    run.h2 = static_cast<int>(h2);
  }
  if (!o.samples.empty()) {
    const auto [n1, n2] = integer_pair("--samples", o.samples, 3);
    run.n1 = static_cast<int>(n1);
    run.n2 = static_cast<int>(n2);
  }
  const CaseDefinition c = case_as_in(o.common, o.from);
  const HbmState start = starting_point(o.from, SpecialPointType::neimark_sacker, "--ns", k, make_system(c));
  run.start = runs::StartPoint{start.omega, start.x, o.from + "/special_states.csv"};
  run.origin = {{"from", o.from}, {"ns", k}, {"ns_order", "omega"}};
  ResultFolderSink sink(o.common.out_dir);
  Progress progress(o.common.quiet, run.omega_min, run.omega_max);
  progress.relay_to(o.common.progress_file);
  StopRequest stop(o.time_limit);
  CliMonitor monitor(progress, stop, c.outputs);
  runs::RunReport report;
  try {
    report = runs::torus(c, run, sink, monitor);
  } catch (const std::runtime_error& e) {
    if (dynamic_cast<const CaseError*>(&e)) throw;
    throw RunFailed{e.what()};
  }
  progress.finish();
  if (!report.success()) throw RunFailed{report.failure};
  if (!o.common.quiet) std::fprintf(stderr, "torus: %s, %.3f s -> %s\n", report.brief.c_str(), seconds_since(t0), o.common.out_dir.c_str());
  return 0;
}

void add_torus_verb(CLI::App& app, VerbList& verbs) {
  static TorusCliOptions torus;
  CLI::App* t = app.add_subcommand("torus", "the quasi-periodic response born at a Neimark-Sacker point, continued in omega");
  add_common_options(t, torus.common);
  t->add_option("--from", torus.from, "frc result folder holding the NS point")->required();
  t->add_option("--ns", torus.ns, "which Neimark-Sacker point of --from (from 1, in increasing omega)")->required();
  t->add_option("--range", torus.range, "LO:HI, the omega interval the branch may explore")->required();
  t->add_option("--harmonics", torus.harmonics, "H1,H2: harmonics in the forcing's phase and in the NS phase (default: the case's H, 4)");
  t->add_option("--samples", torus.samples, "N1,N2: grid of the two phases (default: the case's samples, the power of two above 4 H2)");
  add_time_limit_option(t, torus.time_limit);
  verbs.push_back({t, [] { return run_torus(torus); }});
}

const VerbRegistrar torus_registrar(add_torus_verb);

}  // namespace

}  // namespace hbtrack::cli
