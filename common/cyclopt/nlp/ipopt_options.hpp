#pragma once
// Ipopt-specific settings of the adapter (ipopt_solver.hpp). The Problem interface provides
// first derivatives only, so the Hessian is always Ipopt's limited-memory (L-BFGS) approximation.

#include <string>

namespace cyclopt::nlp {

struct IpoptOptions {
  int limited_memory_max_history = 6;  // Ipopt's limited_memory_max_history; >= 1
  std::string mu_strategy = "monotone";  // Ipopt's mu_strategy: "monotone" or "adaptive"
};

}  // namespace cyclopt::nlp
