#include "cyclopt/giant_swing/minimum_jerk_problem.hpp"

#include "cyclopt/autodiff/dual.hpp"

#include <stdexcept>
#include <string>

namespace cyclopt::giant_swing {

namespace {

void require(bool ok, const std::string& field, const std::string& range) {
  if (!ok) throw std::invalid_argument("MinimumJerkProblemOptions." + field + ": must be " + range);
}

}  // namespace

MinimumJerkProblem::MinimumJerkProblem(const Model& model, const TaskSpec& spec, const MinimumJerkProblemOptions& options)
    : model_(model), spec_(spec), options_(options), min_rate_(options.min_rate_fraction * spec.omega) {
  require(options.free_coefficients >= kMinFreeBezierCoefficients &&
              options.free_coefficients <= kMaxFreeBezierCoefficients,
          "free_coefficients",
          "in [" + std::to_string(kMinFreeBezierCoefficients) + ", " + std::to_string(kMaxFreeBezierCoefficients) + "]");
  require(options.steps >= 10, "steps", ">= 10");
  require(options.min_rate_fraction >= 0.0 && options.min_rate_fraction < 1.0, "min_rate_fraction", "in [0, 1)");
}

Eigen::VectorXd MinimumJerkProblem::lower_bounds() const {
  return Eigen::VectorXd::Constant(num_variables(), spec_.ranges.alpha_min);
}

Eigen::VectorXd MinimumJerkProblem::upper_bounds() const {
  return Eigen::VectorXd::Constant(num_variables(), spec_.ranges.alpha_max);
}

std::string MinimumJerkProblem::variable_name(int i) const { return "bezier_c" + std::to_string(i + 3); }

std::string MinimumJerkProblem::constraint_name(bool equality, int i) const {
  if (equality) return "phi_rate_end_over_omega_minus_1";
  return "phi_rate_positive_at_node_" + std::to_string(i + 1);
}

ReducedSwing<double> MinimumJerkProblem::swing(const Eigen::VectorXd& x) const {
  return integrate_zero_dynamics(model_, bezier_from_free(x), spec_.initial_rate, options_.steps);
}

nlp::EvaluationStatus MinimumJerkProblem::evaluate(const Eigen::VectorXd& x, bool with_derivatives,
                                                   nlp::Evaluation& out) {
  ++integrations_;
  return dispatch<kMinFreeBezierCoefficients>(x, with_derivatives, out);
}

// Dual<N> needs N at compile time: one instantiation per admissible n.
template <int N>
nlp::EvaluationStatus MinimumJerkProblem::dispatch(const Eigen::VectorXd& x, bool with_derivatives,
                                                   nlp::Evaluation& out) {
  if (x.size() == N) return evaluate_with<N>(x, with_derivatives, out);
  if constexpr (N < kMaxFreeBezierCoefficients) return dispatch<N + 1>(x, with_derivatives, out);
  throw std::invalid_argument("MinimumJerkProblem: x has " + std::to_string(x.size()) + " entries, expected " +
                              std::to_string(num_variables()));
}

template <int N>
nlp::EvaluationStatus MinimumJerkProblem::evaluate_with(const Eigen::VectorXd& x, bool with_derivatives,
                                                        nlp::Evaluation& out) {
  using D = ad::Dual<N>;
  Eigen::Matrix<D, N, 1> free;
  for (int i = 0; i < N; ++i) free[i] = with_derivatives ? D::variable(x[i], i) : D(x[i]);
  // One code path: Dual values equal the double ones; without derivatives the parts stay zero.
  const int steps = options_.steps;
  const ReducedSwing<D> s = integrate_zero_dynamics(model_, bezier_from_free(free), spec_.initial_rate, steps);
  if (!s.ok) return nlp::EvaluationStatus::failure("phi' reached 0 before phi = 2 pi (the swing reverses)");
  const double omega2 = spec_.omega * spec_.omega;
  const D end_rate = ad::sqrt(s.end[0]);
  const D equality = end_rate / spec_.omega - 1.0;
  out.objective = s.end[2].v;
  out.equalities = Eigen::VectorXd::Constant(1, equality.v);
  out.inequalities.resize(steps);
  for (int k = 0; k < steps; ++k) out.inequalities[k] = (min_rate_ * min_rate_ - s.rate_squared[std::size_t(k)].v) / omega2;
  if (with_derivatives) {
    out.gradient = s.end[2].d;
    out.equality_jacobian = equality.d.transpose();
    out.inequality_jacobian.resize(steps, N);
    for (int k = 0; k < steps; ++k) out.inequality_jacobian.row(k) = -s.rate_squared[std::size_t(k)].d.transpose() / omega2;
  }
  return nlp::EvaluationStatus::success();
}

}  // namespace cyclopt::giant_swing

namespace cyclopt::giant_swing {

std::optional<Eigen::VectorXd> scale_to_close(MinimumJerkProblem& problem, const Eigen::VectorXd& shape,
                                              double initial_amplitude, double tolerance, int max_iterations) {
  double a = initial_amplitude;
  nlp::Evaluation e;
  for (int i = 0; i < max_iterations; ++i) {
    if (!problem.evaluate(a * shape, true, e).ok) return std::nullopt;
    const double c = e.equalities[0];
    if (std::abs(c) <= tolerance) return Eigen::VectorXd(a * shape);
    const double slope = e.equality_jacobian.row(0).dot(shape);
    if (slope == 0.0) return std::nullopt;
    a -= c / slope;
  }
  return std::nullopt;
}

}  // namespace cyclopt::giant_swing
