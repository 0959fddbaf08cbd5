#pragma once
// The periodic state of frictional_contact's penalty law over sampled [x_n, x_t] or, in two
// tangential directions (frictional_contact_2d), [x_n, x_t1, x_t2] (properties
// normal_stiffness, tangential_stiffness, mu, normal_preload): forces, sensitivity operator and
// property derivatives. The DLFT law applies it to the prediction lambda / epsilon.
#include "hbtrack/elements/nonlinear_element.hpp"

namespace hbtrack {

void penalty_contact_period(const Eigen::MatrixXd& x, const std::vector<double>& props, ElementResponse& out,
                            bool want_property_derivatives);

}  // namespace hbtrack
