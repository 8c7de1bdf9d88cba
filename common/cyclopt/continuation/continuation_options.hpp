#pragma once
// Parameters of the continuation (seed 001, Algorithm 2; defaults Table 7.1) and of the simpler
// comparison methods of section 8.2 (trivial predictor: the last solution is the start of the
// next solve, with a fixed parameter step or stepping to each requested value).
#include "cyclopt/nlp/solver_options.hpp"

#include <string>
#include <vector>

namespace cyclopt::continuation {

enum class Predictor {
  qp,       // the QP predictor of Algorithm 2 (two SQP steps, kappa (7.2), trust region)
  trivial,  // x_{k+1,0} = x_k (warm start), no step control
  // Not in the seed: first the direct step from x_k to the next requested value, its corrector
  // (SQP) from W_1 of (6.24) on differences; kept when it converges and test_jump sees no jump,
  // otherwise the QP predictor of Algorithm 2 from x_k up to that value. The fixed step of
  // continuation_bench was ~20x cheaper than QPSQP where the curve is smooth (section 8.2).
  trivial_then_qp,
};
const char* to_string(Predictor p);
// The spec's names of every predictor, in declaration order: "qp", "trivial", "trivial_then_qp".
std::vector<std::string> predictor_names();
// One of predictor_names(); anything else throws std::invalid_argument naming `field` and the names.
Predictor parse_predictor(const std::string& text, const std::string& field = "predictor");
// The job spec's names of ContinuationOptions::reuse_predictor_hessian: "per_point" (true) and
// "per_try" (false, Algorithm 2).
const char* predictor_hessian_name(bool reuse_predictor_hessian);

struct ContinuationOptions {
  Predictor predictor = Predictor::qp;
  // Table 7.1. Delta_1 = |p_2 - p_1| and Delta_max = max |p_{k+1} - p_k| when left at 0.
  double eta = 1e-4;                   // eta of the merit test (6.19); in (0, 1)
  double tau = 0.8;                    // trust-region factor; in (0, 1)
  double initial_trust_region = 0.0;   // Delta_1; >= 0 (0: grid spacing)
  double min_trust_region = 0.002;     // Delta_min; > 0
  double max_trust_region = 0.0;       // Delta_max; >= 0 (0: largest grid spacing)
  // Trivial predictor: parameter step |Delta p| (e.g. 0.2 m/s as in Fig. 8.4) towards the last
  // requested value; 0 steps to each requested value in turn.
  double fixed_step = 0.0;
  // Inequalities with c_u >= -active_tolerance at x_k are active for the multipliers (6.26) of
  // the predictor's Hessians (6.24).
  double active_tolerance = 1e-6;
  // QP predictor: false (Algorithm 2) - every try computes (6.24) at x_k and at x_{k,1}, 2n
  // Jacobians; true - one (6.24) at x_k per continuation point, reused by every try from x_k,
  // and W_2 the BFGS update (6.22) of W_1 (QpPredictorSettings::fresh_second_hessian; not in the
  // seed). P2-shoes HMT speed sweep: the same best f_mech at all 21 speeds for 45 % less CPU
  // (bench/results/speed_sweep_bench.txt); the seed's way stays selectable.
  bool reuse_predictor_hessian = true;
  // Jump to another solution curve (section 8.2: the followed optimum stops existing and the
  // corrector converges elsewhere): the secant |x_{k+1} - x_k|_2 / |Delta p| exceeds
  // jump_slope_factor times that of the previous step on the same curve, and the relative
  // distance |x_{k+1} - x_k|_2 / max(1, |x_k|_2) exceeds jump_min_distance. On the first step of
  // a curve (no previous secant) the relative distance alone decides, against jump_first_distance.
  double jump_slope_factor = 4.0;      // > 1
  double jump_min_distance = 0.02;     // >= 0
  double jump_first_distance = 0.2;    // >= jump_min_distance
  // The corrector (SQP of Algorithm 1 or Ipopt). With the SQP and the QP predictor its initial
  // Hessian is the predictor's W_{k+1,0} (Algorithm 2, step 19).
  nlp::SolverOptions corrector = nlp::seed_table_6_2_options();
};

// Throws std::invalid_argument naming the first field outside its admissible range.
void validate(const ContinuationOptions& options);

}  // namespace cyclopt::continuation
