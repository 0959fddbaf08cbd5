// The model's fingerprint covers what each element subclass keeps outside the base class
// (NonlinearElement::configuration): an edit there is another model, which --resume refuses.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "hbtrack/elements/elastic_dry_friction_2d.hpp"
#include "hbtrack/elements/frictional_contact.hpp"
#include "hbtrack/elements/iwan.hpp"
#include "hbtrack/elements/polynomial_elements.hpp"
#include "hbtrack/elements/scalar_elements.hpp"
#include "hbtrack/elements/tip_contact.hpp"
#include "hbtrack/results/model_fingerprint.hpp"

// File-local names in a namespace of this file's own: unity builds compile several test files
// as one.
namespace hbtrack_tests::file_model_fingerprint {

using namespace hbtrack;

namespace {

// The fingerprint of a 1-dof model (3 for the elements with more local dofs) holding `element`.
std::string fingerprint_with(const std::shared_ptr<NonlinearElement>& element, int dofs = 1) {
  StructuralModel model;
  for (int i = 0; i < dofs; ++i) model.dof_names.push_back("x" + std::to_string(i + 1));
  model.mass = model.stiffness = Eigen::MatrixXd::Identity(dofs, dofs);
  model.damping = Eigen::MatrixXd::Zero(dofs, dofs);
  for (int i = 0; i < dofs; ++i) element->dofs.push_back(i);
  return model_fingerprint(model, {element});
}

std::shared_ptr<NonlinearElement> weighted(std::shared_ptr<ScalarElement> element, double weight) {
  element->weights = Eigen::VectorXd::Constant(1, weight);
  return element;
}

// A planar slider on two dofs whose second direction is (sin a, cos a).
std::shared_ptr<NonlinearElement> planar(double a) {
  auto element = std::make_shared<ElasticDryFriction2D>();
  element->weights = (Eigen::MatrixXd(2, 2) << 1.0, 0.0, std::sin(a), std::cos(a)).finished();
  return element;
}

}  // namespace

TEST(ModelFingerprint, EachElementsOwnStateIsPartOfIt) {
  struct Variant {
    const char* what;
    std::function<std::shared_ptr<NonlinearElement>(bool edited)> make;
    int dofs = 1;
  };
  const std::vector<Variant> variants = {
      {"cubic spring's weights", [](bool e) { return weighted(std::make_shared<CubicSpring>(), e ? 1.5 : 1.0); }},
      {"a weight's last bit", [](bool e) { return weighted(std::make_shared<CubicSpring>(), e ? std::nextafter(1.0, 2.0) : 1.0); }},
      {"contact law",
       [](bool e) {
         return weighted(std::make_shared<GapContact>(e ? ContactLawKind::sqrt : ContactLawKind::polynomial, "regularized_contact"), 1.0);
       }},
      {"Iwan sliders", [](bool e) { return weighted(std::make_shared<Iwan>(e ? 60 : 50), 1.0); }},
      {"tip contact law", [](bool e) { return std::make_shared<TipContact>(e ? ContactLawKind::penalty : ContactLawKind::polynomial); }, 3},
      {"tip friction",
       [](bool e) { return std::make_shared<TipContact>(ContactLawKind::polynomial, e ? TipFriction::stick_slip : TipFriction::sliding); },
       3},
      {"frictional contact formulation",
       [](bool e) { return std::make_shared<FrictionalContact>(e ? ContactFormulation::dlft : ContactFormulation::penalty); }, 2},
      {"planar slider's second direction", [](bool e) { return planar(e ? 0.1 : 0.0); }, 2},
      {"planar slider's last bit", [](bool e) { return planar(e ? std::nextafter(0.0, 1.0) : 0.0); }, 2},
      {"frictional contact in two directions",
       [](bool e) { return std::make_shared<FrictionalContact>(ContactFormulation::penalty, e ? 2 : 1); }, 3},
      {"polynomial exponents", [](bool e) { return std::make_shared<PolynomialStiffness>(Eigen::MatrixXi::Constant(1, 1, e ? 2 : 3)); }},
  };
  for (const Variant& v : variants) {
    const std::string original = fingerprint_with(v.make(false), v.dofs);
    EXPECT_EQ(fingerprint_with(v.make(false), v.dofs), original) << v.what << ": the same model hashed differently";
    EXPECT_NE(fingerprint_with(v.make(true), v.dofs), original) << v.what << ": an edit left the fingerprint unchanged";
  }
}

}  // namespace hbtrack_tests::file_model_fingerprint
