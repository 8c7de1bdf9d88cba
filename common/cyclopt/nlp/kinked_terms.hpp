#pragma once
// The kinks an objective declares: terms w max(p(x), 0) of the positive part of smooth functions
// p, which make f nonsmooth where p = 0 (seed 001: f_mech (5.102) integrates max(u q_dot, 0) (5.100)
// over the step; its optima hold joints still, i.e. sit on those kinks). A solver that knows them
// can model them in its subproblem as the l1 terms they are - as the elastic mode (6.10)-(6.14)
// treats violated constraints - and test optimality with their Clarke subgradients
// (sqp_subproblems.hpp, clarke_stationarity.hpp) instead of a gradient that does not exist there.

#include <Eigen/Core>

#include <vector>

namespace cyclopt::nlp {

// One kinked term. Near its kink f behaves as  f_rest + weight * max(p_sample, 0)  with f_rest's
// gradient continuous there. partner >= 0: the term's kink is one of f only where the partner
// sample is at its kink too (the seed's trapezoid rule with zero crossing, Fig. 5.3: the positive
// part of the linear interpolant of two samples is continuously differentiable unless both vanish).
struct KinkedTerm {
  int sample = 0;       // row of KinkedTerms::values / jacobian
  int partner = -1;     // a sample, or -1
  double weight = 0.0;  // > 0: the jump of df/dp_sample across the kink
  double slope = 0.0;   // in [0, weight]: what Evaluation::gradient holds of df/dp_sample through this term
};

struct KinkedTerms {
  Eigen::VectorXd values;    // p_s(x), one per sample
  Eigen::MatrixXd jacobian;  // dp_s/dx, one row per sample
  std::vector<KinkedTerm> terms;
  bool empty() const { return terms.empty(); }
};

// The terms near their kink: |p_s| <= band * |grad p_s|_inf for the sample and, with a partner,
// the partner (at first order within a step of length `band` of its kink); per sample the sums of
// those terms' weights and slopes. Samples ascending. Needs the jacobian.
struct NearKinks {
  std::vector<int> terms;    // indices into KinkedTerms::terms
  std::vector<int> samples;  // the distinct samples of those terms
  Eigen::VectorXd weights;   // per listed sample: w_s, its subgradients are [0, w_s]
  Eigen::VectorXd slopes;    // per listed sample: a_s, what the gradient holds of df/dp_s
  Eigen::Index size() const { return static_cast<Eigen::Index>(samples.size()); }
  bool empty() const { return samples.empty(); }
};

NearKinks near_kinks(const KinkedTerms& kinks, double band);

// The band of near_kinks for a step of relative length `relative_band`: relative_band * max(1, |x|_inf).
double kink_band(const Eigen::VectorXd& x, double relative_band);

// The slopes of `near`'s terms in another evaluation of the same problem (same terms), per listed sample.
Eigen::VectorXd kink_slopes(const KinkedTerms& kinks, const NearKinks& near);

// The rows of `near`'s samples of kinks.jacobian (|near| x n).
Eigen::MatrixXd kink_jacobian(const KinkedTerms& kinks, const NearKinks& near);

}  // namespace cyclopt::nlp
