#include "hbtrack/runs/campbell.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <stdexcept>

namespace hbtrack::runs {

namespace {

using Eigen::MatrixXcd;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using nlohmann::json;

struct SpeedModes {
  VectorXd frequencies;  // increasing
  MatrixXcd shapes;      // displacement parts, one column per frequency
};

// The lowest `count` frequencies of M x'' + speed G x' + K x = 0 at one speed, with their shapes.
SpeedModes modes_at(const MatrixXd& mass, const MatrixXd& stiffness, const MatrixXd& gyroscopic, double speed, int count) {
  const Eigen::Index n = mass.rows();
  SpeedModes out;
  if (gyroscopic.size() == 0 || speed == 0.0) {
    const Eigen::GeneralizedSelfAdjointEigenSolver<MatrixXd> solver(stiffness, mass);
    if (solver.info() != Eigen::Success || solver.eigenvalues().minCoeff() <= 0)
      throw std::runtime_error("the stiffness at speed is not positive definite");
    out.frequencies = solver.eigenvalues().head(count).cwiseSqrt();
    out.shapes = solver.eigenvectors().leftCols(count).cast<std::complex<double>>();
    return out;
  }
  // First-order form in the modes of (K, M), x = Phi q, Phi^T M Phi = I, Phi^T K Phi = D^2:
  // y = [D q; q'] gives y' = A y with A = [0 D; -D -speed Phi^T G Phi], skew-symmetric (G is), so
  // its eigenvalues +-i w are as well conditioned as those of a symmetric matrix. (The plain form
  // [0 I; -M^-1 K, -M^-1 speed G] lost 1e-5 of the frequencies to its scaling.)
  const Eigen::GeneralizedSelfAdjointEigenSolver<MatrixXd> undamped(stiffness, mass);
  if (undamped.info() != Eigen::Success || undamped.eigenvalues().minCoeff() <= 0)
    throw std::runtime_error("the stiffness at speed is not positive definite");
  const MatrixXd& phi = undamped.eigenvectors();
  const VectorXd d = undamped.eigenvalues().cwiseSqrt();
  MatrixXd a = MatrixXd::Zero(2 * n, 2 * n);
  a.topRightCorner(n, n) = d.asDiagonal();
  a.bottomLeftCorner(n, n) = -MatrixXd(d.asDiagonal());
  a.bottomRightCorner(n, n) = -speed * (phi.transpose() * gyroscopic * phi);
  const Eigen::EigenSolver<MatrixXd> solver(a);
  if (solver.info() != Eigen::Success) throw std::runtime_error("the gyroscopic eigenproblem did not converge");
  const MatrixXd to_displacement = phi * d.cwiseInverse().asDiagonal();
  std::vector<std::pair<double, Eigen::Index>> positive;
  for (Eigen::Index k = 0; k < 2 * n; ++k)
    if (solver.eigenvalues()(k).imag() > 0) positive.emplace_back(solver.eigenvalues()(k).imag(), k);
  std::sort(positive.begin(), positive.end());
  const int kept = std::min<int>(count, static_cast<int>(positive.size()));
  out.frequencies.resize(kept);
  out.shapes.resize(n, kept);
  for (int r = 0; r < kept; ++r) {
    out.frequencies(r) = positive[static_cast<size_t>(r)].first;
    out.shapes.col(r) =
        to_displacement.cast<std::complex<double>>() * solver.eigenvectors().col(positive[static_cast<size_t>(r)].second).head(n);
  }
  return out;
}

// |a^H M b|^2 / (a^H M a b^H M b)
double mac(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b, const MatrixXd& mass) {
  const std::complex<double> ab = a.dot(mass * b);
  const double aa = a.dot(mass * a).real(), bb = b.dot(mass * b).real();
  return std::norm(ab) / (aa * bb);
}

}  // namespace

std::vector<double> parse_speeds(const std::string& text, const std::string& field) {
  double lo = 0, hi = 0;
  int count = 0;
  char c1 = 0, c2 = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%lf %c %lf %c %d %c", &lo, &c1, &hi, &c2, &count, &extra) != 5 || c1 != ':' || c2 != ':')
    throw CaseError(field + ": '" + text + "' must be LO:HI:N (N evenly spaced speeds in rad/s, ends included)");
  if (!std::isfinite(lo) || !std::isfinite(hi) || lo < 0 || hi <= lo)
    throw CaseError(field + ": need 0 <= LO < HI (rad/s), got '" + text + "'");
  if (count < 2 || count > 10000) throw CaseError(field + ": N must be in 2..10000, got " + std::to_string(count));
  std::vector<double> speeds;
  for (int k = 0; k < count; ++k) speeds.push_back(lo + (hi - lo) * k / (count - 1));
  return speeds;
}

RunReport campbell(const CaseDefinition& c, const CampbellOptions& o, ResultSink& sink) {
  const auto t0 = RunClock::now();
  if (!c.rotation) throw CaseError(c.path + ": --speeds: the case has no [rotation] (a Campbell diagram needs [model] Kg1, Mspin)");
  if (o.count < 1) throw CaseError("--count: must be >= 1");
  if (o.speeds.empty()) throw CaseError("--speeds: no speed");
  for (size_t k = 0; k < o.speeds.size(); ++k)
    if (!(o.speeds[k] >= 0) || (k > 0 && !(o.speeds[k] > o.speeds[k - 1]))) throw CaseError("--speeds: must be >= 0 and increasing");
  const RotationSettings& r = c.rotation.value();
  const int n = c.model.dofs();
  const int count = std::min(o.count, n);
  // A few more modes than reported, so that a mode that comes down from above is followed.
  const int searched = std::min(n, count + 4);
  // A column per mode: its name, or "mode K" when it has none or another mode has it already
  // (make-blade names the modes above 1T less surely and may repeat one).
  std::vector<std::string> names;
  for (int k = 0; k < count; ++k) {
    const std::string given = k < static_cast<int>(o.names.size()) ? o.names[static_cast<size_t>(k)] : "";
    const bool usable = !given.empty() && given != "?" && std::find(names.begin(), names.end(), given) == names.end();
    names.push_back(usable ? given : "mode " + std::to_string(k + 1));
  }

  std::vector<VectorXd> rows;
  Eigen::MatrixXcd followed;  // the shapes of the followed modes at the previous speed
  double lowest_mac = 1.0;
  std::string failure;
  for (const double speed : o.speeds) {
    const MatrixXd k = r.stiffness_at_rest + speed * speed * (r.geometric_stiffness - r.spin_softening);
    SpeedModes modes;
    try {
      modes = modes_at(c.model.mass, k, r.gyroscopic, speed, searched);
    } catch (const std::runtime_error& e) {
      failure = "at " + std::to_string(speed) + " rad/s: " + e.what();
      break;
    }
    VectorXd row(count + 1);
    row(0) = speed;
    Eigen::MatrixXcd shapes(n, count);
    if (followed.size() == 0) {
      row.tail(count) = modes.frequencies.head(count);
      shapes = modes.shapes.leftCols(count);
    } else {
      // Each followed mode takes the unused mode of largest MAC with its previous shape.
      std::vector<bool> used(static_cast<size_t>(modes.frequencies.size()), false);
      for (int j = 0; j < count; ++j) {
        int best = -1;
        double best_mac = -1;
        for (Eigen::Index m = 0; m < modes.frequencies.size(); ++m) {
          if (used[static_cast<size_t>(m)]) continue;
          const double v = mac(followed.col(j), modes.shapes.col(m), c.model.mass);
          if (v > best_mac) best_mac = v, best = static_cast<int>(m);
        }
        used[static_cast<size_t>(best)] = true;
        lowest_mac = std::min(lowest_mac, best_mac);
        row(j + 1) = modes.frequencies(best);
        shapes.col(j) = modes.shapes.col(best);
      }
    }
    followed = shapes;
    rows.push_back(row);
  }
  if (!failure.empty()) return RunReport{json::object(), failure};

  sink.open();
  std::vector<std::string> header{"speed"};
  header.insert(header.end(), names.begin(), names.end());
  auto table = sink.table("campbell", header);
  for (const VectorXd& row : rows) table->append(std::vector<double>(row.data(), row.data() + row.size()));
  // Engine-order crossings: where w_j(Omega) - k Omega changes sign between two rows.
  json crossings = json::array();
  for (int eo = 1; eo <= o.engine_orders; ++eo)
    for (int j = 0; j < count; ++j)
      for (size_t s = 1; s < rows.size(); ++s) {
        const double g0 = rows[s - 1](j + 1) - eo * rows[s - 1](0), g1 = rows[s](j + 1) - eo * rows[s](0);
        if (g0 > 0 && g1 <= 0) {
          const double t = g0 / (g0 - g1);
          const double speed = rows[s - 1](0) + t * (rows[s](0) - rows[s - 1](0));
          crossings.push_back({{"engine_order", eo}, {"mode", names[static_cast<size_t>(j)]}, {"speed", speed}, {"frequency", eo * speed}});
        }
      }
  json first = json::array(), last = json::array();
  for (int j = 0; j < count; ++j) first.push_back(rows.front()(j + 1)), last.push_back(rows.back()(j + 1));
  json summary = {{"verb", "modes"},
                  {"kind", "campbell"},
                  {"case", c.path},
                  {"dofs", n},
                  {"mode_names", names},
                  {"speeds", {{"min", o.speeds.front()}, {"max", o.speeds.back()}, {"count", o.speeds.size()}}},
                  {"frequencies_at_lowest_speed", first},
                  {"frequencies_at_highest_speed", last},
                  {"gyroscopic", r.gyroscopic.size() > 0},
                  {"lowest_mac_between_speeds", lowest_mac},
                  {"engine_order_crossings", crossings},
                  {"timings", {{"wall_s", seconds_since(t0)}}}};
  sink.summary(summary);
  return RunReport{summary, "", std::to_string(rows.size()) + " speeds, " + std::to_string(count) + " modes"};
}

}  // namespace hbtrack::runs
