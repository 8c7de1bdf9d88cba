#pragma once
// The family of NLPs (7.1) over a scalar parameter p that a continuation follows (seed 001,
// section 7.2): min_x f(x, p) s.t. c_g(x, p) = 0, c_u(x, p) <= 0. Every p gets its own Problem
// (problems hold workspace); all of them have the same variables.
#include "cyclopt/nlp/problem.hpp"
#include <functional>
#include <memory>
#include <string>

namespace cyclopt::continuation {

struct ParametricProblem {
  std::string parameter_name;                                     // for reports, e.g. "speed" or "l_HM"
  std::function<std::unique_ptr<nlp::Problem>(double p)> at;      // the NLP (7.1) at p
};

}  // namespace cyclopt::continuation
