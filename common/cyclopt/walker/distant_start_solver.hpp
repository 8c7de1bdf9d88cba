#pragma once
// Solver settings for a gait optimisation from a distant start (the automatic starting gait, a
// perturbed gait of a multistart, a neighbouring curve's optimum), shared by the optimise and
// multistart jobs, the speed sweep and the foot design.

#include "cyclopt/nlp/solver_options.hpp"

namespace cyclopt::walker {

// Hessian refresh period of distant_start_solver (iterations of the SQP, Hessian evaluations of
// Ipopt): 50 costs ~n/50 = 0.6 Jacobians per iteration for the walker's n ~ 30.
inline constexpr int kDistantStartHessianRefresh = 50;

// SqpOptions::progress_window of the multistart solves of the speed sweep and of the foot design
// (not in the seed; the design's figures at foot_design.cpp): a solve that makes no progress in f,
// feasibility or KKT error over this many iterations ends as stalled instead of crawling to
// MaxIter. P2-shoes HMT, 20 perturbed starts (bench/results/speed_sweep_bench.txt):
// 0.3 m/s 0/20 KKT either way, 7994 instead of 28567 iterations; 1.3 m/s the same best optimum,
// 19/20 KKT (one run that converged after 1075 iterations to the 4th best optimum stalls at 885);
// the whole 21-speed sweep 512 instead of 1056 s with a 10 % lower mean f_mech.
inline constexpr int kMultistartProgressWindow = 200;

// SqpOptions::max_qp_iterations of distant_start_solver (not in the seed). The rho 10 foot design
// multistart (bench/results/foot_design_bench.txt) had one run of 20 stuck in the l1-relaxed mode:
// 366 of its 466 iterations relaxed, 1.26 million active-set iterations (elastic QPs of up to 154
// variables, ~3000 iterations per SQP iteration), 146 s of the multistart's 372 s of solves, ending
// at MaxIter with f 0.598. The other 19 took 170-18695 active-set iterations in all. With this
// budget that run ends after 149 iterations (38.5 s); the other runs, the design, its sweeps and
// the study's answer are unchanged, and the multistart takes 144 s instead of 194-215 s.
inline constexpr int kDistantStartQpIterations = 200000;

// `solver` with the Hessian approximation started from W_1 of (6.24) on the forward-difference
// Hessian of the Lagrangian, as the seed's SQP (W_1 = I is only its comparison with fmincon), and
// refreshed the same way every kDistantStartHessianRefresh iterations (not in the seed) - for the
// SQP and for Ipopt's damped BFGS alike. Measured from the automatic starting gait and from
// perturbed starts (bench/results/walker_solvers.txt, multistart_bench.txt): the damped BFGS
// update alone crawls for thousands of iterations on rolling feet (P2-shoes HMT at 1.3 m/s: one of
// 8 perturbed starts at MaxIter, 5547 iterations for 8; with the refresh 8/8 KKT in 1637), and
// Ipopt reaches a KKT point from the starting gait on HM and HMT feet only with it.
// hessian_refresh: the period; 0 keeps W_1 only (the design multistart, foot_design.cpp). The SQP
// also stops after kDistantStartQpIterations active-set iterations of its subproblems.
nlp::SolverOptions distant_start_solver(nlp::SolverOptions solver, int hessian_refresh = kDistantStartHessianRefresh);

}  // namespace cyclopt::walker
