#pragma once
// The KKT sensitivities of an optimum (issue 15 item 6): d f*/d p of every model parameter from
// the Lagrangian at the KKT point (kkt_sensitivity.hpp), computed right after a converged solve,
// without a re-solve; the jobs store them with the optimum (records::KktSensitivitiesRecord).
//
// Multipliers: the SQP's are least-squares multipliers on its working set at |grad L| <= TolOpt
// (1e-5 in Table 6.2); they give the derivatives to ~1e-6 relative but classify the nearly active
// rows (weakly active, kink) unreliably. So the optimum is first polished by Ipopt (tolerance
// 1e-11, warm-started with the solve's multipliers, the first BFGS matrix from differences: a few
// iterations, as bench/kkt_sensitivity_bench.cpp validated against re-solves); when the polish
// does not converge the solve's own multipliers are used and `multipliers` says so. Multipliers
// with |grad_z L|_inf > kMaxLagrangianGradient (or a point kkt_sensitivity refuses) give no
// numbers: `unavailable` says why.

#include "cyclopt/studies/kkt_sensitivity.hpp"
#include "cyclopt/walker/gait_optimisation.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace cyclopt::studies {

inline constexpr double kMaxLagrangianGradient = 1e-4;

struct OptimumSensitivities {
  std::string multipliers;  // where the multipliers came from: the polish, or the solve's own and why
  // Set: no numbers (the multipliers were unusable, or kkt_sensitivity refused the point). With
  // unusable multipliers `kkt` still holds the objective and |grad_z L| that condemned them.
  std::optional<std::string> unavailable;
  KktSensitivity kkt;       // seconds: of the polish and the sensitivities
  bool evaluated = false;   // kkt_sensitivity ran (kkt holds its objective, gradient and seconds)
};

// model and problem: as solved (opt.z holds the free parameters); parameters: empty for
// studies::sensitivity_parameters(). nullopt unless opt.summary converged. should_stop (may be
// empty) stops the polish (then the solve's own multipliers are used).
std::optional<OptimumSensitivities> optimum_sensitivities(const walker::WalkerModel<double>& model,
                                                          const walker::GaitProblemOptions& problem,
                                                          const walker::GaitOptimum& opt,
                                                          const std::vector<std::string>& parameters = {},
                                                          const std::function<bool()>& should_stop = {});

}  // namespace cyclopt::studies
