#pragma once
// Ipopt-specific settings of the adapter (ipopt_solver.hpp). The Problem interface provides
// first derivatives only, so the Hessian of the Lagrangian is a quasi-Newton approximation:
// Ipopt's own limited-memory one, or the adapter's dense damped BFGS handed to Ipopt as "exact".

#include <Eigen/Core>

#include <map>
#include <optional>
#include <string>

namespace cyclopt::nlp {

enum class IpoptHessian {
  // Dense damped BFGS of the Lagrangian (lagrangian_bfgs.hpp) through eval_h. The walker gait
  // NLP converges with it; with Ipopt's L-BFGS it does not (bench/results/walker_solvers.txt).
  damped_bfgs,
  limited_memory,  // Ipopt's hessian_approximation=limited-memory
  // Forward differences of the exact Lagrangian gradient at every iteration (difference_hessian.hpp):
  // n evaluations with derivatives per iteration, cheap for a handful of variables and far fewer
  // iterations (the giant swing's minimum-jerk NLP).
  difference,
};

// Multipliers of a nearby KKT point (SolverSummary's convention and sizes), e.g. the previous
// point of a continuation: Ipopt then starts with warm_start_init_point=yes from them and a
// small barrier parameter instead of re-centring the iterate in the 2000 walker inequalities.
struct IpoptWarmStart {
  Eigen::VectorXd equality_multipliers;
  Eigen::VectorXd inequality_multipliers;
  Eigen::VectorXd bound_multipliers;
  double mu_init = 1e-6;  // Ipopt's mu_init for the warm start; > 0
};

struct IpoptOptions {
  IpoptHessian hessian = IpoptHessian::damped_bfgs;
  // damped_bfgs only: the first W is (6.24) of the forward-difference Hessian of the Lagrangian
  // at the start (n extra Jacobians, once) instead of the scaled identity (6.25) - what the SQP's
  // difference_hessian does; without it a start at (or near) a KKT point still needs ~100
  // iterations to rebuild the curvature.
  bool difference_hessian_start = false;
  // damped_bfgs only, > 0: W is reset to (6.24) of a fresh difference Hessian every this many
  // Hessian evaluations (n extra Jacobians each), as SqpOptions::difference_hessian_every.
  int difference_hessian_every = 0;
  int limited_memory_max_history = 6;  // Ipopt's limited_memory_max_history (limited_memory only); >= 1
  // Ipopt's mu_strategy: "monotone" or "adaptive". Adaptive: with the walker's 2003
  // inequalities, monotone mu starting at 0.1 first centres the gait in the inequalities (f rises
  // 50 -> 75 for f_usq) and stalls there with the damped BFGS; a smaller monotone mu_init
  // converges, but to other KKT points than the SQP's (f_mech 0.039059 instead of 0.038974).
  std::string mu_strategy = "adaptive";
  std::optional<IpoptWarmStart> warm_start;
  // Any further Ipopt option by its Ipopt name (e.g. {"nlp_scaling_method", "none"},
  // {"bound_push", 1e-6}), applied after the adapter's own settings, so they override them.
  // An option Ipopt does not know, or a value outside its range, makes the solve throw
  // std::invalid_argument naming the option.
  std::map<std::string, std::string> string_options;
  std::map<std::string, double> numeric_options;
  std::map<std::string, int> integer_options;
};

}  // namespace cyclopt::nlp
