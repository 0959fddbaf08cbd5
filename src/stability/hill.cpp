#include "hbtrack/stability/hill.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <Spectra/GenEigsRealShiftSolver.h>
#include <algorithm>
#include <cmath>
#include <complex>
#include <numeric>
#include <memory>
#include <set>

#include "hbtrack/util/dense_eigen.hpp"
#include "hill_pencil.hpp"
#include "hill_system.hpp"

namespace hbtrack {

namespace {

// y = (A - sigma I)^-1 x for the first-order Hill matrix A = [[0, I], [-D2^-1 J, -D2^-1 D1]]
// without forming A: y1 = -L(sigma)^-1 (D2 x2 + (D1 + sigma D2) x1), y2 = x1 + sigma y1, with
// the quadratic pencil L(sigma) = J + sigma D1 + sigma^2 D2 factorised once (HillPencil: block
// elimination of the linear dofs) and D1, D2 applied from the structured system.
class HillShiftInvert {
 public:
  using Scalar = double;
  explicit HillShiftInvert(const HillSystem& system) : system_(system), size_(system.size()) {}
  Eigen::Index rows() const { return 2 * size_; }
  Eigen::Index cols() const { return 2 * size_; }
  void set_shift(double sigma) {
    sigma_ = sigma;
    pencil_ = std::make_unique<HillPencil>(system_, sigma);
  }
  void perform_op(const double* x_in, double* y_out) const {
    const Eigen::Map<const Eigen::VectorXd> x1(x_in, size_), x2(x_in + size_, size_);
    Eigen::Map<Eigen::VectorXd> y1(y_out, size_), y2(y_out + size_, size_);
    const Eigen::VectorXd rhs = system_.damping_times(x1) + system_.mass_times(x2 + sigma_ * x1);
    y1 = -pencil_->solve(rhs);
    y2 = x1 + sigma_ * y1;
  }

 private:
  const HillSystem& system_;
  Eigen::Index size_;
  double sigma_ = 0;
  std::unique_ptr<HillPencil> pencil_;  // (std::optional here trips GCC 12's -Wmaybe-uninitialized at -O1)
};

// Hill's eigenvalues nearest a small real shift (eigenvalue families l + i k w share their real
// part, so the ones near the imaginary axis with small |Im l| decide stability). Empty when
// the Arnoldi iteration did not converge.
Eigen::VectorXcd eigenvalues_near_axis(const HillSystem& system, int count, double omega, Eigen::MatrixXcd& vectors) {
  HillShiftInvert op(system);
  const Eigen::Index dimension = 2 * system.size();
  const Eigen::Index ncv = std::min<Eigen::Index>(dimension, std::max<Eigen::Index>(2 * count + 1, 20));
  // A shift a little off zero keeps the pencil regular at a limit point, where J is singular.
  Spectra::GenEigsRealShiftSolver<HillShiftInvert> solver(op, count, ncv, 1e-3 * omega);
  solver.init();
  solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-10);
  if (solver.info() != Spectra::CompInfo::Successful) return {};
  vectors = solver.eigenvectors().topRows(system.size());
  return solver.eigenvalues();
}

// Every eigenvalue of the first-order form [p; l p]: A = [[0, I], [-D2^-1 J, -D2^-1 D1]], and
// the p part of its eigenvectors.
Eigen::VectorXcd all_eigenvalues(const Eigen::MatrixXd& jacobian, const Eigen::MatrixXd& damping, const Eigen::MatrixXd& mass_matrix,
                                 int blocks, Eigen::MatrixXcd& vectors) {
  const Eigen::Index size = jacobian.rows(), n = mass_matrix.rows();
  const Eigen::LLT<Eigen::MatrixXd> mass(mass_matrix);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(2 * size, 2 * size);
  a.topRightCorner(size, size).setIdentity();
  for (int b = 0; b < blocks; ++b) {
    a.block(size + b * n, 0, n, size) = -mass.solve(jacobian.middleRows(b * n, n));
    a.block(size + b * n, size, n, size) = -mass.solve(damping.middleRows(b * n, n));
  }
  Eigen::MatrixXcd all_vectors;
  const Eigen::VectorXcd values = dense_eigenvalues(a, &all_vectors);
  vectors = all_vectors.topRows(size);
  return values;
}

// Where the energy of a Hill eigenvector p sits among the harmonics: sum k E_k / sum E_k over
// the complex exponentials e^{i k w t} (|k| <= H) of p(t). Members l + i m w of one exponent family
// have centroids shifted by m; the member whose centroid is nearest 0 is the one the truncation
// resolves best (Lazarus & Thomas 2010, Guillot et al. 2020), a spurious one sits near +-H.
double energy_centroid(const Eigen::VectorXcd& p, int n, const FourierBasis& basis) {
  using C = std::complex<double>;
  double weighted = 0, total = basis.has_mean() ? 0.25 * p.head(n).squaredNorm() : 0.0;
  for (int first = basis.has_mean() ? 1 : 0; first < basis.coefficients(); first += 2) {
    const int j = basis.harmonic_of(first);
    const auto c = p.segment(first * n, n), sn = p.segment((first + 1) * n, n);
    const double plus = 0.25 * (c - C(0, 1) * sn).squaredNorm(), minus = 0.25 * (c + C(0, 1) * sn).squaredNorm();
    weighted += j * (plus - minus);
    total += plus + minus;
  }
  return total > 0 ? weighted / total : 0.0;
}

}  // namespace

