#pragma once
// Downhill simplex (Nelder-Mead) minimiser for functions without derivatives, after the
// Numerical Recipes routines amoeba/amotry that seed 000 uses (ch. 4.1, eq. 4.1-4.8, appendix
// C.1-C.2): trial points p_try(c) = p_s + c (p_ihi - p_s) with c = -1 (reflection), 2 (expansion),
// 0.5 (contraction), and multiple contraction p_i -> (p_i + p_ilo)/2 about the best point.
// Plain option and summary structs (Ceres style).

#include <Eigen/Core>

#include <functional>

namespace cyclopt::nlp {

struct NelderMeadOptions {
  double initial_step = 1.0;     // lambda_0 of eq. 4.2: p_i = p_0 + lambda_0 e_i
  double f_tolerance = 1e-10;    // stop when 2 |f_hi - f_lo| / (|f_hi| + |f_lo|) < f_tolerance
  int max_evaluations = 5000;
};

enum class NelderMeadTermination { converged, max_evaluations };

struct NelderMeadSummary {
  NelderMeadTermination termination = NelderMeadTermination::max_evaluations;
  Eigen::VectorXd x;  // best point
  double f = 0.0;     // f(x)
  int evaluations = 0;
  int iterations = 0;
};

const char* to_string(NelderMeadTermination t);

NelderMeadSummary nelder_mead(const std::function<double(const Eigen::VectorXd&)>& f, const Eigen::VectorXd& x0,
                              const NelderMeadOptions& options);

}  // namespace cyclopt::nlp
