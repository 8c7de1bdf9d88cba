#include "cyclopt/nlp/ipopt_solver.hpp"

#include "cyclopt/nlp/cached_evaluator.hpp"
#include "cyclopt/nlp/damped_bfgs.hpp"
#include "cyclopt/nlp/difference_hessian.hpp"
#include "cyclopt/nlp/kkt_measures.hpp"
#include "cyclopt/nlp/lagrangian_bfgs.hpp"
#include "cyclopt/nlp/wall_clock.hpp"

#include <IpIpoptApplication.hpp>
#include <IpTNLP.hpp>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>

namespace cyclopt::nlp {
namespace {

using Ipopt::Index;
using Ipopt::Number;

// Debian's Ipopt 3.11 factorises with sequential MUMPS, whose Fortran module state is global:
// two Ipopt solves in parallel threads corrupt each other ("PB allocation in DMUMPS_LOAD_INIT").
// Every Ipopt solve in the process therefore holds this lock.
std::mutex& ipopt_mutex() {
  static std::mutex m;
  return m;
}

// Beyond Ipopt's nlp_{lower,upper}_bound_inf (+-1e19): "no bound".
constexpr Number kIpoptInfinity = 2e19;

// eval_h's values: the lower triangle of the symmetric H, row by row (the pattern eval_h declares).
void write_lower_triangle(const Eigen::MatrixXd& H, Number* values) {
  for (Index i = 0, k = 0; i < H.rows(); ++i)
    for (Index j = 0; j <= i; ++j, ++k) values[k] = H(i, j);
}

Number finite_or_ipopt_infinity(double bound) {
  return std::isfinite(bound) ? bound : (bound > 0 ? kIpoptInfinity : -kIpoptInfinity);
}

class ProblemTnlp : public Ipopt::TNLP {
 public:
  enum class StopReason { none, user, time_limit };

  ProblemTnlp(Problem& problem, const SolverOptions& options, const Eigen::VectorXd& x0, SolverSummary& summary)
      : problem_(problem),
        options_(options),
        x0_(x0),
        summary_(summary),
        evaluator_(problem, summary, options.should_stop),
        n_(problem.num_variables()),
        m_eq_(problem.num_equalities()),
        m_in_(problem.num_inequalities()),
        bfgs_(problem.num_variables()),
        restoration_bfgs_(problem.num_variables()),
        start_(Clock::now()) {}

  StopReason stop_reason() const { return stop_reason_; }
  Clock::time_point start() const { return start_; }
  CachedEvaluator& evaluator() { return evaluator_; }

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac_g, Index& nnz_h_lag, IndexStyleEnum& index_style) override {
    n = n_;
    m = m_eq_ + m_in_;
    nnz_jac_g = n * m;
    nnz_h_lag = options_.ipopt.hessian == IpoptHessian::limited_memory ? 0 : n * (n + 1) / 2;
    index_style = C_STYLE;
    return true;
  }

  bool get_bounds_info(Index n, Number* x_l, Number* x_u, Index m, Number* g_l, Number* g_u) override {
    const Eigen::VectorXd lower = problem_.lower_bounds(), upper = problem_.upper_bounds();
    for (Index i = 0; i < n; ++i) {
      x_l[i] = finite_or_ipopt_infinity(lower[i]);
      x_u[i] = finite_or_ipopt_infinity(upper[i]);
    }
    for (Index j = 0; j < m; ++j) {
      g_l[j] = j < m_eq_ ? 0.0 : -kIpoptInfinity;  // c_eq = 0, c_in <= 0 (seed eq. 5.104)
      g_u[j] = 0.0;
    }
    return true;
  }

  // Multipliers are asked for only with warm_start_init_point=yes, which the adapter sets when
  // IpoptOptions::warm_start is given; Ipopt's z_L, z_U >= 0 are the parts of nu = z_U - z_L.
  bool get_starting_point(Index n, bool init_x, Number* x, bool init_z, Number* z_L, Number* z_U, Index m,
                          bool init_lambda, Number* lambda) override {
    const std::optional<IpoptWarmStart>& warm = options_.ipopt.warm_start;
    if (!init_x || ((init_z || init_lambda) && !warm)) return false;
    Eigen::Map<Eigen::VectorXd>(x, n) = x0_;
    if (init_z) {
      Eigen::Map<Eigen::VectorXd>(z_L, n) = (-warm->bound_multipliers).cwiseMax(0.0);
      Eigen::Map<Eigen::VectorXd>(z_U, n) = warm->bound_multipliers.cwiseMax(0.0);
    }
    if (init_lambda) {
      Eigen::Map<Eigen::VectorXd> out(lambda, m);
      out.head(m_eq_) = warm->equality_multipliers;
      out.tail(m_in_) = warm->inequality_multipliers;
    }
    return true;
  }

