// The element catalogue (the types a case file may name, their keys and properties), and elements
// defined in Python: a callable gets the time samples of the element's displacements and
// velocities (numpy arrays, N x k) and returns the forces (N x k), optionally with their
// derivatives; central differences stand in for the derivatives it does not return.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <cmath>
#include <stdexcept>

#include "bindings.hpp"
#include "hbtrack/elements/element_catalog.hpp"
#include "hbtrack/elements/nonlinear_element.hpp"
#include "hbtrack/io/case_file.hpp"

namespace hbtrack::python {

namespace {

using Eigen::MatrixXd;

class PythonElement final : public NonlinearElement {
 public:
  PythonElement(py::object force, bool uses_velocity, double step) : force_(std::move(force)), uses_velocity_(uses_velocity), step_(step) {}
  // The callable may be the last reference to Python objects: drop it with the GIL held.
  ~PythonElement() override {
    py::gil_scoped_acquire gil;
    force_ = py::object();
  }
  std::string type() const override { return "python"; }
  const std::vector<std::string>& property_names() const override {
    static const std::vector<std::string> none;  // parameters live in the callable's closure
    return none;
  }
  bool depends_on_velocity() const override { return uses_velocity_; }

  void evaluate(const MatrixXd& x, const MatrixXd& v, double /*omega*/, const std::vector<double>& /*properties*/, ElementResponse& out,
                bool want_property_derivatives) const override {
    // The analyses run with the GIL released; a Python error becomes a C++ one here, with the
    // GIL still held for its cleanup.
    py::gil_scoped_acquire gil;
    try {
      const Eigen::Index n = x.rows();
      out.dforce_domega.resize(0, 0);
      out.history_dforce_dx.resize(0, 0);
      if (want_property_derivatives) out.dforce_dproperty.resize(n, 0);
      bool have_dx = false, have_dv = false;
      out.force = call(x, v, &out, &have_dx, &have_dv);
      if (!have_dx) out.dforce_dx = central_difference(x, v, false);
      if (!uses_velocity_) {
        out.dforce_dv.resize(0, 0);
      } else if (!have_dv) {
        out.dforce_dv = central_difference(x, v, true);
      }
    } catch (py::error_already_set& e) {
      throw std::runtime_error(std::string("python element: ") + e.what());
    }
  }

 private:
  // Forces N x k; when `out` is given, the derivatives the callable returned as well.
  MatrixXd call(const MatrixXd& x, const MatrixXd& v, ElementResponse* out, bool* have_dx, bool* have_dv) const {
    const Eigen::Index n = x.rows();
    const int k = local_dofs();
    const py::object result = force_(py::cast(x), py::cast(v));
    py::object force = result;
    if (py::isinstance<py::tuple>(result)) {
      const py::tuple parts = result.cast<py::tuple>();
      if (parts.size() < 1 || parts.size() > 3)
        throw std::invalid_argument("python element: return forces, or (forces, dforce_dx[, dforce_dv])");
      force = parts[0];
      if (out && parts.size() >= 2 && !parts[1].is_none()) {
        out->dforce_dx = derivative(parts[1], n, k, "dforce_dx");
        *have_dx = true;
      }
      if (out && parts.size() == 3 && !parts[2].is_none() && uses_velocity_) {
        out->dforce_dv = derivative(parts[2], n, k, "dforce_dv");
        *have_dv = true;
      }
    }
    const auto f = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(force);
    if (!f || !((f.ndim() == 2 && f.shape(0) == n && f.shape(1) == k) || (k == 1 && f.ndim() == 1 && f.shape(0) == n)))
      throw std::invalid_argument("python element: forces must be an array of shape (N, k) = (" + std::to_string(n) + ", " +
                                  std::to_string(k) + ")");
    MatrixXd forces(n, k);
    const double* data = f.data();
    for (Eigen::Index t = 0; t < n; ++t)
      for (int i = 0; i < k; ++i) forces(t, i) = data[t * k + i];
    return forces;
  }

  // d[t, i, j] = d f_i(t) / d x_j(t) into the ElementResponse layout (column i + k j).
  static MatrixXd derivative(const py::handle& value, Eigen::Index n, int k, const char* name) {
    const auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
    if (!d || d.ndim() != 3 || d.shape(0) != n || d.shape(1) != k || d.shape(2) != k)
      throw std::invalid_argument(std::string("python element: ") + name + " must have shape (N, k, k) = (" + std::to_string(n) + ", " +
                                  std::to_string(k) + ", " + std::to_string(k) + ")");
    MatrixXd out(n, k * k);
    const double* data = d.data();
    for (Eigen::Index t = 0; t < n; ++t)
      for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) out(t, i + k * j) = data[(t * k + i) * k + j];
    return out;
  }