FloquetResult hill_floquet(HarmonicBalance& hbm, const Eigen::VectorXd& x, double forcing_omega, HillSolver solver) {
  const int n = hbm.model().dofs();
  // The exponent families are l + i k w with w the basis' fundamental (omega / nu), and the
  // multipliers are over its period.
  const double omega = hbm.fundamental(forcing_omega);
  const int blocks = hbm.basis().coefficients();
  const Eigen::Index size = static_cast<Eigen::Index>(n) * blocks;
  // Dense QR on the whole spectrum while it is cheap; beyond, the 2n eigenvalues nearest the
  // axis by shift-invert Arnoldi (one LU of the pencil's Schur complement on the element dofs
  // instead of a 2n(2H+1) QR). Stability and the PD/NS/LP test functions need only the
  // exponents near the axis: at most 24 of them, whatever the size (Arnoldi's cost grows with
  // the square of that count).
  constexpr Eigen::Index kDenseLimit = 300;
  Eigen::VectorXcd all;
  Eigen::MatrixXcd vectors;
  const bool arnoldi = solver == HillSolver::arnoldi || (solver == HillSolver::automatic && 2 * size > kDenseLimit);
  // Reused from call to call: the dense matrices (11 MB on the blade) and the element blocks
  // would otherwise be mapped and faulted in afresh at every point.
  thread_local Eigen::MatrixXd jacobian, damping;
  if (arnoldi) {
    std::set<int> coupled;  // the dofs the elements touch: the only ones coupling harmonics
    for (const auto& e : hbm.elements()) coupled.insert(e->dofs.begin(), e->dofs.end());
    thread_local HillSystem system;
    system.stiffness = &hbm.model().stiffness;
    system.mass = &hbm.model().mass;
    system.damping = &hbm.model().damping;
    system.basis = &hbm.basis();
    system.fundamental = omega;
    system.coupled.assign(coupled.begin(), coupled.end());
    hbm.hill_element_blocks(x, forcing_omega, system.coupled, system.element_jacobian, system.element_damping);
    system.prepare_products();
    all = eigenvalues_near_axis(system, std::min<int>({2 * n, 24, static_cast<int>(size) - 2}), omega, vectors);
    if (all.size() == 0) system.dense(jacobian, damping);  // the dense solver below, on the same matrices
  } else {
    hbm.hill_matrices(x, forcing_omega, jacobian, damping);
  }
  if (all.size() == 0) all = all_eigenvalues(jacobian, damping, hbm.model().mass, blocks, vectors);
  std::vector<double> centroid(static_cast<size_t>(all.size()));  // signed, in harmonics
  for (Eigen::Index i = 0; i < all.size(); ++i) centroid[static_cast<size_t>(i)] = energy_centroid(vectors.col(i), n, hbm.basis());
  std::vector<Eigen::Index> order(static_cast<size_t>(all.size()));
  std::iota(order.begin(), order.end(), 0);
  // Most central eigenvectors first (not smallest |Im l|: on a law that is not smooth, spurious
  // exponents of slowly converging families reach small |Im l| too); ties (the two members
  // s +- i w/2 of a period-doubling family) by |Im l|.
  std::stable_sort(order.begin(), order.end(), [&](Eigen::Index i, Eigen::Index j) {
    const double ci = std::abs(centroid[static_cast<size_t>(i)]), cj = std::abs(centroid[static_cast<size_t>(j)]);
    if (std::abs(ci - cj) > 1e-6) return ci < cj;
    return std::abs(all(i).imag()) < std::abs(all(j).imag());
  });
  // Keep the 2n most central, skipping the other members of a family already kept. If p(t) e^{lt}
  // solves the variational equation, so does (p(t) e^{-ikwt}) e^{(l + ikw)t}: the member l + ikw
  // has its eigenvector's energy shifted by -k harmonics. In the truncated Hill matrix the
  // members' real parts differ by the truncation error (4 % in |mu| on rotor 67 at H = 10, where
  // the member one harmonic off the centre has |mu| = 1.007 and the central one 0.968), so a
  // member is recognised by its imaginary part (k w, to 0.05 w) and its centroid (-k, to 0.35
  // harmonic), not by its real part. At a period doubling the exponents sit on the strip edge,
  // where s + i w/2 and s - i w/2 are the same family: keeping both would lose the other exponent
  // crossing there.
  FloquetResult r;
  r.method = StabilityMethod::hill;
  r.exponents.resize(2 * n);
  std::vector<double> kept_centroid;
  int kept = 0;
  for (size_t i = 0; i < order.size() && kept < 2 * n; ++i) {
    const std::complex<double> l = all(order[i]);
    const double c = centroid[static_cast<size_t>(order[i])];
    bool member = false;
    for (int j = 0; j < kept && !member; ++j) {
      const std::complex<double> d = l - r.exponents(j);
      const double shift = std::round(d.imag() / omega);
      member = shift != 0.0 && std::abs(d.imag() - shift * omega) <= 0.05 * omega &&
               std::abs(c - kept_centroid[static_cast<size_t>(j)] + shift) <= 0.35;
    }
    if (member) continue;
    r.centroid_spread = std::max(r.centroid_spread, std::abs(c));
    kept_centroid.push_back(c);
    r.exponents(kept++) = l;
  }
  r.exponents.conservativeResize(kept);
  finish_floquet(r, omega, 1e-9 * omega);
  // An exponent whose conjugate is a member of its own family (Im l = k w / 2, the conjugate
  // skipped above, not kept as a family of its own) stands for a real multiplier (+ at k even,
  // - at k odd: a period doubling's); the truncation leaves it a few 1e-3 w off (0.006 rad in
  // the multiplier's argument on NLvib's two-dof example), so its multiplier is put back on the
  // real axis, where the PD/LP test functions see it. The exponents stay the eigenvalues Hill's
  // matrix has.
  for (Eigen::Index i = 0; i < r.multipliers.size(); ++i) {
    const std::complex<double> l = r.exponents(i);
    const double half_periods = 2.0 * l.imag() / omega;
    if (l.imag() == 0.0 || std::abs(half_periods - std::round(half_periods)) > 0.02) continue;
    bool conjugate_kept = false;
    for (Eigen::Index j = 0; j < r.exponents.size(); ++j)
      conjugate_kept |= j != i && std::abs(r.exponents(j) - std::conj(l)) <= 0.05 * omega;
    if (!conjugate_kept) r.multipliers(i) = std::abs(r.multipliers(i)) * (std::lround(half_periods) % 2 == 0 ? 1.0 : -1.0);
  }
  return r;
}

}  // namespace hbtrack
