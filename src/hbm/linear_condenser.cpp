#include "hbtrack/hbm/linear_condenser.hpp"

#include <Eigen/LU>
#include <complex>

#include "hbtrack/model/damping.hpp"

namespace hbtrack {

using cd = std::complex<double>;
using Eigen::MatrixXcd;
using Eigen::MatrixXd;
using Eigen::VectorXcd;

std::vector<VectorXcd> complex_forcing(const StructuralModel& model, int harmonics) {
  std::vector<VectorXcd> f(static_cast<size_t>(harmonics + 1), VectorXcd::Zero(model.dofs()));
  for (const HarmonicForce& h : model.forcing) {
    if (h.order < 0 || h.order > harmonics) continue;  // HarmonicBalance rejects these
    auto& fj = f[static_cast<size_t>(h.order)];
    if (h.order == 0) {
      fj += 2.0 * h.cos_part.cast<cd>();
    } else {
      fj += h.cos_part.cast<cd>() - cd(0, 1) * h.sin_part.cast<cd>();
    }
  }
  return f;
}

namespace {

std::vector<int> complement(int n, const std::vector<int>& retained) {
  std::vector<char> keep(static_cast<size_t>(n), 0);
  for (int r : retained) keep[static_cast<size_t>(r)] = 1;
  std::vector<int> rest;
  for (int i = 0; i < n; ++i)
    if (!keep[static_cast<size_t>(i)]) rest.push_back(i);
  return rest;
}

MatrixXcd submatrix(const MatrixXcd& a, const std::vector<int>& rows, const std::vector<int>& cols) {
  MatrixXcd out(rows.size(), cols.size());
  for (size_t i = 0; i < rows.size(); ++i)
    for (size_t j = 0; j < cols.size(); ++j) out(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = a(rows[i], cols[j]);
  return out;
}

VectorXcd subvector(const VectorXcd& v, const std::vector<int>& idx) {
  VectorXcd out(idx.size());
  for (size_t i = 0; i < idx.size(); ++i) out(static_cast<Eigen::Index>(i)) = v(idx[i]);
  return out;
}

// Marks `at` as computed at omega and sizes the operators every condenser fills; false when it
// already holds them at omega.
bool start_update(double omega, int harmonics, CondensedOperators& at) {
  if (omega == at.omega) return false;
  at.omega = omega;
  at.reduced_stiffness.resize(static_cast<size_t>(harmonics + 1));
  at.reduced_force.resize(static_cast<size_t>(harmonics + 1));
  return true;
}

class SchurCondenser final : public LinearCondenser {
 public:
  SchurCondenser(const StructuralModel& model, std::vector<int> retained, int harmonics)
      : model_(model), linear_(complement(model.dofs(), retained)), forcing_(complex_forcing(model, harmonics)) {
    retained_ = std::move(retained);
    harmonics_ = harmonics;
  }
  std::string method() const override { return linear_.empty() ? "none" : "schur"; }

  MatrixXcd dynamic_stiffness(int j, double omega) const {
    const double w = j * omega;
    return (model_.stiffness - w * w * model_.mass).cast<cd>() + cd(0, w) * model_.damping.cast<cd>();
  }
  MatrixXcd dynamic_stiffness_derivative(int j, double omega) const {
    return (-2.0 * j * j * omega * model_.mass).cast<cd>() + cd(0, j) * model_.damping.cast<cd>();
  }

  void update(double omega, CondensedOperators& at) const override {
    if (!start_update(omega, harmonics_, at)) return;
    const size_t nh = at.reduced_force.size();
    at.lu.resize(nh);
    at.coupling.resize(nh);
    at.linear_response.resize(nh);
    for (int j = 0; j <= harmonics_; ++j) {
      const size_t s = static_cast<size_t>(j);
      const MatrixXcd z = dynamic_stiffness(j, omega);
      MatrixXcd zrr = submatrix(z, retained_, retained_);
      VectorXcd fr = subvector(forcing_[s], retained_);
      if (!linear_.empty()) {
        at.lu[s].compute(submatrix(z, linear_, linear_));
        at.coupling[s] = at.lu[s].solve(submatrix(z, linear_, retained_));        // Z_ll^-1 Z_lr
        at.linear_response[s] = at.lu[s].solve(subvector(forcing_[s], linear_));  // Z_ll^-1 F_l
        const MatrixXcd zrl = submatrix(z, retained_, linear_);
        zrr.noalias() -= zrl * at.coupling[s];
        fr.noalias() -= zrl * at.linear_response[s];
      }
      at.reduced_stiffness[s] = std::move(zrr);
      at.reduced_force[s] = std::move(fr);
    }
  }

  VectorXcd omega_derivative(int j, const VectorXcd& z, double amplitude, const CondensedOperators& at) const override {
    const size_t s = static_cast<size_t>(j);
    const MatrixXcd dz = dynamic_stiffness_derivative(j, at.omega);
    VectorXcd out = submatrix(dz, retained_, retained_) * z;
    if (linear_.empty()) return out;
    const VectorXcd xl = amplitude * at.linear_response[s] - at.coupling[s] * z;
    const VectorXcd rhs = submatrix(dz, linear_, linear_) * xl + submatrix(dz, linear_, retained_) * z;
    const MatrixXcd z_full = dynamic_stiffness(j, at.omega);
    out += submatrix(dz, retained_, linear_) * xl - submatrix(z_full, retained_, linear_) * at.lu[s].solve(rhs);
    return out;
  }

  VectorXcd recover(int j, const VectorXcd& z, double amplitude, const CondensedOperators& at) const override {
    const size_t s = static_cast<size_t>(j);
    VectorXcd x(model_.dofs());
    for (size_t i = 0; i < retained_.size(); ++i) x(retained_[i]) = z(static_cast<Eigen::Index>(i));
    if (!linear_.empty()) {
      const VectorXcd xl = amplitude * at.linear_response[s] - at.coupling[s] * z;
      for (size_t i = 0; i < linear_.size(); ++i) x(linear_[i]) = xl(static_cast<Eigen::Index>(i));
    }
    return x;
  }

 private:
  StructuralModel model_;  // a copy: the condenser must not dangle when its owner moves
  std::vector<int> linear_;
  std::vector<VectorXcd> forcing_;
};

class ModalCondenser final : public LinearCondenser {
 public:
  ModalCondenser(const StructuralModel& model, std::vector<int> retained, int harmonics) {
    retained_ = std::move(retained);
    harmonics_ = harmonics;
    const NormalModes modes = normal_modes(model.mass, model.stiffness);
    shapes_ = modes.shapes;
    frequencies_ = modes.frequencies;
    modal_damping_ = (shapes_.transpose() * model.damping * shapes_).diagonal();
    retained_shapes_.resize(static_cast<Eigen::Index>(retained_.size()), shapes_.cols());
    for (size_t i = 0; i < retained_.size(); ++i) retained_shapes_.row(static_cast<Eigen::Index>(i)) = shapes_.row(retained_[i]);
    for (const VectorXcd& f : complex_forcing(model, harmonics)) modal_forcing_.push_back(shapes_.transpose().cast<cd>() * f);
  }
  std::string method() const override { return "modal"; }

  VectorXcd receptance_diagonal(int j, double omega) const {
    const double w = j * omega;
    VectorXcd d(frequencies_.size());
    for (Eigen::Index r = 0; r < d.size(); ++r) d(r) = 1.0 / cd(frequencies_(r) * frequencies_(r) - w * w, w * modal_damping_(r));
    return d;
  }

  void update(double omega, CondensedOperators& at) const override {
    if (!start_update(omega, harmonics_, at)) return;
    const size_t nh = at.reduced_force.size();
    at.modal_receptance.resize(nh);
    at.retained_forced_response.resize(nh);
    for (int j = 0; j <= harmonics_; ++j) {
      const size_t s = static_cast<size_t>(j);
      at.modal_receptance[s] = receptance_diagonal(j, omega);
      const MatrixXcd h_rr = retained_shapes_.cast<cd>() * at.modal_receptance[s].asDiagonal() * retained_shapes_.transpose().cast<cd>();
      at.reduced_stiffness[s] = h_rr.partialPivLu().inverse();
      at.retained_forced_response[s] = retained_shapes_.cast<cd>() * at.modal_receptance[s].cwiseProduct(modal_forcing_[s]);
      at.reduced_force[s] = at.reduced_stiffness[s] * at.retained_forced_response[s];
    }
  }

  VectorXcd omega_derivative(int j, const VectorXcd& z, double amplitude, const CondensedOperators& at) const override {
    const size_t s = static_cast<size_t>(j);
    const VectorXcd& d = at.modal_receptance[s];
    // d/domega of 1/(w_r^2 - (j w)^2 + i j w c_r)
    VectorXcd dd(d.size());
    for (Eigen::Index r = 0; r < d.size(); ++r) dd(r) = -d(r) * d(r) * cd(-2.0 * j * j * at.omega, j * modal_damping_(r));
    const MatrixXcd& zr = at.reduced_stiffness[s];
    const VectorXcd u = zr * (z - amplitude * at.retained_forced_response[s]);  // = -g at a solution
    const VectorXcd dh_u = retained_shapes_.cast<cd>() * dd.cwiseProduct(retained_shapes_.transpose().cast<cd>() * u);
    const VectorXcd dh_f = retained_shapes_.cast<cd>() * dd.cwiseProduct(modal_forcing_[s]);
    return -zr * (dh_u + amplitude * dh_f);
  }

  VectorXcd recover(int j, const VectorXcd& z, double amplitude, const CondensedOperators& at) const override {
    const size_t s = static_cast<size_t>(j);
    // g = amplitude Fr - Zr z is the nonlinear force that balances z; x = H (amplitude F - P^T g).
    const VectorXcd g = amplitude * at.reduced_force[s] - at.reduced_stiffness[s] * z;
    const VectorXcd modal =
        at.modal_receptance[s].cwiseProduct(amplitude * modal_forcing_[s] - retained_shapes_.transpose().cast<cd>() * g);
    return shapes_.cast<cd>() * modal;
  }

 private:
  MatrixXd shapes_;
  Eigen::VectorXd frequencies_, modal_damping_;
  MatrixXd retained_shapes_;
  std::vector<VectorXcd> modal_forcing_;
};

}  // namespace

bool modes_diagonalise_damping(const StructuralModel& model) {
  const NormalModes modes = normal_modes(model.mass, model.stiffness);
  if (modes.frequencies.size() == 0 || modes.frequencies.minCoeff() <= 0.0) return false;
  MatrixXd modal_c = modes.shapes.transpose() * model.damping * modes.shapes;
  const double scale = modal_c.diagonal().cwiseAbs().maxCoeff();
  modal_c.diagonal().setZero();
  return modal_c.cwiseAbs().maxCoeff() <= 1e-10 * std::max(scale, 1e-300);
}

std::unique_ptr<LinearCondenser> make_schur_condenser(const StructuralModel& model, std::vector<int> retained, int harmonics) {
  return std::make_unique<SchurCondenser>(model, std::move(retained), harmonics);
}

std::unique_ptr<LinearCondenser> make_modal_condenser(const StructuralModel& model, std::vector<int> retained, int harmonics) {
  return std::make_unique<ModalCondenser>(model, std::move(retained), harmonics);
}

}  // namespace hbtrack
