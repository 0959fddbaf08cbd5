#include "hbtrack/results/model_fingerprint.hpp"

#include <cstdint>
#include <cstdio>
#include <cstring>

namespace hbtrack {

namespace {

class Fnv1a {
 public:
  void bytes(const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) hash_ = (hash_ ^ p[i]) * 1099511628211ull;
  }
  void number(double v) { bytes(&v, sizeof v); }
  void integer(long long v) { bytes(&v, sizeof v); }
  // Length first: "ab" + "c" and "a" + "bc" differ.
  void text(const std::string& s) {
    integer(static_cast<long long>(s.size()));
    bytes(s.data(), s.size());
  }
  void matrix(const Eigen::MatrixXd& m) {
    integer(m.rows());
    integer(m.cols());
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      for (Eigen::Index i = 0; i < m.rows(); ++i) number(m(i, j));
  }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 14695981039346656037ull;
};

}  // namespace

std::string model_fingerprint(const StructuralModel& model, const ElementList& elements) {
  Fnv1a h;
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
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h.value()));
  return hex;
}

}  // namespace hbtrack
