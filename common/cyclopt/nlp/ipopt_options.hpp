#pragma once
// Ipopt-specific settings of the adapter (ipopt_solver.hpp). The Problem interface provides
// first derivatives only, so the Hessian is Ipopt's limited-memory (L-BFGS) approximation, or, with
// difference_hessian, forward differences of the exact Lagrangian gradient (n evaluations with
// derivatives per Ipopt iteration: cheap for a handful of variables, and far fewer iterations).

#include <map>
#include <string>

namespace cyclopt::nlp {

struct IpoptOptions {
  int limited_memory_max_history = 6;  // Ipopt's limited_memory_max_history; >= 1
  bool difference_hessian = false;     // hessian_approximation "exact" from difference_hessian.hpp
  std::string mu_strategy = "monotone";  // Ipopt's mu_strategy: "monotone" or "adaptive"
  // Any further Ipopt option by its Ipopt name (e.g. {"nlp_scaling_method", "none"},
  // {"bound_push", 1e-6}), applied after the adapter's own settings, so they override them.
  // An option Ipopt does not know, or a value outside its range, makes the solve throw
  // std::invalid_argument naming the option.
  std::map<std::string, std::string> string_options;
  std::map<std::string, double> numeric_options;
  std::map<std::string, int> integer_options;
};

}  // namespace cyclopt::nlp
