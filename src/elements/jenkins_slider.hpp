#pragma once
// One Jenkins slider (a spring of stiffness k in series with a Coulomb slider of limit F) along a
// scalar displacement d: its exact periodic steady state over a sampled period, and its return
// mapping over one time step. Shared by elastic_dry_friction (one slider) and iwan (many in
// parallel); the reasoning is in elastic_dry_friction.hpp and docs/elements.md.
#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <vector>

namespace hbtrack {

// The extremes of d over the period, shared by every slider driven by d.
struct SampledRange {
  Eigen::Index imax = 0, imin = 0;
  double max = 0, min = 0;
  explicit SampledRange(const Eigen::VectorXd& d) : max(d.maxCoeff(&imax)), min(d.minCoeff(&imin)) {}
};

// Force samples and their derivatives with respect to k and F over one period.
struct JenkinsPeriod {
  Eigen::VectorXd force, dforce_dstiffness, dforce_dlimit;
};

// The periodic steady state of the slider under the samples d. Appends scale * d f(t) / d d(s)
// to `terms` as (t, s, value) (repeated entries are meant to be summed).
void jenkins_period(const Eigen::VectorXd& d, const SampledRange& range, double stiffness, double limit, double scale, JenkinsPeriod& out,
                    std::vector<Eigen::Triplet<double>>& terms);

// The scalar sensitivities d f(t) / d d(s) of a force w f along d = w.x, spread over the k dofs:
// entry (t + N i, s + N j) = w_i w_j d f(t) / d d(s) of an (N k) x (N k) matrix.
void spread_scalar_sensitivities(const std::vector<Eigen::Triplet<double>>& scalar_terms, const Eigen::VectorXd& weights,
                                 Eigen::Index samples, Eigen::SparseMatrix<double>& out);

// Return mapping from the slider position z to the displacement d: f = k (d - z) if that stays
// within +-F (stick), else +-F with the slider moved to d -+ F/k (slip).
struct JenkinsStep {
  double force = 0, slider = 0;
  double dforce_dd = 0, dforce_dslider = 0, dslider_dd = 0, dslider_dslider = 0;
};
JenkinsStep jenkins_step(double d, double slider, double stiffness, double limit);

}  // namespace hbtrack
