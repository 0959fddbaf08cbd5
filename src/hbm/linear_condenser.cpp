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

class SchurCondenser final : public LinearCondenser {
 public:
  SchurCondenser(const StructuralModel& model, std::vector<int> retained, int harmonics)
      : model_(model), linear_(complement(model.dofs(), retained)), forcing_(complex_forcing(model, harmonics)) {
    retained_ = std::move(retained);
    harmonics_ = harmonics;
    const size_t nh = static_cast<size_t>(harmonics + 1);
    reduced_stiffness_.resize(nh);
    reduced_force_.resize(nh);
    lu_.resize(nh);
    coupling_.resize(nh);
    linear_response_.resize(nh);
  }
  std::string method() const override { return linear_.empty() ? "none" : "schur"; }

  MatrixXcd dynamic_stiffness(int j, double omega) const {
    const double w = j * omega;
    return (model_.stiffness - w * w * model_.mass).cast<cd>() + cd(0, w) * model_.damping.cast<cd>();
  }
  MatrixXcd dynamic_stiffness_derivative(int j, double omega) const {
    return (-2.0 * j * j * omega * model_.mass).cast<cd>() + cd(0, j) * model_.damping.cast<cd>();
  }

  void update(double omega) override {
    if (omega == omega_) return;
    omega_ = omega;
    for (int j = 0; j <= harmonics_; ++j) {
      const size_t s = static_cast<size_t>(j);
      const MatrixXcd z = dynamic_stiffness(j, omega);
      MatrixXcd zrr = submatrix(z, retained_, retained_);
      VectorXcd fr = subvector(forcing_[s], retained_);
      if (!linear_.empty()) {
        lu_[s].compute(submatrix(z, linear_, linear_));
        coupling_[s] = lu_[s].solve(submatrix(z, linear_, retained_));      // Z_ll^-1 Z_lr
        linear_response_[s] = lu_[s].solve(subvector(forcing_[s], linear_));  // Z_ll^-1 F_l
        const MatrixXcd zrl = submatrix(z, retained_, linear_);
        zrr.noalias() -= zrl * coupling_[s];
        fr.noalias() -= zrl * linear_response_[s];
      }
      reduced_stiffness_[s] = std::move(zrr);
      reduced_force_[s] = std::move(fr);
    }
  }

  VectorXcd omega_derivative(int j, const VectorXcd& z, double amplitude) const override {
    const size_t s = static_cast<size_t>(j);
    const MatrixXcd dz = dynamic_stiffness_derivative(j, omega_);
    VectorXcd out = submatrix(dz, retained_, retained_) * z;
    if (linear_.empty()) return out;
    const VectorXcd xl = amplitude * linear_response_[s] - coupling_[s] * z;
    const VectorXcd rhs = submatrix(dz, linear_, linear_) * xl + submatrix(dz, linear_, retained_) * z;
    const MatrixXcd z_full = dynamic_stiffness(j, omega_);
    out += submatrix(dz, retained_, linear_) * xl - submatrix(z_full, retained_, linear_) * lu_[s].solve(rhs);
    return out;
  }

  VectorXcd recover(int j, const VectorXcd& z, double amplitude) const override {
    const size_t s = static_cast<size_t>(j);
    VectorXcd x(model_.dofs());
    for (size_t i = 0; i < retained_.size(); ++i) x(retained_[i]) = z(static_cast<Eigen::Index>(i));
    if (!linear_.empty()) {
      const VectorXcd xl = amplitude * linear_response_[s] - coupling_[s] * z;
      for (size_t i = 0; i < linear_.size(); ++i) x(linear_[i]) = xl(static_cast<Eigen::Index>(i));
    }
    return x;
  }

