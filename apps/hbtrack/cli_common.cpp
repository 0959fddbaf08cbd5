#include "cli_common.hpp"

#include <unistd.h>

#include <csignal>
#include <cstdio>

namespace hbtrack::cli {

namespace {
volatile std::sig_atomic_t g_interrupted = 0;
}  // namespace

std::vector<VerbFactory>& verb_factories() {
  static std::vector<VerbFactory> factories;  // constructed on first use, before any registrar runs
  return factories;
}

void on_signal(int) { g_interrupted = 1; }
bool interrupted() { return g_interrupted != 0; }

void add_common_options(CLI::App* command, CommonOptions& o) {
  command->add_option("case", o.case_path, "case file (TOML)")->required();
  command->add_option("-o,--output", o.out_dir, "output folder (created if missing)")->required();
  command->add_option("--set", o.sets, "override NAME=VALUE: a named parameter or a dotted case key")->take_all();
  command->add_flag("-q,--quiet", o.quiet, "no progress line or closing report");
}

HarmonicBalance make_system(const CaseDefinition& c) {
  try {
    return HarmonicBalance(c.model, c.elements, c.parameters, c.harmonic_balance);
  } catch (const std::invalid_argument& e) {
    throw CaseError(c.path + ": " + e.what());
  }
}

nlohmann::json options_json(const CaseDefinition& c, const HarmonicBalance& hbm) {
  nlohmann::json params = nlohmann::json::object();
  for (int i = 0; i < hbm.parameters().size(); ++i) params[hbm.parameters().names()[static_cast<size_t>(i)]] = hbm.parameters().value(i);
  const auto& co = c.nfrc.continuation;
  return {{"case", c.path},
          {"parameters", params},
          {"harmonic_balance",
           {{"harmonics", c.harmonic_balance.harmonics},
            {"samples", hbm.basis().samples()},
            {"condensation", hbm.condensation_method()},
            {"unknowns", hbm.unknowns()}}},
          {"continuation",
           {{"omega_start", c.nfrc.omega_start},
            {"omega_end", c.nfrc.omega_end},
            {"length_scale", c.nfrc.length_scale},
            {"step", co.step},
            {"step_min", co.step_min},
            {"step_max", co.step_max},
            {"max_points", co.max_points},
            {"max_iterations", co.max_iterations},
            {"target_iterations", co.target_iterations},
            {"tolerance", co.tolerance},
            {"max_angle", co.max_angle},
            {"predictor", co.predictor},
            {"corrector", co.corrector},
            {"wall_time_limit", co.wall_time_limit},
            {"locate", co.locate}}},
          {"stability", {{"method", c.nfrc.stability.method}, {"monodromy_steps", c.nfrc.stability.monodromy_steps}, {"hill_solver", c.nfrc.stability.hill_solver}}}};
}

std::vector<std::string> branch_header(const CaseDefinition& c) {
  std::vector<std::string> h{"omega"};
  if (c.nfrc.stability.enabled()) h.push_back("stable");
  for (const auto& o : c.outputs) {
    h.push_back("max_" + o.name);
    h.push_back("min_" + o.name);
    h.push_back("h1_" + o.name);
  }
  return h;
}

std::vector<double> branch_row(const RecordedPoint& p) {
  std::vector<double> row{p.omega};
  if (p.stable >= 0) row.push_back(p.stable);
  for (const auto& v : p.outputs) {
    row.push_back(v.max);
    row.push_back(v.min);
    row.push_back(v.h1);
  }
  return row;
}

std::vector<std::string> state_header(int unknowns) {
  std::vector<std::string> h{"omega"};
  for (int i = 0; i < unknowns; ++i) h.push_back("x" + std::to_string(i));
  return h;
}

std::vector<double> state_row(double omega, const Eigen::VectorXd& x) {
  std::vector<double> row{omega};
  row.insert(row.end(), x.data(), x.data() + x.size());
  return row;
}

void add_outputs(nlohmann::json& j, const CaseDefinition& c, const RecordedPoint& p) {
  for (size_t i = 0; i < c.outputs.size() && i < p.outputs.size(); ++i) {
    j["max_" + c.outputs[i].name] = p.outputs[i].max;
    j["min_" + c.outputs[i].name] = p.outputs[i].min;
    j["h1_" + c.outputs[i].name] = p.outputs[i].h1;
  }
}

Progress::Progress(bool quiet) : enabled_(!quiet && isatty(STDERR_FILENO)) {}

Progress::~Progress() {
  if (enabled_) std::fprintf(stderr, "\n");
}

void Progress::update(int index, double omega, const RecordedPoint& p, const std::vector<OutputDof>& outputs) {
  if (!enabled_) return;
  std::fprintf(stderr, "\r  point %5d  omega %-12.6g", index, omega);
  if (!outputs.empty() && !p.outputs.empty()) std::fprintf(stderr, "  max_%s %-12.5g", outputs[0].name.c_str(), p.outputs[0].max);
  std::fflush(stderr);
}

}  // namespace hbtrack::cli