  bool eval_f(Index n, const Number* x, bool, Number& obj_value) override {
    if (!evaluate(n, x, false)) return false;
    obj_value = evaluator_.evaluation().objective;
    return true;
  }

  bool eval_grad_f(Index n, const Number* x, bool, Number* grad_f) override {
    if (!evaluate(n, x, true)) return false;
    Eigen::Map<Eigen::VectorXd>(grad_f, n) = evaluator_.evaluation().gradient;
    return true;
  }

  bool eval_g(Index n, const Number* x, bool, Index m, Number* g) override {
    if (!evaluate(n, x, false)) return false;
    Eigen::Map<Eigen::VectorXd> out(g, m);
    out.head(m_eq_) = evaluator_.evaluation().equalities;
    out.tail(m_in_) = evaluator_.evaluation().inequalities;
    return true;
  }

  // Dense row-major pattern: entry k = (k / n, k % n).
  bool eval_jac_g(Index n, const Number* x, bool, Index m, Index, Index* iRow, Index* jCol, Number* values) override {
    if (values == nullptr) {
      for (Index k = 0; k < n * m; ++k) {
        iRow[k] = k / n;
        jCol[k] = k % n;
      }
      return true;
    }
    if (!evaluate(n, x, true)) return false;
    using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    Eigen::Map<RowMajor> jac(values, m, n);
    jac.topRows(m_eq_) = evaluator_.evaluation().equality_jacobian;
    jac.bottomRows(m_in_) = evaluator_.evaluation().inequality_jacobian;
    if (options_.ipopt.hessian != IpoptHessian::limited_memory) {
      // eval_h comes for this iterate after trial points may have replaced the cache: keep its
      // derivatives instead of evaluating them a second time.
      iterate_x_ = Eigen::Map<const Eigen::VectorXd>(x, n);
      iterate_ = evaluator_.evaluation();
    }
    return true;
  }

  bool intermediate_callback(Ipopt::AlgorithmMode, Index iter, Number obj_value, Number inf_pr, Number inf_du, Number,
                             Number d_norm, Number, Number, Number, Index, const Ipopt::IpoptData*,
                             Ipopt::IpoptCalculatedQuantities*) override {
    summary_.iterations = iter;
    IterationReport report;
    report.iteration = iter;
    report.objective = obj_value;
    report.constraint_violation = inf_pr;
    report.kkt_error = inf_du;
    report.step_norm = d_norm;
    report.wall_seconds = seconds_since(start_);
    if (options_.on_iteration && !options_.on_iteration(report)) {
      stop_reason_ = StopReason::user;
      return false;
    }
    if (report.wall_seconds > options_.max_wall_seconds) {
      stop_reason_ = StopReason::time_limit;
      return false;
    }
    return true;
  }

  void finalize_solution(Ipopt::SolverReturn, Index n, const Number* x, const Number* z_L, const Number* z_U, Index m,
                         const Number*, const Number* lambda, Number, const Ipopt::IpoptData*,
                         Ipopt::IpoptCalculatedQuantities*) override {
    summary_.x = Eigen::Map<const Eigen::VectorXd>(x, n);
    const Eigen::Map<const Eigen::VectorXd> multipliers(lambda, m);
    summary_.equality_multipliers = multipliers.head(m_eq_);
    summary_.inequality_multipliers = multipliers.tail(m_in_);
    summary_.bound_multipliers = Eigen::Map<const Eigen::VectorXd>(z_U, n) - Eigen::Map<const Eigen::VectorXd>(z_L, n);
  }

