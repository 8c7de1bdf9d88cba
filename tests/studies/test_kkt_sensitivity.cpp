// studies/kkt_sensitivity.hpp against an independent reference: the central difference of
// warm-started re-solves (resolved_sensitivity.hpp) at a polished optimum of point feet
// (issue 15 acceptance 5 in small; bench/kkt_sensitivity_bench.cpp runs the P2 foot at 2.3 m/s).
#include "cyclopt/studies/kkt_sensitivity.hpp"
#include "cyclopt/studies/resolved_sensitivity.hpp"
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/walker/gait_optimisation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

using namespace cyclopt;
using namespace cyclopt::studies;

namespace {

struct PolishedOptimum {
  walker::WalkerModel<double> model = walker::make_walker_model(foot::foot_preset("point").spec);
  walker::GaitProblemOptions problem{walker::Objective::mechanical, 1.0, walker::Quadrature::trapezoid, {}};
  nlp::SolverOptions tight;
  nlp::SolverSummary optimum;

  PolishedOptimum() {
    const walker::GaitOptimum start = walker::optimise_gait(model, problem, nlp::seed_table_6_2_options());
    tight.solver = nlp::SolverKind::ipopt;
    tight.optimality_tolerance = tight.constraint_tolerance = 1e-11;
    tight.ipopt.difference_hessian_start = true;
    tight.ipopt.warm_start = nlp::IpoptWarmStart{start.summary.equality_multipliers, start.summary.inequality_multipliers,
                                                 start.summary.bound_multipliers};
    optimum = walker::optimise_gait(model, problem, tight, start.z).summary;
  }
};

const PolishedOptimum& polished() {
  static const PolishedOptimum p;
  return p;
}

}  // namespace

TEST(KktSensitivity, AgreesWithWarmStartedReSolves) {
  const PolishedOptimum& p = polished();
  ASSERT_EQ(p.optimum.termination, nlp::Termination::converged) << p.optimum.message;
  KktSensitivityOptions o;
  o.parameters = {"l_O", "m_T", "J_U", "r_T"};
  const KktSensitivity k = kkt_sensitivity(p.model, p.problem, p.optimum.x, p.optimum, o);
  EXPECT_LT(k.lagrangian_gradient, 1e-7);
  ASSERT_EQ(k.parameters.size(), o.parameters.size());
  int compared = 0;
  for (const ParameterSensitivity& s : k.parameters) {
    const ResolvedSensitivity r = resolved_sensitivity(p.model, p.problem, p.optimum.x, p.optimum, s.name, 1e-4, p.tight);
    std::printf("%-4s KKT %.9e re-solve %.9e kink %d range %.2e / %.2e\n", s.name.c_str(), s.derivative, r.derivative,
                s.kink, s.decrease.relative_change, s.increase.relative_change);
    EXPECT_NEAR(s.relative, s.value / k.objective * s.derivative, 1e-12 * std::abs(s.relative) + 1e-15);
    ASSERT_TRUE(r.converged) << s.name << ": " << r.message;
    ++compared;
    // Inside the predicted active-set range the difference quotient is off by O(h^2); where a weakly
    // active row makes the point a second-order kink (this optimum has one, so every parameter
    // sees it), by O(h) - still a first-order check of the envelope value.
    const bool within_range = !s.kink && std::min(s.decrease.relative_change, s.increase.relative_change) > 1e-4;
    EXPECT_NEAR(s.derivative, r.derivative, (within_range ? 1e-4 : 1e-3) * std::abs(r.derivative)) << s.name;
    if (s.kink) {
      EXPECT_FALSE(s.weakly_active.empty()) << s.name << ": a kink names the weakly active rows behind it";
    }
  }
  EXPECT_EQ(compared, 4);
}

TEST(KktSensitivity, RefusesParametersItCannotDifferentiate) {
  const PolishedOptimum& p = polished();
  KktSensitivityOptions o;
  o.parameters = {"no_such_parameter"};
  EXPECT_THROW(kkt_sensitivity(p.model, p.problem, p.optimum.x, p.optimum, o), std::invalid_argument);
  EXPECT_THROW(kkt_sensitivity(p.model, p.problem, Eigen::VectorXd::Zero(3), p.optimum), std::invalid_argument);
}
