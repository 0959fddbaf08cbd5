// NLvib-style pointwise elements (polynomial_stiffness, power_damper): derivatives against
// finite differences, the case-file form, bad input, and the harmonic-balance Jacobian.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "hbtrack/analysis/nfrc.hpp"
#include "hbtrack/elements/polynomial_elements.hpp"
#include "hbtrack/io/case_file.hpp"
#include "test_support.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_element_library {

using namespace hbtrack;
using Eigen::MatrixXd;
using Eigen::VectorXd;
namespace fs = std::filesystem;

namespace {

// Central differences of every analytic derivative an element returns (x, v, properties).
// Samples are O(1) and h = 1e-6: the O(h^2) truncation error is ~1e-12, so 1e-6 relative
// only fails on a wrong derivative.
void check_derivatives(const NonlinearElement& e, const MatrixXd& x, const MatrixXd& v, const std::vector<double>& props) {
  const int k = e.local_dofs();
  const double h = 1e-6, tol = 1e-6;
  ElementResponse r;
  e.evaluate(x, v, 1.0, props, r, true);
  auto force = [&](const MatrixXd& xx, const MatrixXd& vv, const std::vector<double>& p) {
    ElementResponse out;
    e.evaluate(xx, vv, 1.0, p, out, false);
    return out.force;
  };
  auto expect_close = [&](const MatrixXd& fd, const MatrixXd& analytic, const std::string& what) {
    EXPECT_LT((fd - analytic).cwiseAbs().maxCoeff(), tol * std::max(1.0, fd.cwiseAbs().maxCoeff())) << e.type() << " " << what;
  };
  for (int j = 0; j < k; ++j) {
    MatrixXd xp = x, xm = x, vp = v, vm = v;
    xp.col(j).array() += h, xm.col(j).array() -= h, vp.col(j).array() += h, vm.col(j).array() -= h;
    const MatrixXd fdx = (force(xp, v, props) - force(xm, v, props)) / (2 * h);
    const MatrixXd fdv = (force(x, vp, props) - force(x, vm, props)) / (2 * h);
    for (int i = 0; i < k; ++i) {
      expect_close(fdx.col(i), r.dforce_dx.col(i + k * j), "df" + std::to_string(i) + "/dx" + std::to_string(j));
      if (e.depends_on_velocity())
        expect_close(fdv.col(i), r.dforce_dv.col(i + k * j), "df" + std::to_string(i) + "/dv" + std::to_string(j));
      else
        EXPECT_EQ(fdv.col(i).cwiseAbs().maxCoeff(), 0.0) << e.type() << " ignores velocity";
    }
  }
  for (size_t p = 0; p < props.size(); ++p) {
    auto pp = props, pm = props;
    pp[p] += h, pm[p] -= h;
    expect_close((force(x, v, pp) - force(x, v, pm)) / (2 * h), r.dforce_dproperty.middleCols(static_cast<Eigen::Index>(k * p), k),
                 "df/d" + e.property_names()[p]);
  }
}

MatrixXd samples(int n, int k, double phase) {
  MatrixXd x(n, k);
  for (int t = 0; t < n; ++t)
    for (int j = 0; j < k; ++j) x(t, j) = 1.2 * std::cos(0.37 * t + phase + j) - 0.1 * j;
  x(0, 0) = 0.0;  // a zero sample: 0^p and its derivative
  return x;
}

}  // namespace

TEST(PolynomialStiffness, DerivativesMatchFiniteDifferences) {
  Eigen::MatrixXi p(4, 2);
  p << 3, 0, 1, 2, 2, 1, 0, 0;  // x1^3, x1 x2^2, x1^2 x2, a constant
  PolynomialStiffness e(p);
  e.dofs = {0, 1};
  ASSERT_EQ(e.property_names().size(), 8u);
  EXPECT_EQ(e.property_names()[3], "coefficients[1][1]");
  check_derivatives(e, samples(40, 2, 0.1), samples(40, 2, 0.5), {1.0, 0.0, 0.3, -0.2, 0.0, 0.5, 0.1, -0.1});
}

TEST(PolynomialStiffness, ForceFollowsNlvibsConvention) {
  // f_i = sum_m E(m, i) prod_j x_j^p(m, j), checked at one sample by hand.
  Eigen::MatrixXi p(2, 2);
  p << 3, 0, 1, 2;
  PolynomialStiffness e(p);
  e.dofs = {0, 1};
  ElementResponse r;
  e.evaluate((MatrixXd(1, 2) << 2.0, 3.0).finished(), MatrixXd::Zero(1, 2), 1.0, {1.0, 0.5, 0.0, 2.0}, r, false);
  EXPECT_DOUBLE_EQ(r.force(0, 0), 8.0);                   // 1 * 2^3 + 0 * 2 * 3^2
  EXPECT_DOUBLE_EQ(r.force(0, 1), 0.5 * 8.0 + 2 * 18.0);  // 0.5 * 2^3 + 2 * (2 * 3^2)
}