 private:
  StructuralModel model_;  // a copy: the condenser must not dangle when its owner moves
  std::vector<int> linear_;
  std::vector<VectorXcd> forcing_;
  std::vector<Eigen::PartialPivLU<MatrixXcd>> lu_;
  std::vector<MatrixXcd> coupling_;
  std::vector<VectorXcd> linear_response_;
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
    const size_t nh = static_cast<size_t>(harmonics + 1);
    reduced_stiffness_.resize(nh);
    reduced_force_.resize(nh);
    modal_receptance_.resize(nh);
    retained_forced_response_.resize(nh);
  }
  std::string method() const override { return "modal"; }

  VectorXcd receptance_diagonal(int j, double omega) const {
    const double w = j * omega;
    VectorXcd d(frequencies_.size());
    for (Eigen::Index r = 0; r < d.size(); ++r)
      d(r) = 1.0 / cd(frequencies_(r) * frequencies_(r) - w * w, w * modal_damping_(r));
    return d;
  }

  void update(double omega) override {
    if (omega == omega_) return;
    omega_ = omega;
    for (int j = 0; j <= harmonics_; ++j) {
      const size_t s = static_cast<size_t>(j);
      modal_receptance_[s] = receptance_diagonal(j, omega);
      const MatrixXcd h_rr = retained_shapes_.cast<cd>() * modal_receptance_[s].asDiagonal() * retained_shapes_.transpose().cast<cd>();
      reduced_stiffness_[s] = h_rr.partialPivLu().inverse();
      retained_forced_response_[s] = retained_shapes_.cast<cd>() * modal_receptance_[s].cwiseProduct(modal_forcing_[s]);
      reduced_force_[s] = reduced_stiffness_[s] * retained_forced_response_[s];
    }
  }

  VectorXcd omega_derivative(int j, const VectorXcd& z, double amplitude) const override {
    const size_t s = static_cast<size_t>(j);
    const VectorXcd& d = modal_receptance_[s];
    // d/domega of 1/(w_r^2 - (j w)^2 + i j w c_r)
    VectorXcd dd(d.size());
    for (Eigen::Index r = 0; r < d.size(); ++r)
      dd(r) = -d(r) * d(r) * cd(-2.0 * j * j * omega_, j * modal_damping_(r));
    const MatrixXcd& zr = reduced_stiffness_[s];
    const VectorXcd u = zr * (z - amplitude * retained_forced_response_[s]);  // = -g at a solution
    const VectorXcd dh_u = retained_shapes_.cast<cd>() * dd.cwiseProduct(retained_shapes_.transpose().cast<cd>() * u);
    const VectorXcd dh_f = retained_shapes_.cast<cd>() * dd.cwiseProduct(modal_forcing_[s]);
    return -zr * (dh_u + amplitude * dh_f);
  }

  VectorXcd recover(int j, const VectorXcd& z, double amplitude) const override {
    const size_t s = static_cast<size_t>(j);
    // g = amplitude Fr - Zr z is the nonlinear force that balances z; x = H (amplitude F - P^T g).
    const VectorXcd g = amplitude * reduced_force_[s] - reduced_stiffness_[s] * z;
    const VectorXcd modal = modal_receptance_[s].cwiseProduct(amplitude * modal_forcing_[s] - retained_shapes_.transpose().cast<cd>() * g);
    return shapes_.cast<cd>() * modal;
  }

 private:
  MatrixXd shapes_;
  Eigen::VectorXd frequencies_, modal_damping_;
  MatrixXd retained_shapes_;
  std::vector<VectorXcd> modal_forcing_;
  std::vector<VectorXcd> modal_receptance_;
  std::vector<VectorXcd> retained_forced_response_;
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

std::unique_ptr<LinearCondenser> make_schur_condenser(const StructuralModel& model, std::vector<int> retained,
                                                      int harmonics) {
  return std::make_unique<SchurCondenser>(model, std::move(retained), harmonics);
}

std::unique_ptr<LinearCondenser> make_modal_condenser(const StructuralModel& model, std::vector<int> retained,
                                                      int harmonics) {
  return std::make_unique<ModalCondenser>(model, std::move(retained), harmonics);
}

}  // namespace hbtrack
