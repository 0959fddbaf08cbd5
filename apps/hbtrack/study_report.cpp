#include "study_report.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

#include "hbtrack/results/results_writer.hpp"

namespace hbtrack::cli {

namespace {

using nlohmann::json;

std::string num(double v, const char* format = "%.6g") {
  char buf[48];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

// The name of the first output column (max_NAME) a special point carries, or "".
std::string first_output_key(const json& point) {
  for (const auto& [key, value] : point.items())
    if (key.rfind("max_", 0) == 0) return key;
  return "";
}

void nominal_section(std::ostream& out, const json& s) {
  if (!s.contains("nfrc")) return;
  const json& n = s["nfrc"];
  out << "## Nominal NFRC\n\n"
      << n.value("points", 0) << " points in " << num(n.value("wall_s", 0.0), "%.1f") << " s ([nfrc/](nfrc/)).\n\n";
  out << "| special point | omega (rad/s) | first output max |\n|---|---|---|\n";
  // In increasing omega, as the figures number them (summary.json keeps the branch's order), with
  // the digits that tell close points apart (an NS pair, two folds near a resonance).
  std::vector<json> points(n["special_points"].begin(), n["special_points"].end());
  std::stable_sort(points.begin(), points.end(),
                   [](const json& a, const json& b) { return a.value("omega", 0.0) < b.value("omega", 0.0); });
  for (const auto& sp : points) {
    const std::string key = first_output_key(sp);
    out << "| " << sp.value("type", "") << " | " << num(sp.value("omega", 0.0), "%.7g") << " | "
        << (key.empty() ? "" : num(sp.value(key, 0.0), "%.5g")) << " |\n";
  }
  out << "\n";
  const json warnings = n.value("warnings", json::array());
  for (const auto& w : warnings) out << "- warning: " << w.get<std::string>() << "\n";
  if (!warnings.empty()) out << "\n";
}

// Whether friction feeds each contact's normal load (analysis/friction_loop_gain.hpp).
void friction_loop_gain_section(std::ostream& out, const json& s) {
  if (!s.contains("nfrc") || !s["nfrc"].contains("friction_loop_gain")) return;
  auto value = [](const json& e, const char* key, const char* format) {
    return e.contains(key) && e[key].is_number() ? num(e[key].get<double>(), format) : std::string("-");
  };
  out << "## Friction loop gain\n\nmu G_nt / G_nn from the static flexibility at each contact's dofs, and the loop gain "
         "k G_nn (ratio - 1) (docs/elements.md): above 1 a rigid contact is ill-posed there and the contact stiffness sets "
         "the result.\n\n| element | dofs | sense | ratio | gain | k for gain 1 | self-energising |\n|---|---|---|---|---|---|---|\n";
  for (const auto& e : s["nfrc"]["friction_loop_gain"])
    out << "| " << e.value("element", 0) << " " << e.value("type", "") << " | " << e.value("normal_dof", "") << ", "
        << e.value("tangential_dof", "") << " | " << e.value("sense", 0) << " (" << e.value("sense_from", "") << ") | "
        << value(e, "ratio", "%.3f") << " | " << value(e, "gain", "%.3g") << " | " << value(e, "critical_stiffness", "%.3g") << " | "
        << (e.value("self_energising", false) ? "yes" : "no") << " |\n";
  out << "\n";
}

// The backbones and switched branches [study] asked for (study_branches.hpp).
void branches_section(std::ostream& out, const json& s) {
  if (!s.contains("backbones") && !s.contains("switched")) return;
  out << "## Backbones and switched branches\n\nDrawn over the nominal NFRC in [figures/nfrc.png](figures/nfrc.png).\n\n";
  auto range = [](const json& r, const char* format) {
    return r.is_array() && r.size() == 2 ? num(r[0].get<double>(), format) + " to " + num(r[1].get<double>(), format) : std::string();
  };
  if (s.contains("backbones")) {
    out << "| backbone | modal amplitude | points | stop | omega (rad/s) | damping ratio | time (s) |\n|---|---|---|---|---|---|---|\n";
    for (const auto& b : s["backbones"]) {
      const json& z = b["damping_ratio_range"];
      out << "| [" << b.value("folder", "") << "](" << b.value("folder", "") << "/) mode " << b.value("mode", 0) << " | "
          << range(b["range"], "%.4g") << " | " << b.value("points", 0) << " | " << b.value("stop_reason", "") << " | "
          << range(b["omega_range"], "%.5g") << " | "
          << (z.is_array() && z.size() == 2 ? num(100 * z[0].get<double>(), "%.3g") + " to " + num(100 * z[1].get<double>(), "%.3g") + " %"
                                            : "")
          << " | " << num(b.value("wall_s", 0.0), "%.1f") << " |\n";
    }
    out << "\n";
  }
  if (s.contains("switched")) {
    out << "| NFRC special point | omega (rad/s) | switched branch | points | its special points | stop | omega range | time (s) |\n"
           "|---|---|---|---|---|---|---|---|\n";
    for (const auto& w : s["switched"]) {
      out << "| " << w.value("point", 0) << " (" << w.value("type", "") << ") | " << num(w.value("omega", 0.0), "%.6g") << " | ";
      if (w.contains("on_the_branch_of")) {
        out << "on the branch of " << w["on_the_branch_of"].get<std::string>() << " | | | | | |\n";
        continue;
      }
      out << "[" << w.value("folder", "") << "](" << w.value("folder", "") << "/) | " << w.value("points", 0) << " | "
          << w.value("special_points", 0) << " | " << w.value("stop_reason", "") << " | " << range(w["omega_range"], "%.6g") << " | "
          << num(w.value("wall_s", 0.0), "%.1f") << " |\n";
    }
    if (s["switched"].empty()) out << "| (the nominal NFRC has no BP or PD) | | | | | | | |\n";
    out << "\n";
  }
}

// The tori [study] torus asked for (study_tori.hpp): one row per unstable band between NS points.
void tori_section(std::ostream& out, const json& s) {
  if (!s.contains("tori")) return;
  out << "## Quasi-periodic response (tori)\n\nFrom the lower NS point of each band of the nominal NFRC where the periodic branch is "
         "unstable, the torus born there, continued in omega (`hbtrack torus`; its stability is not decided).\n\n"
         "| NS point (omega) | band to | torus | points | how it ended | omega range | envelope: max (omega), min | time (s) |\n"
         "|---|---|---|---|---|---|---|---|\n";
  for (const auto& t : s["tori"]) {
    out << "| NS" << t.value("ns", 0) << " (" << num(t.value("omega", 0.0)) << ") | NS" << t.value("other_ns", 0) << " ("
        << num(t.value("other_omega", 0.0)) << ") | ";
    if (t.contains("skipped")) {
      out << t.value("folder", "") << " | | skipped: " << t["skipped"].get<std::string>() << " | | | |\n";
      continue;
    }
    std::string ended = t.value("stop_reason", "no result");
    if (t.contains("closed_at_ns")) {
      const int at = t["closed_at_ns"].get<int>();
      ended = "closed at NS" + std::to_string(at) + " (last row " + num(t.value("closed_at_distance", 0.0), "%.2g") + " from it in omega)";
      // One that turned back (at fewer harmonics than the NFRC's, say) has not covered the band.
      if (at != t.value("other_ns", 0)) ended += ", not at the band's other end";
    } else if (t.value("exit_code", 0) != 0)
      ended += " (exit " + std::to_string(t.value("exit_code", 0)) + ")";
    std::string envelope;
    for (const auto& e : t.value("envelope", json::array()))
      envelope += (envelope.empty() ? "" : "; ") + e.value("name", "") + " " + num(e.value("max", 0.0)) + " (" +
                  num(e.value("omega_at_max", 0.0)) + "), " + num(e.value("min", 0.0));
    const json r = t.value("omega_range", json::array());
    out << "[" << t.value("folder", "") << "](" << t.value("folder", "") << "/) | " << t.value("points", 0) << " | " << ended << " | "
        << (r.size() == 2 ? num(r[0].get<double>()) + " to " + num(r[1].get<double>()) : "") << " | " << envelope << " | "
        << num(t.value("wall_s", 0.0), "%.1f") << " |\n";
  }
  if (s["tori"].empty()) out << "| (the nominal NFRC has no unstable band between two NS points) | | | | | | | |\n";
  out << "\n";
}

void tracking_section(std::ostream& out, const json& s) {
  if (!s.contains("tracking") || s["tracking"].empty()) return;  // nothing tracked: a study of backbones or switches
  out << "## Limit-point tracking\n\n| parameter | range | LP | omega at LP | points | stop | time (s) |\n|---|---|---|---|---|---|---|\n";
  for (const auto& t : s["tracking"])
    for (const auto& c : t["curves"]) {
      out << "| " << t["parameter"].get<std::string>() << " | " << num(t["range"][0]) << " to " << num(t["range"][1]) << " | "
          << (c.contains("from")    ? c.value("from", "")
              : c.contains("point") ? c.value("point", "")  // an NS or PD point's curve
                                    : std::to_string(c.value("lp", 0)))
          << " | " << num(c.value("omega", 0.0), "%.2f") << " | ";
      if (c.value("same_curve_as_earlier_lp", false))
        out << "on an earlier LP's curve | | |\n";
      else
        out << c.value("points", 0) << " | " << c.value("stop_reason", "") << " | " << num(c.value("wall_s", 0.0), "%.1f") << " |\n";
    }
  out << "\n### Extrema of the parameter along the curves (appearance and merging of limit points)\n\n";
  out << "| parameter | extremum | value | omega (rad/s) | first output max | curve |\n|---|---|---|---|---|---|\n";
  int count = 0;
  for (const auto& t : s["tracking"])
    for (const auto& e : t["extrema"]) {
      const std::string key = first_output_key(e);
      out << "| " << t["parameter"].get<std::string>() << " | " << e.value("type", "") << " | " << num(e.value("value", 0.0)) << " | "
          << num(e.value("omega", 0.0), "%.2f") << " | " << (key.empty() ? "" : num(e.value(key, 0.0), "%.4g")) << " | "
          << e.value("curve", "") << " |\n";
      ++count;
    }
  if (count == 0) out << "| (none in the ranges) | | | | | |\n";
  out << "\n### Validation NFRCs and isolated branches\n\nAt each value an NFRC from the linear solution; each of its limit points must "
         "be a limit point of the tracking curves there (distance: relative, omega and first output). Crossings of the curves "
         "that no validation NFRC holds announce isolated branches, computed by `hbtrack isolas`.\n\n";
  out << "| parameter = value | NFRC LPs | on a curve | largest distance | curve crossings | not on the NFRC | isolas |\n"
         "|---|---|---|---|---|---|---|\n";
  for (const auto& t : s["tracking"])
    for (const auto& v : t["validations"]) {
      const size_t lps = v["limit_points"].size();
      out << "| " << t["parameter"].get<std::string>() << " = " << num(v.value("value", 0.0)) << " | " << lps << " | "
          << lps - static_cast<size_t>(v.value("lps_off_the_curves", 0)) << " | " << num(v.value("largest_distance", 0.0), "%.1e") << " | "
          << v.value("crossings", 0) << " | " << v.value("crossings_not_on_the_nfrc", 0) << " | " << v.value("isolas", 0) << " |\n";
      if (v.contains("beyond"))
        out << "|   left its range at the start (" << v.value("stop_reason", "")
            << "): again from omega = " << num(v["beyond"].value("omega_start", 0.0), "%.2f") << " in [" << v["beyond"].value("folder", "")
            << "](" << v["beyond"].value("folder", "") << "/), " << v["beyond"].value("stop_reason", "")
            << "; its limit points are the row's | | | | | | |\n";
      for (const auto& i : v.value("isola_branches", json::array()))
        out << "|   isola [" << i.value("folder", "") << "](" << i.value("folder", "") << "/) | omega " << num(i["omega_range"][0], "%.2f")
            << " to " << num(i["omega_range"][1], "%.2f") << " | " << i.value("points", 0) << " points | " << i.value("unstable_points", 0)
            << " unstable | | | |\n";
    }
  out << "\n";
}

// Where the full model's fold lies next to the HBM's (`simulate --near-lp`), with the LP at more
// harmonics when the convergence stage computed it.
void fold_search_lines(std::ostream& out, const json& s) {
  const json search = s["simulation"].value("fold_search", json::object());
  if (search.empty()) return;
  const double lp_omega = search.value("lp_omega", 0.0);
  out << "Time integrations started on the HBM orbit on the stable side of LP" << search.value("lp", 0)
      << " (omega = " << num(lp_omega, "%.2f") << " rad/s";
  if (s.contains("convergence"))
    for (const auto& row : s["convergence"].value("limit_points", json::array()))
      if (row.value("omega", 0.0) == lp_omega && row.contains("refined_omega"))
        out << "; at H = " << s["convergence"].value("harmonics", 0) << ": " << num(row.value("refined_omega", 0.0), "%.2f") << " rad/s, "
            << num(100 * row.value("relative_difference_omega", 0.0), "%+.2f") << " %";
  out << "), closest first ([simulate/](simulate/)):\n\n| NFRC point | omega (rad/s) | from the LP | periods | first harmonics, "
         "largest change | orbit |\n|---|---|---|---|---|---|\n";
  for (const auto& r : search.value("runs", json::array()))
    out << "| " << r.value("point", 0) << " | " << num(r.value("omega", 0.0), "%.2f") << " | "
        << num(100 * r.value("distance", 0.0), "%.2f") << " % | " << r.value("periods", 0) << " | "
        << num(100 * r.value("departure", 0.0), "%.2f") << " % | " << (r.value("held", false) ? "held" : "left") << " |\n";
  out << "\n";
  if (search.contains("held"))
    out << "The full model's periodic branch ends between "
        << (search.contains("left") ? num(search["left"].value("omega", 0.0), "%.2f") : num(lp_omega, "%.2f")) << " and "
        << num(search["held"].value("omega", 0.0), "%.2f")
        << " rad/s: the comparison below is from the start closest to the fold that held.\n\n";
  else
    out << "No start held the orbit (a first harmonic more than " << num(100 * search.value("left_the_orbit_above", 0.0), "%.0f")
        << " % off at the end): the comparison below is the last start's.\n\n";
}

// HBM against simulation, output by output, as compare_with_simulation wrote them.
void comparison_table(std::ostream& out, const json& m) {
  out << "\n\n| quantity | HBM | simulation | difference |\n|---|---|---|---|\n";
  for (const auto& o : m["outputs"])
    out << "| " << o.value("name", "") << " | " << num(o.value("hbm", 0.0), "%.5g") << " | " << num(o.value("simulation", 0.0), "%.5g")
        << " | " << num(100 * o.value("relative_difference", 0.0), "%+.2f") << " % |\n";
  out << "\n";
}

void simulation_section(std::ostream& out, const json& s) {
  if (!s.contains("simulation")) return;
  const json& m = s["simulation"];
  out << "## Time integration of the resonance\n\n";
  fold_search_lines(out, s);
  out << "From the HBM state of NFRC point " << m.value("point", 0) << " (omega = " << num(m.value("omega", 0.0), "%.2f") << " rad/s), "
      << m.value("periods", 0) << " periods of HHT-alpha Newmark in " << num(m.value("wall_s", 0.0), "%.1f") << " s (["
      << m.value("folder", "simulate") << "/](" << m.value("folder", "simulate") << "/)).";
  if (!m.value("converged", false))
    out << " Not periodic to `simulate`'s criterion within these periods (last period-to-period change "
        << num(m.value("last_change", 0.0), "%.1e")
        << "; a lightly damped resonance forgets its start slowly): the differences below include what is left of the "
           "transient"
        << (m.contains("fold_search") ? "." : ", and the step's exit code is 1.");
  comparison_table(out, m);
}

// The isolas' stable point integrated in time, and how far it lies from where Hill's verdict changes.
void isola_simulation_section(std::ostream& out, const json& s) {
  if (!s.contains("isola_simulation")) return;
  const json& m = s["isola_simulation"];
  const std::string folder = m.value("folder", "");
  out << "## Time integration on an isolated branch\n\nFrom point " << m.value("point", 0) << " of [" << folder << "](" << folder
      << "/) (omega = " << num(m.value("omega", 0.0), "%.2f") << " rad/s), the middle of the isolas' widest stable stretch, "
      << num(100 * m.value("stable_margin", 0.0), "%.2f") << " % in omega from its nearer end; " << m.value("periods", 0) << " periods in "
      << num(m.value("wall_s", 0.0), "%.1f") << " s ([simulate_isola/](simulate_isola/)).";
  if (!m.value("converged", false))
    out << " Not periodic to `simulate`'s criterion within these periods (last change " << num(m.value("last_change", 0.0), "%.1e")
        << "): the differences include what is left of the transient.";
  comparison_table(out, m);
}

}  // namespace

void write_study_report(const std::string& dir, const json& s) {
  std::ostringstream out;
  out << "# hbtrack study of " << s.value("case", "") << "\n\nStatus: " << s.value("stop_reason", "") << ", "
      << num(s.contains("timings") ? s["timings"].value("wall_s", 0.0) : 0.0, "%.1f") << " s in all. Every number below is in "
      << "[summary.json](summary.json); each folder is the result of one hbtrack command (its log.txt says which).\n\n";
  // What went wrong comes before everything that might look like a result.
  const json failed = s.value("failed_checks", json::array());
  if (!failed.empty()) {
    out << "## Failed checks\n\nThe results below are not confirmed:\n\n";
    for (const auto& f : failed) out << "- " << f.get<std::string>() << "\n";
    out << "\n";
  }
  for (const auto& f : s.value("figures", json::array())) out << "![" << f.get<std::string>() << "](" << f.get<std::string>() << ")\n\n";
  nominal_section(out, s);
  friction_loop_gain_section(out, s);
  branches_section(out, s);
  tori_section(out, s);
  tracking_section(out, s);
  simulation_section(out, s);
  isola_simulation_section(out, s);
  out << "## Steps\n\n| folder | exit code | time (s) |\n|---|---|---|\n";
  for (const auto& st : s["steps"])
    out << "| " << st.value("folder", "") << " | " << st.value("exit_code", 0) << (st.contains("skipped") ? " (skipped)" : "") << " | "
        << num(st.value("wall_s", 0.0), "%.1f") << " |\n";
  write_file_atomically(dir + "/index.md", out.str());
}

}  // namespace hbtrack::cli