TEST(PowerDamper, DerivativesMatchFiniteDifferences) {
  for (double exponent : {1.0, 2.0, 2.5, 3.0}) {
    PowerDamper e;
    e.dofs = {0, 1};
    e.weights = (VectorXd(2) << 1.0, -0.5).finished();
    MatrixXd v = samples(40, 2, 0.3);
    v.row(0).setZero();  // zero relative velocity: no log(0) or 0^(p-1) trouble
    check_derivatives(e, samples(40, 2, 0.0), v, {0.7, exponent});
  }
}

TEST(PowerDamper, QuadraticAndCubicLaws) {
  PowerDamper e;
  e.dofs = {0};
  e.weights = VectorXd::Ones(1);
  ElementResponse r;
  const MatrixXd v = (MatrixXd(2, 1) << -2.0, 0.5).finished();
  e.evaluate(MatrixXd::Zero(2, 1), v, 1.0, {0.3, 2.0}, r, false);
  EXPECT_DOUBLE_EQ(r.force(0, 0), -0.3 * 4.0);  // c v |v|
  EXPECT_DOUBLE_EQ(r.force(1, 0), 0.3 * 0.25);
  e.evaluate(MatrixXd::Zero(2, 1), v, 1.0, {0.3, 3.0}, r, false);
  EXPECT_NEAR(r.force(0, 0), -0.3 * 8.0, 1e-15);  // c v^3
}

