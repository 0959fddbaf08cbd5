#include "hbtrack/results/model_fingerprint.hpp"

#include "hbtrack/util/fnv1a.hpp"

namespace hbtrack {

namespace {

// The model's fields fed to FNV-1a with their sizes first ("ab" + "c" and "a" + "bc" differ).
class ModelHash {
 public:
  void number(double v) { h_.bytes(&v, sizeof v); }
  void integer(long long v) { h_.bytes(&v, sizeof v); }
  void text(const std::string& s) {
    integer(static_cast<long long>(s.size()));
    h_.bytes(s);
  }
  void matrix(const Eigen::MatrixXd& m) {
    integer(m.rows());
    integer(m.cols());
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      for (Eigen::Index i = 0; i < m.rows(); ++i) number(m(i, j));
  }
  std::string hex() const { return h_.hex(); }

 private:
  Fnv1a h_;
};

}  // namespace

std::string model_fingerprint(const StructuralModel& model, const ElementList& elements) {
  ModelHash h;
  h.integer(static_cast<long long>(model.dof_names.size()));
  for (const std::string& name : model.dof_names) h.text(name);
  h.matrix(model.mass);
  h.matrix(model.damping);
  h.matrix(model.stiffness);
  h.integer(static_cast<long long>(model.forcing.size()));
  for (const HarmonicForce& f : model.forcing) {
    h.integer(f.order);
    h.matrix(f.cos_part);
    h.matrix(f.sin_part);
  }
  if (model.forcing_growth.active()) {  // only then: the fingerprints of fixed forcings stay as they were
    h.number(model.forcing_growth.exponent);
    h.number(model.forcing_growth.reference_frequency);
  }
  h.integer(static_cast<long long>(elements.size()));
  for (const auto& e : elements) {
    h.text(e->type());
    h.integer(static_cast<long long>(e->dofs.size()));
    for (int dof : e->dofs) h.integer(dof);
    h.integer(static_cast<long long>(e->properties.size()));
    for (const ParameterBinding& b : e->properties) {
      h.number(b.offset);
      h.number(b.scale);
      h.integer(b.parameter);
    }
    h.number(e->lanczos_exponent);
    h.text(e->configuration());  // a subclass's own state: weights, a law's choice
  }
  return h.hex();
}

}  // namespace hbtrack
