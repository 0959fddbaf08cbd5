#include "hbtrack/model/base_motion.hpp"

#include <stdexcept>

#include "hbtrack/model/damping.hpp"

namespace hbtrack {

EquivalentForcing base_motion_forcing(const StructuralModel& model, const BaseMotion& base) {
  const int n = model.dofs();
  if (base.harmonic < 1)
    throw std::invalid_argument("base_motion.harmonic: must be >= 1 (a constant base motion exerts no force on the relative motion)");
  if (base.dofs.empty()) throw std::invalid_argument("base_motion.dofs: needs at least one dof carried by the base");
  Eigen::VectorXd influence = Eigen::VectorXd::Zero(n);
  for (int d : base.dofs) {
    if (d < 0 || d >= n) throw std::invalid_argument("base_motion.dofs: dof index out of range");
    influence(d) = 1.0;
  }
  const Eigen::VectorXd m_r = model.mass * influence;
  const NormalModes modes = normal_modes(model.mass, model.stiffness);
  const double lowest = modes.frequencies.size() > 0 ? modes.frequencies.minCoeff() : 0.0;
  EquivalentForcing out;
  out.growth.reference_frequency = lowest > 0.0 ? lowest : 1.0;
  const double w = base.harmonic * out.growth.reference_frequency;  // h omega at omega = omega_ref
  HarmonicForce& f = out.force;
  f.order = base.harmonic;
  // -M r u_b'' with u_b'' written from what is imposed, as (h omega)^k times the value at omega_ref.
  switch (base.kind) {
    case BaseMotionKind::displacement:  // u_b'' = -(h w)^2 u_b
      out.growth.exponent = 2.0;
      f.cos_part = w * w * base.cos_part * m_r;
      f.sin_part = w * w * base.sin_part * m_r;
      break;
    case BaseMotionKind::velocity:  // v_b = c cos + s sin: u_b'' = h w (s cos - c sin)
      out.growth.exponent = 1.0;
      f.cos_part = -w * base.sin_part * m_r;
      f.sin_part = w * base.cos_part * m_r;
      break;
    case BaseMotionKind::acceleration:
      f.cos_part = -base.cos_part * m_r;
      f.sin_part = -base.sin_part * m_r;
      break;
  }
  return out;
}

}  // namespace hbtrack
