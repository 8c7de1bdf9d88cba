#pragma once
// A solve's end point polished on the manifold of its held joints (held_joints.hpp, issue 52): where
// a run stalls beside a joint held still over the whole step, the gait problem with that joint's
// Bezier coefficients tied (HeldJointProblem) is smooth, and its solve may converge where the
// original one crawls around the held joint's kinks. The manifold's solution is then tested on the
// original problem: a converged result passed the KKT or the nonsmooth (Clarke) test of the original
// problem there (nlp/clarke_stationarity.hpp), never the manifold's test alone. A bench configuration
// (bench/kink_bench.cpp "+held"), not a step of the product's solves: bench/results/kink_bench.txt
// says what it reached and why it is not one.

#include "cyclopt/nlp/solver_options.hpp"
#include "cyclopt/walker/gait_problem.hpp"

#include <optional>
#include <vector>

namespace cyclopt::walker {

struct HeldJointSolveOptions {
  double still_ratio = 1e-3;  // held_joints(): a joint's largest |q_dot| over the fastest joint's, in (0, 1)
};

struct HeldJointSolve {
  std::vector<int> joints;                     // held at the start's end point (empty: no manifold solve)
  std::optional<nlp::SolverSummary> manifold;  // the solve on their manifold
  // The original problem's summary at the better point: the manifold's end point when it is feasible
  // (TolCon) and lower than the start's, converged only where the original problem's tests pass
  // there; else `start` unchanged.
  nlp::SolverSummary result;
};

// `start` is a run of `solver` on GaitProblem(model, options); the manifold is solved with `solver`
// from its end point. Only SQP runs that ended without a KKT point on f_mech with the seed's rule and
// without free model parameters are polished; any other `start` is returned as it is. Throws
// std::invalid_argument for options out of range (naming the field).
HeldJointSolve solve_on_held_joints(const WalkerModel<double>& model, const GaitProblemOptions& options,
                                    const nlp::SolverOptions& solver, const nlp::SolverSummary& start,
                                    const HeldJointSolveOptions& held = {});

}  // namespace cyclopt::walker