  // Lower triangle, row by row: entry k of row i is (i, k), k <= i.
  bool eval_h(Index n, const Number* x, bool, Number obj_factor, Index m, const Number* lambda, bool, Index, Index* iRow,
              Index* jCol, Number* values) override {
    if (values == nullptr) {
      for (Index i = 0, k = 0; i < n; ++i)
        for (Index j = 0; j <= i; ++j, ++k) {
          iRow[k] = i;
          jCol[k] = j;
        }
      return true;
    }
    const Eigen::Map<const Eigen::VectorXd> point(x, n), multipliers(lambda, m);
    if (iterate_x_.size() != n || point != iterate_x_) {
      if (!evaluate(n, x, true)) return false;
      iterate_x_ = point;
      iterate_ = evaluator_.evaluation();
    }
    if (options_.ipopt.hessian == IpoptHessian::difference) {
      const std::optional<Eigen::MatrixXd> H = lagrangian_hessian_by_differences(
          evaluator_, point, iterate_, multipliers.head(m_eq_), multipliers.tail(m_in_), obj_factor);
      if (!H) return false;
      write_lower_triangle(*H, values);
      return true;
    }
    if (obj_factor > 0.0) {
      const int k = objective_hessians_++, every = options_.ipopt.difference_hessian_every;
      const bool refresh = (options_.ipopt.difference_hessian_start && k == 0) || (every > 0 && k > 0 && k % every == 0);
      if (refresh)
        if (const std::optional<Eigen::MatrixXd> H = lagrangian_hessian_by_differences(
                evaluator_, point, iterate_, multipliers.head(m_eq_) / obj_factor, multipliers.tail(m_in_) / obj_factor))
          bfgs_.reset(obj_factor * clamped_hessian(*H));
    }
    // obj_factor = 0: Ipopt's restoration phase (feasibility problem, constraint curvature only).
    LagrangianBfgs& bfgs = obj_factor > 0.0 ? bfgs_ : restoration_bfgs_;
    write_lower_triangle(bfgs.at(point, iterate_, obj_factor, multipliers.head(m_eq_), multipliers.tail(m_in_)), values);
    return true;
  }

 private:
  // Values only for eval_f/eval_g: line-search trial points that Ipopt rejects never pay for
  // the Jacobian (18 ms against 0.3 ms for the walker at P = 200).
  bool evaluate(Index n, const Number* x, bool with_derivatives) {
    return evaluator_.evaluate(Eigen::Map<const Eigen::VectorXd>(x, n), with_derivatives).ok;
  }

  Problem& problem_;
  const SolverOptions& options_;
  Eigen::VectorXd x0_;
  SolverSummary& summary_;
  CachedEvaluator evaluator_;
  const Index n_, m_eq_, m_in_;
  LagrangianBfgs bfgs_, restoration_bfgs_;
  int objective_hessians_ = 0;  // eval_h calls outside the restoration phase
  Eigen::VectorXd iterate_x_;  // the last point of eval_jac_g or eval_h (exact-Hessian modes), and its derivatives
  Evaluation iterate_;
  const Clock::time_point start_;
  StopReason stop_reason_ = StopReason::none;
};

Termination termination_of(Ipopt::ApplicationReturnStatus status, ProblemTnlp::StopReason stop) {
  switch (status) {
    case Ipopt::Solve_Succeeded: return Termination::converged;
    case Ipopt::Solved_To_Acceptable_Level: return Termination::acceptable;
    case Ipopt::Infeasible_Problem_Detected:
    case Ipopt::Restoration_Failed: return Termination::infeasible;
    case Ipopt::Maximum_Iterations_Exceeded: return Termination::max_iterations;
    case Ipopt::Maximum_CpuTime_Exceeded: return Termination::time_limit;
    case Ipopt::User_Requested_Stop:
      return stop == ProblemTnlp::StopReason::time_limit ? Termination::time_limit : Termination::user_stop;
    case Ipopt::Invalid_Number_Detected: return Termination::evaluation_failure;
    default: return Termination::numerical_failure;
  }
}

void reject_option(const std::string& name) {
  throw std::invalid_argument("SolverOptions.ipopt options: Ipopt rejects option '" + name +
                              "' (unknown name, wrong type or value outside its range)");
}

void apply_passthrough_options(const IpoptOptions& ipopt, Ipopt::OptionsList& o) {
  for (const auto& [name, value] : ipopt.string_options)
    if (!o.SetStringValue(name, value)) reject_option(name);
  for (const auto& [name, value] : ipopt.numeric_options)
    if (!o.SetNumericValue(name, value)) reject_option(name);
  for (const auto& [name, value] : ipopt.integer_options)
    if (!o.SetIntegerValue(name, value)) reject_option(name);
}

void check_warm_start(const IpoptWarmStart& warm, const Problem& problem) {
  auto require = [](bool ok, const char* field, int size) {
    if (!ok)
      throw std::invalid_argument(std::string("SolverOptions.ipopt.warm_start.") + field + ": size must be " +
                                  std::to_string(size));
  };
  require(warm.equality_multipliers.size() == problem.num_equalities(), "equality_multipliers", problem.num_equalities());
  require(warm.inequality_multipliers.size() == problem.num_inequalities(), "inequality_multipliers",
          problem.num_inequalities());
  require(warm.bound_multipliers.size() == problem.num_variables(), "bound_multipliers", problem.num_variables());
}

}  // namespace

