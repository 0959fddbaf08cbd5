// hbtrack: command-line front end. Each analysis verb reads a case file, writes its results into
// the folder given with -o (design.md contracts) and exits non-zero with a one-line reason on
// stderr when it fails.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/io/case_file.hpp"
#include "hbtrack/io/results_writer.hpp"

namespace {

using hbtrack::CaseDefinition;
using nlohmann::json;

volatile std::sig_atomic_t g_interrupted = 0;
void on_signal(int) { g_interrupted = 1; }

// Failures that are the run's, not the input's: results were written, exit code 1.
struct RunFailed {
  std::string reason;
};

json options_json(const CaseDefinition& c, const hbtrack::HarmonicBalance& hbm) {
  json params = json::object();
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
            {"wall_time_limit", co.wall_time_limit}}}};
}

std::vector<std::string> branch_header(const CaseDefinition& c) {
  std::vector<std::string> h{"omega"};
  for (const auto& o : c.outputs) {
    h.push_back("max_" + o.name);
    h.push_back("min_" + o.name);
    h.push_back("h1_" + o.name);
  }
  return h;
}

std::vector<double> branch_row(const hbtrack::RecordedPoint& p) {
  std::vector<double> row{p.omega};
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

void add_outputs(json& j, const CaseDefinition& c, const hbtrack::RecordedPoint& p) {
  for (size_t i = 0; i < c.outputs.size() && i < p.outputs.size(); ++i) {
    j["max_" + c.outputs[i].name] = p.outputs[i].max;
    j["min_" + c.outputs[i].name] = p.outputs[i].min;
    j["h1_" + c.outputs[i].name] = p.outputs[i].h1;
  }
}

hbtrack::HarmonicBalance make_system(const CaseDefinition& c) {
  try {
    return hbtrack::HarmonicBalance(c.model, c.elements, c.parameters, c.harmonic_balance);
  } catch (const std::invalid_argument& e) {
    throw hbtrack::CaseError(c.path + ": " + e.what());
  }
}

class Progress {
 public:
  explicit Progress(bool quiet) : enabled_(!quiet && isatty(STDERR_FILENO)) {}
  void update(int index, double omega, const hbtrack::RecordedPoint& p, const std::vector<hbtrack::OutputDof>& outputs) {
    if (!enabled_) return;
    std::fprintf(stderr, "\r  point %5d  omega %-12.6g", index, omega);
    if (!outputs.empty() && !p.outputs.empty()) std::fprintf(stderr, "  max_%s %-12.5g", outputs[0].name.c_str(), p.outputs[0].max);
    std::fflush(stderr);
  }
  ~Progress() {
    if (enabled_) std::fprintf(stderr, "\n");
  }

 private:
  bool enabled_;
};

int run_frc(const std::string& case_path, const std::string& out_dir, const std::vector<std::string>& sets, bool quiet) {
  const auto t0 = std::chrono::steady_clock::now();
  const CaseDefinition c = hbtrack::load_case(case_path, sets);
  hbtrack::HarmonicBalance hbm = make_system(c);
  hbtrack::ensure_directory(out_dir);
  hbtrack::CsvAppender branch(out_dir + "/branch.csv", branch_header(c));
  hbtrack::CsvAppender states(out_dir + "/states.csv", state_header(hbm.unknowns()));
  json summary = {{"verb", "frc"}, {"options", options_json(c, hbm)}, {"stop_reason", "running"}};
  hbtrack::write_json_atomically(out_dir + "/summary.json", summary);

  Progress progress(quiet);
  const hbtrack::NfrcResult r = hbtrack::compute_nfrc(
      hbm, c.nfrc, c.outputs, [&](const hbtrack::BranchPoint& p, const hbtrack::RecordedPoint& rec, int index) {
        branch.append(branch_row(rec));
        states.append(state_row(p.lambda, p.u));
        progress.update(index, p.lambda, rec, c.outputs);
        return g_interrupted == 0;
      });
  const auto& s = r.continuation.summary;
  summary["stop_reason"] = s.stop_reason;
  summary["points"] = s.points;
  summary["newton_iterations"] = s.newton_iterations;
  summary["failed_steps"] = s.failed_steps;
  summary["step_halvings"] = s.step_halvings;
  summary["jacobian_evaluations"] = s.jacobian_evaluations;
  summary["options"]["continuation"]["length_scale"] = r.length_scale;
  summary["timings"] = {{"wall_s", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()},
                        {"continuation_s", s.wall_s}};
  summary["outputs"] = json::array();
  for (const auto& o : c.outputs) summary["outputs"].push_back({{"name", o.name}, {"dof", c.model.dof_names[static_cast<size_t>(o.dof)]}});
  json special = json::array();
  for (const auto& sp : r.continuation.special_points) {
    json j = {{"type", sp.type}, {"index", sp.index}, {"omega", sp.lambda}, {"located", sp.located}};
    j["parameters"] = summary["options"]["parameters"];
    if (sp.index >= 0 && static_cast<size_t>(sp.index) < r.recorded.size()) add_outputs(j, c, r.recorded[static_cast<size_t>(sp.index)]);
    special.push_back(j);
  }
  summary["special_points"] = special;
  hbtrack::write_json_atomically(out_dir + "/summary.json", summary);
  if (!r.continuation.success())
    throw RunFailed{"continuation stopped: " + s.stop_reason + " after " + std::to_string(s.points) + " points (kept in " + out_dir + ")"};
  if (!quiet)
    std::fprintf(stderr, "frc: %d points, %d limit points, %d Newton iterations, %.3f s -> %s\n", s.points,
                 static_cast<int>(special.size()), s.newton_iterations, summary["timings"]["wall_s"].get<double>(), out_dir.c_str());
  return 0;
}

int run_solve(const std::string& case_path, const std::string& out_dir, const std::vector<std::string>& sets, double omega,
              bool quiet) {
  const auto t0 = std::chrono::steady_clock::now();
  const CaseDefinition c = hbtrack::load_case(case_path, sets);
  if (!(omega > 0) || !std::isfinite(omega)) throw hbtrack::CaseError("--omega: must be > 0 and finite");
  hbtrack::HarmonicBalance hbm = make_system(c);
  hbtrack::ensure_directory(out_dir);
  const auto& co = c.nfrc.continuation;
  const hbtrack::FixedFrequencySolution s = hbtrack::solve_at_frequency(hbm, omega, c.outputs, co.tolerance, 4 * co.max_iterations);
  json summary = {{"verb", "solve"},
                  {"options", options_json(c, hbm)},
                  {"omega", omega},
                  {"converged", s.converged},
                  {"stop_reason", s.converged ? "converged" : "no_convergence"},
                  {"points", s.converged ? 1 : 0},
                  {"newton_iterations", std::max(s.newton_iterations, 0)},
                  {"failed_steps", s.converged ? 0 : 1},
                  {"special_points", json::array()}};
  if (s.converged) {
    hbtrack::CsvAppender branch(out_dir + "/branch.csv", branch_header(c));
    branch.append(branch_row(s.recorded));
    hbtrack::CsvAppender states(out_dir + "/states.csv", state_header(hbm.unknowns()));
    states.append(state_row(omega, s.x));
    add_outputs(summary, c, s.recorded);
  }
  summary["timings"] = {{"wall_s", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()}};
  hbtrack::write_json_atomically(out_dir + "/summary.json", summary);
  if (!s.converged) throw RunFailed{"Newton did not converge at omega = " + std::to_string(omega)};
  if (!quiet) std::fprintf(stderr, "solve: converged in %d Newton iterations -> %s\n", s.newton_iterations, out_dir.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"hbtrack: nonlinear forced response of structures with contact and friction by harmonic balance"};
  app.require_subcommand(1);
  std::string case_path, out_dir;
  std::vector<std::string> sets;
  bool quiet = false;
  double omega = 0;

  auto common = [&](CLI::App* verb) {
    verb->add_option("case", case_path, "case file (TOML)")->required();
    verb->add_option("-o,--output", out_dir, "output folder (created if missing)")->required();
    verb->add_option("--set", sets, "override NAME=VALUE: a named parameter or a dotted case key")->take_all();
    verb->add_flag("-q,--quiet", quiet, "no progress line or closing report");
  };
  CLI::App* frc = app.add_subcommand("frc", "nonlinear frequency response curve by arc-length continuation in omega");
  common(frc);
  CLI::App* solve = app.add_subcommand("solve", "one periodic solution at a fixed frequency");
  common(solve);
  solve->add_option("--omega", omega, "forcing frequency (rad/s)")->required();

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  try {
    if (*frc) return run_frc(case_path, out_dir, sets, quiet);
    if (*solve) return run_solve(case_path, out_dir, sets, omega, quiet);
  } catch (const RunFailed& e) {
    std::fprintf(stderr, "hbtrack: %s\n", e.reason.c_str());
    return 1;
  } catch (const hbtrack::CaseError& e) {
    std::fprintf(stderr, "hbtrack: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hbtrack: %s\n", e.what());
    return 3;
  }
  return 0;
}
