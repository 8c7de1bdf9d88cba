#include "cyclopt/nlp/cached_evaluator.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace cyclopt::nlp {

CachedEvaluator::CachedEvaluator(Problem& problem, SolverSummary& counts, std::function<bool()> should_stop)
    : problem_(problem), counts_(counts), should_stop_(std::move(should_stop)) {}

const EvaluationStatus& CachedEvaluator::evaluate(const Eigen::VectorXd& x, bool with_derivatives) {
  if (valid_ && x.size() == x_.size() && x == x_ && (has_derivatives_ || !with_derivatives || !status_.ok)) return status_;
  if (stopped_ || (should_stop_ && should_stop_())) {
    stopped_ = true;
    valid_ = false;
    status_ = EvaluationStatus::failure("stopped (should_stop)");
    return status_;
  }
  x_ = x;
  valid_ = true;
  has_derivatives_ = with_derivatives;
  ++(with_derivatives ? counts_.jacobian_evaluations : counts_.function_evaluations);
  status_ = problem_.evaluate(x, with_derivatives, evaluation_);
  if (status_.ok) {
    check_sizes(with_derivatives);
    bool finite = std::isfinite(evaluation_.objective) && evaluation_.equalities.allFinite() && evaluation_.inequalities.allFinite();
    if (with_derivatives)
      finite = finite && evaluation_.gradient.allFinite() && evaluation_.equality_jacobian.allFinite() &&
               evaluation_.inequality_jacobian.allFinite();
    if (!finite) status_ = EvaluationStatus::failure("non-finite value or derivative");
  }
  if (!status_.ok) ++counts_.failed_evaluations;
  return status_;
}

void CachedEvaluator::add_counts(const SolverSummary& helper) {
  counts_.function_evaluations += helper.function_evaluations;
  counts_.jacobian_evaluations += helper.jacobian_evaluations;
  counts_.failed_evaluations += helper.failed_evaluations;
}

void CachedEvaluator::check_sizes(bool with_derivatives) const {
  const Eigen::Index n = problem_.num_variables(), m_eq = problem_.num_equalities(), m_in = problem_.num_inequalities();
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw std::logic_error("Problem::evaluate returned " + what);
  };
  require(evaluation_.equalities.size() == m_eq, "equalities of size " + std::to_string(evaluation_.equalities.size()) +
                                                     ", num_equalities() = " + std::to_string(m_eq));
  require(evaluation_.inequalities.size() == m_in, "inequalities of size " + std::to_string(evaluation_.inequalities.size()) +
                                                       ", num_inequalities() = " + std::to_string(m_in));
  if (!with_derivatives) return;
  require(evaluation_.gradient.size() == n, "gradient of size " + std::to_string(evaluation_.gradient.size()) +
                                                ", num_variables() = " + std::to_string(n));
  require(evaluation_.equality_jacobian.rows() == m_eq && evaluation_.equality_jacobian.cols() == n,
          "equality_jacobian not num_equalities() x num_variables()");
  require(evaluation_.inequality_jacobian.rows() == m_in && evaluation_.inequality_jacobian.cols() == n,
          "inequality_jacobian not num_inequalities() x num_variables()");
  const KinkedTerms& k = evaluation_.kinks;
  const Eigen::Index samples = k.values.size();
  require(k.empty() || (k.jacobian.rows() == samples && k.jacobian.cols() == n),
          "kinks.jacobian not one row per kinks.values entry x num_variables()");
  for (const KinkedTerm& t : k.terms)
    require(t.sample >= 0 && t.sample < samples && t.partner >= -1 && t.partner < samples && t.weight > 0.0,
            "a kinked term with a sample or partner outside [0, " + std::to_string(samples) + ") or a weight <= 0");
}

}  // namespace cyclopt::nlp
