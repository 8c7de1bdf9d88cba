#include "cyclopt/giant_swing/closed_swing_search.hpp"

#include <limits>

namespace cyclopt::giant_swing {

ClosedSwingSearchResult minimise_jerk_over_closed_swings(MinimumJerkProblem& problem, const Eigen::VectorXd& start_shape,
                                                         const nlp::NelderMeadOptions& options) {
  const int before = problem.integrations();
  const Eigen::VectorXd lower = problem.lower_bounds(), upper = problem.upper_bounds();
  auto closed = [&](const Eigen::VectorXd& d) -> std::optional<Eigen::VectorXd> {
    const auto x = scale_to_close(problem, d, 1.0);
    if (!x || (x->array() < lower.array()).any() || (x->array() > upper.array()).any()) return std::nullopt;
    return x;
  };
  auto jerk_of = [&](const Eigen::VectorXd& d) {
    const auto x = closed(d);
    if (!x) return std::numeric_limits<double>::infinity();
    nlp::Evaluation e;
    if (!problem.evaluate(*x, false, e).ok || (e.inequalities.array() > 0.0).any())
      return std::numeric_limits<double>::infinity();
    return e.objective;
  };
  ClosedSwingSearchResult out;
  out.search = nlp::nelder_mead(jerk_of, start_shape, options);
  const auto best = closed(out.search.x);
  out.ok = best.has_value() && std::isfinite(out.search.f);
  if (out.ok) {
    out.coefficients = *best;
    out.jerk = out.search.f;
  }
  out.integrations = problem.integrations() - before;
  return out;
}

}  // namespace cyclopt::giant_swing