  // Pointwise central differences, one dof column at a time (2k calls), step relative to the
  // signal's size: the truncation error is O(step^2), the round-off O(eps / step).
  MatrixXd central_difference(const MatrixXd& x, const MatrixXd& v, bool of_velocity) const {
    const int k = local_dofs();
    MatrixXd out(x.rows(), k * k);
    for (int j = 0; j < k; ++j) {
      const MatrixXd& base = of_velocity ? v : x;
      const double h = step_ * std::max(1.0, base.col(j).cwiseAbs().maxCoeff());
      MatrixXd plus = base, minus = base;
      plus.col(j).array() += h;
      minus.col(j).array() -= h;
      const MatrixXd fp = of_velocity ? call(x, plus, nullptr, nullptr, nullptr) : call(plus, v, nullptr, nullptr, nullptr);
      const MatrixXd fm = of_velocity ? call(x, minus, nullptr, nullptr, nullptr) : call(minus, v, nullptr, nullptr, nullptr);
      out.middleCols(static_cast<Eigen::Index>(k) * j, k) = (fp - fm) / (2.0 * h);
    }
    return out;
  }

  py::object force_;
  bool uses_velocity_;
  double step_;
};

py::dict key_dict(const ElementKey& key) {
  static const char* kinds[] = {"choice", "integer", "integer_rows", "property_rows"};
  py::dict out;
  out["kind"] = kinds[static_cast<int>(key.kind)];
  if (key.kind == ElementKey::Kind::choice) out["values"] = key.values;
  if (key.kind == ElementKey::Kind::integer || key.kind == ElementKey::Kind::integer_rows) out["range"] = py::make_tuple(key.min, key.max);
  if (key.fallback.empty())
    out["default"] = py::none();
  else if (key.kind == ElementKey::Kind::integer)
    out["default"] = std::stoi(key.fallback);
  else
    out["default"] = key.fallback;
  out["doc"] = key.doc;
  return out;
}

py::dict property_dict(const PropertySpec& p) {
  py::dict out;
  out["unit"] = p.unit;
  out["range"] = to_string(p.range);
  out["default"] = p.fallback ? py::object(py::float_(*p.fallback)) : py::object(py::none());
  out["doc"] = p.doc;
  return out;
}

// {type: {summary, dofs, weighted, directions, keys, variants: [{choices, properties}]}} from the catalogue.
py::dict element_types() {
  py::dict out;
  for (const ElementType& type : element_catalog()) {
    py::dict t, keys;
    t["summary"] = type.summary;
    t["dofs"] = type.dof_names;
    t["weighted"] = type.weighted;
    t["directions"] = type.directions;
    for (const ElementKey& key : type.keys) keys[py::str(key.name)] = key_dict(key);
    t["keys"] = keys;
    py::list variants;
    for (const ElementSetup& setup : element_variants(type)) {
      py::dict variant, properties;
      variant["choices"] = setup.choices;
      for (const PropertySpec& p : type.build(setup).properties) properties[py::str(p.name)] = property_dict(p);
      variant["properties"] = properties;
      variants.append(variant);
    }
    t["variants"] = variants;
    out[py::str(type.type)] = t;
  }
  return out;
}

}  // namespace

void bind_elements(py::module_& m) {
  m.def("element_types", &element_types,
        "The element catalogue: {type: {summary, dofs, weighted, directions, keys, variants: [{choices, properties}]}} "
        "(see hbtrack.element_types)");
  m.def(
      "add_python_element",
      [](CaseDefinition& c, const std::vector<std::string>& dofs, py::object force, bool uses_velocity, double step) {
        if (!PyCallable_Check(force.ptr())) throw std::invalid_argument("force: must be callable");
        if (!(step > 0) || !std::isfinite(step)) throw std::invalid_argument("step: must be > 0");
        if (dofs.empty()) throw std::invalid_argument("dofs: expected at least one dof name");
        auto element = std::make_shared<PythonElement>(std::move(force), uses_velocity, step);
        for (const std::string& name : dofs) {
          const int index = c.model.find_dof(name);
          if (index < 0) throw std::invalid_argument("dofs: unknown dof '" + name + "'");
          for (int d : element->dofs)
            if (d == index) throw std::invalid_argument("dofs: '" + name + "' appears twice");
          element->dofs.push_back(index);
        }
        c.elements.push_back(std::move(element));
      },
      py::arg("case"), py::arg("dofs"), py::arg("force"), py::arg("uses_velocity") = false, py::arg("step") = 1e-6,
      "Appends an element whose forces a Python callable computes (see hbtrack.add_python_element)");
}

}  // namespace hbtrack::python
