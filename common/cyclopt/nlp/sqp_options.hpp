#pragma once
// Parameters of the seed's SQP line-search method with l1 merit function (seed 001, section
// 6.2.4, Algorithm 1). Defaults are Table 6.2. The tolerances TolOpt/TolCon, MaxIter and MaxTime
// of Table 6.2 live in the generic SolverOptions (see seed_table_6_2_options()).

#include "cyclopt/qp/active_set_solver.hpp"
#include "cyclopt/qp/screened_solve.hpp"

#include <Eigen/Core>

#include <functional>

namespace cyclopt::nlp {

// Issue 52 (not in the seed): the objective's declared kinked terms (Evaluation::kinks, the walker's
// f_mech) near their kink are modelled exactly in the subproblems - an epigraph variable per sample
// (sqp_subproblems.hpp), the QP's multipliers sigma_s in [0, w_s] carrying their curvature into the
// Hessian model - and a point that fails the KKT test of step 2 is accepted when it passes the
// nonsmooth (Clarke) test (clarke_stationarity.hpp) instead. Merit function and line search keep
// the exact objective. Without declared kinks the solver is the seed's.
struct KinkOptions {
  bool enabled = false;
  // Samples within a step of model_band * max(1, |x|_inf) of their kink at first order (|p_s| <=
  // that times |grad p_s|_inf, kinked_terms.hpp; their partners likewise) get their kink in the QP;
  // the others keep their smooth branch. The band shrinks where it models slow zero crossings as
  // kinks (sqp_solver.cpp, shrink_model_band). In (0, 1).
  double model_band = 1e-6;
  // Samples within test_band * max(1, |x|_inf) of their kink may use their Clarke subgradients in
  // the optimality test (the Goldstein-type radius of the nonsmooth test). In (0, model_band].
  double test_band = 1e-9;
  // The inequalities with c_i >= -active_tolerance may carry multipliers in the nonsmooth test (the
  // QP's working set alone would admit rows that are no longer active: no complementarity). >= 0.
  double active_tolerance = 1e-7;
};

struct SqpOptions {
  double initial_penalty = 1.0;         // mu_1 of eq. (6.10); > 0
  double penalty_increase = 2.0;        // rho, steps 4, 6, 7; > 1
  double epsilon1 = 0.1;                // step 6 factor; in (0, 1]
  double epsilon2 = 0.1;                // step 7 factor; in (0, epsilon1] (Algorithm 1: open interval; Table 6.2: equal)
  double armijo = 1e-4;                 // eta of eq. (6.15)/(6.19); in (0, 1)
  double backtracking = 0.7;            // tau, backtracking factor; in (0, 1)
  double relative_min_penalty = 1e-3;   // sigma of eq. (6.9); in (0, 1)
  double initial_trust_radius = 1.0;    // Delta_1 of the LP (6.14); in [Delta_min, Delta_max]
  double min_trust_radius = 1e-3;       // Delta_min; from iteration 2 on relative to |d_2|_inf (step 14); > 0
  double max_trust_radius = 1e3;        // Delta_max; likewise relative; >= Delta_min
  double step_tolerance = 1e-14;        // TolStep: |d_k|_inf below this stops (step 3); > 0
  int max_function_evaluations = 10000;  // MaxFun; >= 1
  // ObjLimit: f below this stops ("objective probably unbounded below"). The OCR of Table 6.2
  // reads 10^-20, which would stop at once on any problem with negative optimum; a lower limit
  // of -10^20 is what the rule of step 18 needs, so that is the default here.
  double objective_limit = -1e20;
  bool second_order_correction = true;  // EQP projection, eqs. (6.16)-(6.19)
  // After step 9 had to shorten d_k to reach a real solution (factor beta < 1), bound the next QP
  // step by |beta d_k|_inf, doubling the bound after every full step (not in the seed; the QP is
  // solved without the box if the box makes it incompatible).
  bool evaluable_step_bound = true;
  // Largest number of backtracking steps (sequence 1, tau, tau^2, ...) before the line search
  // (steps 9 and 12) gives up; 0.7^100 ~ 3e-16.
  int max_backtracking_steps = 100;
  // Optional Hessian of the Lagrangian (eq. (6.23)), e.g. by complex step or AD of the gradients:
  // W_1 is then its eigenvalue-clamped version (6.24). Empty: W_1 = I and W_2 from (6.25), unless
  // difference_hessian.
  bool difference_hessian = false;  // W_1 from (6.24) on forward differences of the exact gradients (difference_hessian.hpp)
  // > 0 (with difference_hessian): W_k is replaced by (6.24) on a fresh difference Hessian every
  // this many iterations instead of the BFGS update (6.22) (not in the seed).
  int difference_hessian_every = 0;
  // > 0: the run ends as `stalled` when, over the last progress_window iterations, the objective
  // fell by less than progress_min_decrease * max(|f|, 1e-8), the constraint violation did not
  // halve and the smallest KKT error did not fall below half the smallest before (not in the
  // seed; the last test spares runs in their final convergence, where f no longer changes).
  // Meant for solves from distant starts, whose runs that end at MaxIter crawl along the kinks of
  // f_mech for thousands of iterations without reaching a KKT point; 0: never.
  int progress_window = 0;
  double progress_min_decrease = 1e-2;  // in (0, 1)
  // > 0: the run ends at max_iterations ("MaxQpIter") once the active-set iterations of its QP
  // subproblems (6.7), (6.13), (6.14) add up to more than this (SolverSummary::qp_iterations; not
  // in the seed). A count, not a time, so a run ends at the same iterate on any machine. Meant for
  // runs stuck in the l1-relaxed mode, whose elastic QPs take thousands of active-set iterations
  // per SQP iteration (walker/distant_start_solver.hpp); 0: never.
  int max_qp_iterations = 0;
  std::function<Eigen::MatrixXd(const Eigen::VectorXd& x, const Eigen::VectorXd& equality_multipliers,
                                const Eigen::VectorXd& inequality_multipliers)>
      lagrangian_hessian;
  qp::ActiveSetOptions qp;  // for the subproblems (6.7), (6.13), (6.14)
  // The subproblems are solved on the inequalities near activity only (screened_solve.hpp; the
  // result is the full subproblem's): a deviation in cost, not in iterates, from the seed.
  qp::ScreeningOptions screening;
  KinkOptions kinks;
};

}  // namespace cyclopt::nlp
