#pragma once
// Part B of issue 6 as an NLP (nlp::Problem): minimum jerk on the virtual constraint alpha = b(phi)
// with the boundary conditions as constraints instead of penalty weights (seed 000 eq. 4.10 turns
// them into weighted terms; here they hold exactly):
//   variables   the n free Bezier coefficients c3..c(n+2), n = 4..12 (virtual_constraint.hpp);
//               alpha, alpha', alpha'' = 0 at phi = 0 and 2 pi hold by construction (eq. 3.10-3.11)
//   bounds      alpha_min <= c_i <= alpha_max (convex hull: the admissible range of ch. 4.2)
//   objective   1/2 int alpha'''^2 dt over one swing (eq. 4.12)
//   equality    phi'(2 pi) / omega - 1 = 0 (eq. 3.12; start rate per task: omega, omega/2, 2 omega)
//   inequality  min_rate^2 - phi'^2(phi_k) <= 0 at every integration node (phi' > 0, ch. 4.2)
// Derivatives are exact (ad::Dual<n> through the fixed-step zero dynamics). Each evaluation is one
// model integration, with or without sensitivities (counted, for comparison with the seed's method).

#include "cyclopt/giant_swing/task_spec.hpp"
#include "cyclopt/giant_swing/zero_dynamics.hpp"
#include "cyclopt/nlp/problem.hpp"

#include <optional>

namespace cyclopt::giant_swing {

struct MinimumJerkProblemOptions {
  int free_coefficients = 8;        // n in [4, 12]: Bezier degree n + 5
  int steps = 200;                  // fixed Cash-Karp steps per swing, >= 10
  double min_rate_fraction = 0.05;  // phi' >= fraction * omega at every node, in [0, 1)
};

class MinimumJerkProblem : public nlp::Problem {
 public:
  // Throws std::invalid_argument naming the option outside its range.
  MinimumJerkProblem(const Model& model, const TaskSpec& spec, const MinimumJerkProblemOptions& options = {});

  int num_variables() const override { return options_.free_coefficients; }
  int num_equalities() const override { return 1; }
  int num_inequalities() const override { return options_.steps; }
  Eigen::VectorXd lower_bounds() const override;
  Eigen::VectorXd upper_bounds() const override;
  nlp::EvaluationStatus evaluate(const Eigen::VectorXd& x, bool with_derivatives, nlp::Evaluation& out) override;
  std::string variable_name(int i) const override;
  std::string constraint_name(bool equality, int i) const override;

  int integrations() const { return integrations_; }
  const TaskSpec& spec() const { return spec_; }
  // The swing for coefficients x (values only; not counted).
  ReducedSwing<double> swing(const Eigen::VectorXd& x) const;

 private:
  template <int N>
  nlp::EvaluationStatus evaluate_with(const Eigen::VectorXd& x, bool with_derivatives, nlp::Evaluation& out);
  template <int N>
  nlp::EvaluationStatus dispatch(const Eigen::VectorXd& x, bool with_derivatives, nlp::Evaluation& out);

  Model model_;
  TaskSpec spec_;
  MinimumJerkProblemOptions options_;
  double min_rate_;
  int integrations_ = 0;
};

}  // namespace cyclopt::giant_swing

namespace cyclopt::giant_swing {

// Newton on the amplitude a of x = a * shape until the boundary equality phi'(2 pi) = omega holds
// (exact derivative from the problem); |equality| <= tolerance on success. A closed swing on its
// own and a feasible start point for an NLP solver. Returns nullopt if it does not converge.
std::optional<Eigen::VectorXd> scale_to_close(MinimumJerkProblem& problem, const Eigen::VectorXd& shape,
                                              double initial_amplitude, double tolerance = 1e-13,
                                              int max_iterations = 30);

}  // namespace cyclopt::giant_swing