SolverSummary solve_with_ipopt(Problem& problem, const SolverOptions& options, const Eigen::VectorXd& x0) {
  validate(options);
  if (x0.size() != problem.num_variables())
    throw std::invalid_argument("x0: size must equal num_variables() = " + std::to_string(problem.num_variables()) +
                                ", got " + std::to_string(x0.size()));
  SolverSummary summary;
  const std::lock_guard<std::mutex> lock(ipopt_mutex());
  Ipopt::SmartPtr<ProblemTnlp> tnlp = new ProblemTnlp(problem, options, x0, summary);
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  app->RethrowNonIpoptException(true);
  Ipopt::OptionsList& o = *app->Options();
  o.SetIntegerValue("print_level", options.print_level);
  if (options.print_level == 0) o.SetStringValue("sb", "yes");  // no banner
  if (options.ipopt.hessian == IpoptHessian::limited_memory) {
    o.SetStringValue("hessian_approximation", "limited-memory");
    o.SetIntegerValue("limited_memory_max_history", options.ipopt.limited_memory_max_history);
  }
  if (const std::optional<IpoptWarmStart>& warm = options.ipopt.warm_start) {
    check_warm_start(*warm, problem);
    // A start at a KKT point of a nearby problem: keep it (Ipopt's defaults push iterate and
    // multipliers 1e-2 into the interior and restart at mu = 0.1, i.e. away from it).
    o.SetStringValue("warm_start_init_point", "yes");
    o.SetNumericValue("mu_init", warm->mu_init);
    o.SetNumericValue("warm_start_bound_push", 1e-9);
    o.SetNumericValue("warm_start_slack_bound_push", 1e-9);
    o.SetNumericValue("warm_start_mult_bound_push", 1e-9);
  }
  o.SetStringValue("mu_strategy", options.ipopt.mu_strategy);
  o.SetIntegerValue("max_iter", options.max_iterations);
  o.SetNumericValue("tol", options.optimality_tolerance);
  o.SetNumericValue("dual_inf_tol", options.optimality_tolerance);
  o.SetNumericValue("compl_inf_tol", options.optimality_tolerance);
  o.SetNumericValue("constr_viol_tol", options.constraint_tolerance);
  // Ipopt relaxes every bound (incl. c_in <= 0) by bound_relax_factor (default 1e-8), which
  // leaves violations and objective errors of that size; keep it below the requested tolerance.
  o.SetNumericValue("bound_relax_factor", std::min(1e-8, 0.1 * options.constraint_tolerance));
  if (std::isfinite(options.max_wall_seconds)) o.SetNumericValue("max_cpu_time", options.max_wall_seconds);
  apply_passthrough_options(options.ipopt, o);
  if (app->Initialize("") != Ipopt::Solve_Succeeded) {
    summary.message = "Ipopt initialisation failed";
    return summary;
  }
  const Ipopt::ApplicationReturnStatus status = app->OptimizeTNLP(tnlp);
  summary.termination = termination_of(status, tnlp->stop_reason());
  summary.message = "Ipopt return status " + std::to_string(static_cast<int>(status));
  summary.wall_seconds = seconds_since(tnlp->start());
  if (summary.x.size() != x0.size()) summary.x = x0;  // Ipopt stopped before finalize_solution
  // Objective, violation and KKT error in the common definition (kkt_measures.hpp).
  const Eigen::VectorXd lower = problem.lower_bounds(), upper = problem.upper_bounds();
  CachedEvaluator& evaluator = tnlp->evaluator();
  if (evaluator.evaluate(summary.x, true).ok) {
    const Evaluation& e = evaluator.evaluation();
    summary.objective = e.objective;
    summary.constraint_violation = constraint_violation(e, summary.x, lower, upper);
    if (summary.equality_multipliers.size() == problem.num_equalities())
      summary.kkt_error = lagrangian_gradient(e, summary.equality_multipliers, summary.inequality_multipliers,
                                              summary.bound_multipliers)
                              .lpNorm<Eigen::Infinity>();
  } else if (summary.termination == Termination::numerical_failure || summary.iterations == 0) {
    summary.termination = Termination::evaluation_failure;
    summary.message += ": evaluation failed at the final point";
  }
  if (evaluator.stopped()) {
    summary.termination = Termination::user_stop;
    summary.message += " (stopped by should_stop)";
  }
  if (summary.termination == Termination::converged) summary.optimality = Optimality::kkt;
  return summary;
}

}  // namespace cyclopt::nlp
