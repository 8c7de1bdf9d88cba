#include "cyclopt/nlp/solver_options.hpp"

namespace cyclopt::nlp {

const char* to_string(Termination t) {
  switch (t) {
    case Termination::converged: return "converged";
    case Termination::acceptable: return "acceptable";
    case Termination::max_iterations: return "max_iterations";
    case Termination::time_limit: return "time_limit";
    case Termination::infeasible: return "infeasible";
    case Termination::evaluation_failure: return "evaluation_failure";
    case Termination::user_stop: return "user_stop";
    case Termination::numerical_failure: return "numerical_failure";
  }
  return "unknown";
}

}  // namespace cyclopt::nlp
