#pragma once
// Held joints (issue 52). f_mech's optima at low speed hold a joint still over the whole step: its
// Bezier coefficients alpha_0 .. alpha_M (5.55-5.62) all equal, so q_dot_j vanishes at every grid
// point and every sample of its power u_j q_dot_j (5.100) sits on the kink of max(., 0). Around such
// a point the SQP crawls (bench/results/kink_bench.txt). On the manifold
//
//   alpha_{i+1,j}(x) - alpha_{i,j}(x) = 0,  i = 0 .. M-1,  for every held joint j,
//
// the held joints' powers vanish identically; with their terms left out of f_mech the problem with
// those equalities added (HeldJointProblem) is smooth and is solved like a smooth one. Its solution is a point of the
// original problem; whether it is a (nonsmooth) KKT point of that problem is for the caller to
// test (held_joint_solve.hpp does, with the Clarke test of nlp/clarke_stationarity.hpp).

#include "cyclopt/walker/gait_problem.hpp"

#include <vector>

namespace cyclopt::walker {

// The joints whose largest |q_dot_j| over the grid is at most still_ratio (in (0, 1)) times the
// largest joint's: held still over the whole step.
std::vector<int> held_joints(const PeriodicGait<double>& gait, double still_ratio);

// The gait problem of `options` (f_mech by the seed's rule, no free model parameters: the held rows
// would depend on them) with M equalities per held joint after its speed equality (5.103), and f_mech
// without the held joints' powers.
class HeldJointProblem : public nlp::Problem {
 public:
  // Throws std::invalid_argument naming objective (not f_mech by the seed's rule), free_parameters
  // (when there are any) or joints (an index outside [0, n_b)).
  HeldJointProblem(const WalkerModel<double>& model, const GaitProblemOptions& options, std::vector<int> joints);

  int num_variables() const override { return gait_.num_variables(); }
  int num_equalities() const override;
  int num_inequalities() const override { return gait_.num_inequalities(); }
  Eigen::VectorXd lower_bounds() const override { return gait_.lower_bounds(); }
  Eigen::VectorXd upper_bounds() const override { return gait_.upper_bounds(); }
  nlp::EvaluationStatus evaluate(const Eigen::VectorXd& z, bool with_derivatives, nlp::Evaluation& out) override;
  std::unique_ptr<nlp::Problem> clone() const override { return std::make_unique<HeldJointProblem>(*this); }
  std::string variable_name(int i) const override { return gait_.variable_name(i); }
  std::string constraint_name(bool equality, int i) const override;

  const std::vector<int>& joints() const { return joints_; }

 private:
  void leave_out_held_powers(const PeriodicGait<double>& gait, nlp::Evaluation& out) const;

  WalkerModel<double> model_;
  GaitProblem gait_;
  std::vector<int> joints_;
};

}  // namespace cyclopt::walker
