#include "cyclopt/giant_swing/minimum_jerk_swing.hpp"

#include "cyclopt/nlp/solve.hpp"

#include <chrono>
#include <cmath>

namespace cyclopt::giant_swing {

nlp::SolverOptions minimum_jerk_solver_options() {
  nlp::SolverOptions o;
  o.solver = nlp::SolverKind::ipopt;
  o.max_iterations = 200;
  o.optimality_tolerance = 1e-8;
  o.constraint_tolerance = 1e-10;
  o.ipopt.hessian = nlp::IpoptHessian::difference;
  o.ipopt.mu_strategy = "monotone";  // as measured in bench/results/giant_swing_bench.txt
  return o;
}

Eigen::VectorXd pike_shape(int free_coefficients) {
  Eigen::VectorXd shape = Eigen::VectorXd::Zero(free_coefficients);
  shape.tail(free_coefficients - free_coefficients / 2).setOnes();
  return shape;
}

MinimumJerkResult solve_minimum_jerk(const Model& model, const TaskSpec& spec, const MinimumJerkSettings& settings) {
  const auto t0 = std::chrono::steady_clock::now();
  nlp::validate(settings.solver);
  MinimumJerkProblem problem(model, spec, settings.problem);
  MinimumJerkResult out;
  const Eigen::VectorXd shape = pike_shape(settings.problem.free_coefficients);
  std::optional<Eigen::VectorXd> start;
  for (double amplitude : {1.0, 0.5, 1.5, 0.25})
    if ((start = scale_to_close(problem, shape, amplitude))) break;
  if (!start) {
    out.message = "no closed start swing: Newton on the pike amplitude did not converge";
  } else {
    nlp::Evaluation e;
    problem.evaluate(*start, false, e);
    out.start_jerk = e.objective;
    out.summary = nlp::solve(problem, settings.solver, *start);
    out.coefficients = out.summary.x;
    const ReducedSwing<double> s = problem.swing(out.coefficients);
    if (!s.ok) {
      out.message = "the solver's final point does not complete the swing";
    } else {
      out.jerk = s.end[2];
      out.boundary_error = std::sqrt(s.end[0]) / spec.omega - 1.0;
      out.friction_loss = s.end[3];
      out.torque_integral = s.end[4];
      out.ok = out.summary.success() && std::abs(out.boundary_error) <= kBoundaryTolerance;
      if (!out.ok)
        out.message = std::string("solver ") + nlp::to_string(out.summary.termination) + ": " + out.summary.message;
    }
  }
  out.integrations = problem.integrations();
  out.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace cyclopt::giant_swing
