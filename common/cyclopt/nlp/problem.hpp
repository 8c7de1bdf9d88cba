#pragma once
// The nonlinear program every scene hands to a solver (seed 001, eq. 1.1 / section 5.4):
//
//   min_x f(x)   subject to   c_eq(x) = 0,   c_in(x) <= 0,   lower <= x <= upper.
//
// Inequalities follow the seed's sign convention (eq. 5.104: c_u <= 0). Derivatives are dense
// (the walker has ~30 variables and ~2000 constraints). An evaluation may fail - the walker's
// "no real solution" (eq. 5.87) - and solvers must treat that as "step too long", never as a crash.

#include "cyclopt/nlp/kinked_terms.hpp"

#include <Eigen/Core>

#include <memory>
#include <string>

namespace cyclopt::nlp {

// Values (and, on request, first derivatives) of objective and constraints at one x.
struct Evaluation {
  double objective = 0.0;
  Eigen::VectorXd equalities;     // c_eq(x), size num_equalities()
  Eigen::VectorXd inequalities;   // c_in(x), size num_inequalities(); feasible where <= 0
  // Filled only when derivatives were requested:
  Eigen::VectorXd gradient;              // df/dx, size n
  Eigen::MatrixXd equality_jacobian;     // dc_eq/dx, num_equalities() x n
  Eigen::MatrixXd inequality_jacobian;   // dc_in/dx, num_inequalities() x n
  // The objective's kinked terms (kinked_terms.hpp), with derivatives, from problems that declare
  // them (the walker's f_mech); empty otherwise. Solvers that do not use them see f as always.
  KinkedTerms kinks;
};

// Outcome of one evaluation: ok, or a failure with a human-readable reason.
struct EvaluationStatus {
  bool ok = true;
  std::string reason;  // empty when ok
  static EvaluationStatus success() { return {}; }
  static EvaluationStatus failure(std::string why) { return {false, std::move(why)}; }
};

class Problem {
 public:
  virtual ~Problem() = default;
  virtual int num_variables() const = 0;
  virtual int num_equalities() const = 0;
  virtual int num_inequalities() const = 0;
  // Simple bounds; +-infinity where unbounded. Default: unbounded.
  virtual Eigen::VectorXd lower_bounds() const;
  virtual Eigen::VectorXd upper_bounds() const;
  // Evaluates at x; derivatives only if with_derivatives. On failure `out` is unspecified.
  virtual EvaluationStatus evaluate(const Eigen::VectorXd& x, bool with_derivatives, Evaluation& out) = 0;
  // An independent copy for evaluations in another thread (parallel_columns.hpp), or nullptr
  // (the default) where the problem cannot be copied: its evaluations then stay in one thread.
  virtual std::unique_ptr<Problem> clone() const;
  // Optional human-readable names (for reports); default "x[i]", "c_eq[i]", "c_in[i]".
  virtual std::string variable_name(int i) const;
  virtual std::string constraint_name(bool equality, int i) const;
};

}  // namespace cyclopt::nlp
