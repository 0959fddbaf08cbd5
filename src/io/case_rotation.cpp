#include "case_rotation.hpp"

#include <Eigen/Cholesky>

namespace hbtrack {

namespace {

constexpr const char* kFixedSpeed =
    "is the rotation speed ([rotation] speed), which the model's K(Omega) was built with: vary it with "
    "`sweep --param` or `--set` (one case per speed), not by continuation";

}  // namespace

void read_rotation(const CaseReader& in, const toml::value& root, CaseDefinition& c) {
  const toml::value* model = in.find(root, "model");
  const toml::value* kg = model ? in.find(*model, "Kg1") : nullptr;
  const toml::value* ms = model ? in.find(*model, "Mspin") : nullptr;
  const toml::value* g = model ? in.find(*model, "G") : nullptr;
  const toml::value* rotation = in.find(root, "rotation");
  if (!rotation) {
    const std::pair<const toml::value*, const char*> keys[] = {{kg, "model.Kg1"}, {ms, "model.Mspin"}, {g, "model.G"}};
    for (const auto& [given, field] : keys)
      if (given) in.fail(given, field, "a rotating model's matrix: give the speed in [rotation] speed = ... (rad/s)");
    return;
  }
  in.table(*rotation, "rotation");
  in.check_keys(*rotation, "rotation", {"speed"});
  if (!kg) in.fail(rotation, "model.Kg1", "missing: [rotation] needs the geometric stiffness at 1 rad/s (make-blade --rotating: Kg1.mtx)");
  if (!ms) in.fail(rotation, "model.Mspin", "missing: [rotation] needs the spin-softening matrix (make-blade --rotating: Mspin.mtx)");
  const toml::value& speed = in.require(*rotation, "speed", "rotation.speed");
  const toml::value* speed_value = &speed;  // where the number is: here, or the named parameter's line
  std::string speed_field = "rotation.speed";
  RotationSettings r;
  if (speed.is_string()) {
    // A named parameter: its value in [parameters] (after --set), read here because the model is
    // built before the parameters are.
    r.speed_parameter = speed.as_string().str;
    const toml::value* parameters = in.find(root, "parameters");
    const toml::value* value = parameters && parameters->is_table() ? in.find(*parameters, r.speed_parameter) : nullptr;
    if (!value) in.fail(&speed, "rotation.speed", "unknown parameter '" + r.speed_parameter + "' (declare it in [parameters])");
    r.speed = in.number(*value, "parameters." + r.speed_parameter);
    speed_value = value;
    speed_field = "parameters." + r.speed_parameter + " (the rotation speed)";
  } else {
    r.speed = in.number(speed, "rotation.speed");
  }
  if (r.speed < 0)
    in.fail(speed_value, speed_field,
            "must be >= 0 (rad/s; the sense of rotation is the axis' the matrices were built about), got " + std::to_string(r.speed));
  const int n = c.model.dofs();
  r.geometric_stiffness = in.matrix(*kg, "model.Kg1", n);
  r.spin_softening = in.matrix(*ms, "model.Mspin", n);
  if (g) r.gyroscopic = in.matrix(*g, "model.G", n);
  const auto symmetric = [](const Eigen::MatrixXd& a, double sign) {
    const double scale = std::max(a.cwiseAbs().maxCoeff(), 1e-300);
    return (a - sign * a.transpose()).cwiseAbs().maxCoeff() <= 1e-10 * scale;
  };
  if (!symmetric(r.geometric_stiffness, 1)) in.fail(kg, "model.Kg1", "must be symmetric");
  if (!symmetric(r.spin_softening, 1)) in.fail(ms, "model.Mspin", "must be symmetric");
  if (g && !symmetric(r.gyroscopic, -1)) in.fail(g, "model.G", "must be skew-symmetric (G^T = -G)");
  r.stiffness_at_rest = c.model.stiffness;
  c.model.stiffness = r.stiffness_at_rest + r.speed * r.speed * (r.geometric_stiffness - r.spin_softening);
  c.model.stiffness = (0.5 * (c.model.stiffness + c.model.stiffness.transpose())).eval();
  if (Eigen::LLT<Eigen::MatrixXd>(c.model.stiffness).info() != Eigen::Success)
    in.fail(speed_value, speed_field,
            "K + Omega^2 (Kg1 - Mspin) is not positive definite at " + std::to_string(r.speed) +
                " rad/s (the spin softening exceeds the stiffening: past a divergence speed, or the matrices do not match)");
  c.rotation = std::move(r);
}

void add_gyroscopic_damping(CaseDefinition& c) {
  if (c.rotation && c.rotation->gyroscopic.size() > 0) c.model.damping += c.rotation->speed * c.rotation->gyroscopic;
}

void fix_rotation_parameter(CaseDefinition& c) {
  if (c.rotation && !c.rotation->speed_parameter.empty()) c.parameters.fix(c.parameters.find(c.rotation->speed_parameter), kFixedSpeed);
}

}  // namespace hbtrack