namespace {

fs::path write_case(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / ("hbtrack_element_library_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const fs::path p = dir / (name + ".toml");
  std::ofstream(p) << text;
  return p;
}

std::string three_dof_case(const std::string& elements) {
  return "[model]\ndofs = [\"a\", \"b\", \"c\"]\nM = {diagonal = [1.0, 1.0, 1.0]}\nK = [[2.0, -1.0, 0.0], [-1.0, 1.0, 0.0], [0.0, 0.0, "
         "1.0]]\n"
         "[damping]\nrayleigh = [0.0, 0.01]\n[[forcing]]\ndof = \"a\"\ncos = 0.1\n[parameters]\nk3 = 0.5\n" +
         elements + "[continuation]\nomega_start = 0.5\nomega_end = 1.5\n";
}

}  // namespace

TEST(ElementLibraryCase, ExampleLoadsAndItsJacobianMatchesFiniteDifferences) {
  const CaseDefinition c = load_case(test::source_path("examples/polynomial_and_power_damper.toml"));
  ASSERT_EQ(c.elements.size(), 2u);
  EXPECT_EQ(c.elements[0]->type(), "polynomial_stiffness");
  EXPECT_EQ(c.elements[0]->property_values(c.parameters)[0], 0.5);  // bound to k3
  EXPECT_EQ(c.elements[1]->type(), "power_damper");
  // The AFT Jacobian (Toeplitz-plus-Hankel blocks of the pointwise derivatives) against central
  // differences of the residual: smooth in x except |v| at v = 0 (C1), error O(h^2) ~ 1e-12.
  HarmonicBalance hbm(c.model, c.elements, c.parameters, c.harmonic_balance);
  VectorXd x = hbm.linear_solution(0.9) * 20.0;
  for (Eigen::Index i = 0; i < x.size(); ++i) x(i) += 0.01 * std::cos(3.0 * static_cast<double>(i));
  EXPECT_LT(test::residual_jacobian_error(hbm, x, 0.9, 1e-6), 1e-6);
  // Tracking a coefficient: d r / d k3 against a difference in the parameter.
  const int k3 = c.parameters.find("k3");
  const VectorXd analytic = hbm.parameter_derivative(x, 0.9, k3);
  auto residual_at = [&](double value) {
    hbm.set_parameter(k3, value);
    VectorXd ry;
    hbm.evaluate(x, 0.9, ry, nullptr, nullptr);
    return ry;
  };
  const VectorXd fd_k3 = (residual_at(0.5 + 1e-6) - residual_at(0.5 - 1e-6)) / 2e-6;
  residual_at(0.5);
  EXPECT_LT(test::relative_error(analytic, fd_k3), 1e-6);
}

TEST(ElementLibraryCase, BadInputIsOneClearLine) {
  struct Bad {
    const char* name;
    std::string elements;
    const char* expected;
  };
  const std::vector<Bad> cases{
      {"ragged_exponents",
       "[[elements]]\ntype = \"polynomial_stiffness\"\ndofs = [\"a\", \"b\"]\nexponents = [[3, 0], [1]]\ncoefficients = [[1.0, 0.0], [0.0, "
       "1.0]]\n",
       "elements[0].exponents[1]: every row needs the same length"},
      {"negative_exponent", "[[elements]]\ntype = \"polynomial_stiffness\"\ndofs = [\"a\"]\nexponents = [[-1]]\ncoefficients = [[1.0]]\n",
       "elements[0].exponents[0][0]: must be an integer in [0, 64]"},
      {"exponents_vs_dofs",
       "[[elements]]\ntype = \"polynomial_stiffness\"\ndofs = [\"a\", \"b\"]\nexponents = [[3]]\ncoefficients = [[1.0, 0.0]]\n",
       "elements[0].exponents: expected one exponent per dof (2)"},
      {"coefficient_rows",
       "[[elements]]\ntype = \"polynomial_stiffness\"\ndofs = [\"a\"]\nexponents = [[3], [2]]\ncoefficients = [[1.0]]\n",
       "elements[0].coefficients: expected one row per monomial (2)"},
      {"unknown_coefficient_parameter",
       "[[elements]]\ntype = \"polynomial_stiffness\"\ndofs = [\"a\"]\nexponents = [[3]]\ncoefficients = [[\"k4\"]]\n",
       "elements[0].coefficients[0][0]: unknown parameter 'k4'"},
      {"damper_exponent", "[[elements]]\ntype = \"power_damper\"\ndofs = [\"a\"]\ncoefficient = 1.0\nexponent = 0.5\n",
       "elements[0].exponent: must be >= 1"},
      {"jenkins_limit", "[[elements]]\ntype = \"elastic_dry_friction\"\ndofs = [\"a\"]\nstiffness = 1.0\nlimit_force = -1.0\n",
       "elements[0].limit_force: must be >= 0"},
      {"jenkins_missing_stiffness", "[[elements]]\ntype = \"elastic_dry_friction\"\ndofs = [\"a\"]\nlimit_force = 1.0\n",
       "elements[0].stiffness: missing"},
      {"tip_friction",
       "[[elements]]\ntype = \"tip_contact\"\ndofs = [\"a\", \"b\", \"c\"]\nstiffness = 1.0\nclearance = 0.1\nwidth = 0.1\nmu = "
       "0.2\nradius = 0.3\nfriction = \"sticky\"\n",
       "elements[0].friction: must be \"sliding\" or \"stick_slip\""},
      {"tip_stick_slip_stiffness",
       "[[elements]]\ntype = \"tip_contact\"\ndofs = [\"a\", \"b\", \"c\"]\nstiffness = 1.0\nclearance = 0.1\nwidth = 0.1\nmu = "
       "0.2\nradius = 0.3\nfriction = \"stick_slip\"\n",
       "elements[0].tangential_stiffness: missing (required for tip_contact)"},
      {"tip_sliding_stiffness",
       "[[elements]]\ntype = \"tip_contact\"\ndofs = [\"a\", \"b\", \"c\"]\nstiffness = 1.0\nclearance = 0.1\nwidth = 0.1\nmu = "
       "0.2\nradius = 0.3\ntangential_stiffness = 5.0\n",
       "elements[0].tangential_stiffness: unknown key"},
      {"tip_sliding_engine_order",
       "[[elements]]\ntype = \"tip_contact\"\ndofs = [\"a\", \"b\", \"c\"]\nstiffness = 1.0\nclearance = 0.1\nwidth = 0.1\nmu = "
       "0.2\nradius = 0.3\nengine_order = 0.0\n",
       "elements[0].engine_order: must be nonzero"},
      {"iwan_chi", "[[elements]]\ntype = \"iwan\"\ndofs = [\"a\"]\nlimit_force = 1.0\nstiffness = 3.0\nchi = -1.0\nbeta = 0.1\n",
       "elements[0].chi: must be > -1"},
      {"iwan_beta", "[[elements]]\ntype = \"iwan\"\ndofs = [\"a\"]\nlimit_force = 1.0\nstiffness = 3.0\nchi = -0.5\nbeta = -0.1\n",
       "elements[0].beta: must be >= 0"},
      {"iwan_limit", "[[elements]]\ntype = \"iwan\"\ndofs = [\"a\"]\nlimit_force = 0.0\nstiffness = 3.0\nchi = -0.5\nbeta = 0.1\n",
       "elements[0].limit_force: must be > 0"},
      {"iwan_sliders",
       "[[elements]]\ntype = \"iwan\"\ndofs = [\"a\"]\nlimit_force = 1.0\nstiffness = 3.0\nchi = -0.5\nbeta = 0.1\nsliders = 1.5\n",
       "elements[0].sliders: expected an integer"},
  };
  for (const Bad& bad : cases) {
    const fs::path p = write_case(bad.name, three_dof_case(bad.elements));
    try {
      load_case(p.string());
      ADD_FAILURE() << bad.name << ": no error";
    } catch (const CaseError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find(bad.expected), std::string::npos) << bad.name << ": got '" << msg << "'";
      EXPECT_EQ(msg.find('\n'), std::string::npos) << bad.name << ": not one line";
    }
  }
}

}  // namespace hbtrack_tests::file_element_library
