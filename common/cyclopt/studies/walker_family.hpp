#pragma once
// The walker's NLP of seed 001 section 5.4 as a family over one scalar parameter: the mean speed
// v_bar ("speed", GaitProblemOptions::speed) or any named model parameter of p_mod (5.91), e.g.
// a foot length for the sensitivity study of section 10.1.
#include "cyclopt/continuation/parametric_problem.hpp"
#include "cyclopt/walker/gait_problem.hpp"
#include <string>

namespace cyclopt::studies {

using continuation::ParametricProblem;

// parameter: "speed" or a name from walker::model_parameter_names(model) (not one of the problem's
// free parameters). Throws std::invalid_argument naming the parameter and the valid names.
ParametricProblem walker_family(const walker::WalkerModel<double>& model, const walker::GaitProblemOptions& options,
                                const std::string& parameter);

}  // namespace cyclopt::studies
