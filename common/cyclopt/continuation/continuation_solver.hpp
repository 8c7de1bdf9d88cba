#pragma once
// Predictor-corrector continuation of a local optimum of (7.1) over the requested parameter
// values p_0, p_1, ..., p_Q (seed 001, section 7.2, Algorithm 2).
//
// Predictor::qp (the QPSQP method): the trust region Delta_k bounds the step; Delta p_k is cut to
// hit the next requested value exactly without shrinking Delta_k (step 2); the QP predictor
// (qp_predictor.hpp) is accepted when both steps pass (6.19) and kappa (7.2) < 1, else Delta_k is
// reduced by tau (tau^2 if already d_1 failed) down to Delta_min, where the try is accepted
// anyway (steps 16-18); after an accepted step Delta_{k+1} = min(Delta_max, Delta_k / tau); the
// corrector starts from x_{k+1,0} with W_{k+1,0} as initial SQP Hessian (step 19).
// Predictor::trivial: the corrector starts from x_k at p_k + Delta p, Delta p fixed
// (ContinuationOptions::fixed_step, towards p_Q) or stepping to each requested value.
//
// Beyond the seed: a corrector that fails (no KKT point) is retried from x_k with the step
// shortened (tau^2 for the QP predictor, halved for the trivial one) until |Delta p| <= Delta_min,
// where the run stops; the failed solve is still reported as a non-converged point. Every
// converged point is tested for a jump to another curve (curve_jump.hpp); a jump gives the new
// point a fresh curve id and is listed in ContinuationResult::jumps.
#include "cyclopt/continuation/continuation_options.hpp"
#include "cyclopt/continuation/parametric_problem.hpp"
#include "cyclopt/continuation/solution_curve.hpp"
#include <Eigen/Core>
#include <functional>
#include <vector>

namespace cyclopt::continuation {

struct CurveStart {
  int curve_id = 0;       // id of the curve through the first point
  int next_curve_id = 1;  // id given to the first curve jumped to, then counted up
};

// Called with every point as soon as it is solved; returning false stops the run.
using PointCallback = std::function<bool(const CurvePoint&)>;
// Called after every converged point the run goes on from, with where it stands (solution_curve.hpp).
using StateCallback = std::function<void(const RunState&)>;

// parameters: p_0 (where x0 is solved first, step 1), then p_1..p_Q, strictly monotone (either
// direction). Throws std::invalid_argument for invalid options or parameters.
ContinuationResult continue_solution(const ParametricProblem& family, const Eigen::VectorXd& x0,
                                     const std::vector<double>& parameters, const ContinuationOptions& options,
                                     const CurveStart& start = {}, const PointCallback& on_point = {},
                                     const StateCallback& on_state = {});
// The same run resumed from `state` (an on_state of an earlier call with the same family, x0,
// parameters, options and start): its points so far are not solved or passed to on_point again.
ContinuationResult resume_solution(const ParametricProblem& family, const RunState& state,
                                   const std::vector<double>& parameters, const ContinuationOptions& options,
                                   const PointCallback& on_point = {}, const StateCallback& on_state = {});

}  // namespace cyclopt::continuation
