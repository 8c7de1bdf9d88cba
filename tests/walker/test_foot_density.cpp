// Foot mass properties that follow the geometry (seed 001 section 10.2, appendix E): the coupled
// model against the seed's reference density, p_mod with rho, and the exact derivatives of the
// gait's objective and every constraint with respect to every foot parameter and rho (Dual pass
// through mass_properties) against the complex step on random admissible feet (acceptance 1 of
// issue 15). The near-polygonal mass properties are checked against closed-form polygon values in
// tests/foot/test_mass_properties.cpp.
#include "../foot/random_feet.hpp"
#include "reference_gaits.hpp"

#include "cyclopt/foot/mass_properties.hpp"
#include "cyclopt/io/foot_spec_json.hpp"
#include "cyclopt/walker/gait_problem.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <complex>
#include <cstdio>
#include <random>
#include <string>
#include <tuple>

namespace cyclopt::walker {
namespace {

using C = std::complex<double>;
constexpr double kStep = 1e-30;

foot::FootSpec with_density(foot::FootSpec s, double rho) {
  s.density = rho;
  return s;
}

TEST(FootDensity, SeedReferenceDensityGivesTheTableMass) {
  // Section 10.2: rho = 36.9 kg/m^2 gives P2's foot the mass m_F = 0.96 kg of Table 5.1.
  const WalkerModel<double> m = make_walker_model(with_density(foot::foot_preset("P2-shoes-left-HMT").spec, 36.9));
  EXPECT_NEAR(m.segments[m_F], 0.96, 0.005);
  EXPECT_GT(m.segments[r_F], 0.0);
  EXPECT_GT(m.segments[J_F], 0.0);
  EXPECT_NE(m.foot_zero_angle, kFootZeroAngle);  // eq. (E.7), not the Table 5.1 value
  const auto names = model_parameter_names(m);
  EXPECT_EQ(names.back(), "density");
  EXPECT_EQ(density_index(m), model_parameter_count(m) - 1);
  EXPECT_DOUBLE_EQ(model_parameters(m)(density_index(m)), 36.9);
}

TEST(FootDensity, WithoutDensityTheModelIsUnchanged) {
  const foot::FootSpec spec = foot::foot_preset("P1-barefoot-left-HM").spec;
  const WalkerModel<double> m = make_walker_model(spec);
  EXPECT_EQ(model_parameter_count(m), segment_parameter_count + int{foot::hm::count} + 1);
  EXPECT_EQ(density_index(m), -1);
  EXPECT_DOUBLE_EQ(m.segments[m_F], table_5_1()[m_F]);
  EXPECT_DOUBLE_EQ(m.foot_zero_angle, kFootZeroAngle);
  for (int i = 0; i < model_parameter_count(m); ++i) EXPECT_FALSE(follows_foot_geometry(m, i));
}

TEST(FootDensity, MassPropertiesFollowFootParametersAndRho) {
  const WalkerModel<double> m = make_walker_model(with_density(foot::foot_preset("P1-barefoot-left-HM").spec, 30.0));
  const Eigen::VectorXd p = model_parameters(m);
  const int l_hm = model_parameter_index(m, "l_HM"), rho = density_index(m);
  Eigen::VectorXd longer = p, denser = p, stale = p;
  longer(l_hm) *= 1.2;
  denser(rho) *= 2.0;
  stale(m_F) = 5.0;  // a derived entry: ignored on input
  const WalkerModel<double> ml = with_model_parameters<double>(m, longer), md = with_model_parameters<double>(m, denser);
  EXPECT_GT(ml.segments[m_F], m.segments[m_F] * 1.05);
  EXPECT_NEAR(md.segments[m_F], 2.0 * m.segments[m_F], 1e-12);
  EXPECT_NEAR(md.segments[J_F], 2.0 * m.segments[J_F], 1e-12);
  EXPECT_NEAR(md.segments[r_F], m.segments[r_F], 1e-12);  // the centre of mass does not depend on rho
  EXPECT_DOUBLE_EQ(with_model_parameters<double>(m, stale).segments[m_F], m.segments[m_F]);
  for (const char* derived : {"m_F", "r_F", "J_F", "theta_F0"})
    EXPECT_TRUE(follows_foot_geometry(m, model_parameter_index(m, derived))) << derived;
  EXPECT_FALSE(follows_foot_geometry(m, rho));
  // A spec that fixes theta_F,0 keeps it as an independent parameter.
  foot::FootSpec fixed = with_density(foot::foot_preset("P1-barefoot-left-HM").spec, 30.0);
  fixed.theta_F0 = 2.3;
  const WalkerModel<double> mf = make_walker_model(fixed);
  EXPECT_DOUBLE_EQ(mf.foot_zero_angle, 2.3);
  EXPECT_FALSE(follows_foot_geometry(mf, model_parameter_index(mf, "theta_F0")));
}

TEST(FootDensity, DerivedParametersCannotBeFreed) {
  const WalkerModel<double> m = make_walker_model(with_density(foot::foot_preset("P1-barefoot-left-HM").spec, 30.0));
  try {
    GaitProblem(m, {Objective::mechanical, 1.3, Quadrature::trapezoid, {"l_HM", "m_F"}});
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("m_F"), std::string::npos) << e.what();
  }
  const GaitProblem problem(m, {Objective::mechanical, 1.3, Quadrature::trapezoid, {"l_HM", "density"}});
  EXPECT_EQ(problem.variable_name(problem.num_variables() - 1), "density");
  EXPECT_DOUBLE_EQ(problem.lower_bounds()(problem.num_variables() - 1), foot::kMinDensity);
}

foot::FootSpec hm_foot(double h_f, double l_ha, double l_hm, double k_h, double k_hm, double k_m, double rho) {
  foot::FootSpec s;
  s.model = foot::FootModel::hm;
  s.parameters.resize(foot::hm::count);
  s.parameters << h_f, l_ha, l_hm, k_h, k_hm, k_m;
  s.density = rho;
  return s;
}

// Independent figures: the seed's optimal feet for rho = 10 kg/m^2 (Tables 10.1 and 10.2, l_MT = 0
// so listed as HM; parameters printed with 2-4 digits) and their printed m_F, r_F, J_F, theta_F,0.
TEST(FootDensity, SeedsOptimalFeetHaveTheTabulatedMassProperties) {
  struct Row {
    const char* name;
    foot::FootSpec spec;
    double m, r, J, theta;
  };
  const Row rows[] = {
      {"Table 10.1 high foot", hm_foot(0.100, 0.1095, 0.400, 1e-8, 0.32, 1e-8, 10.0), 0.399, 0.1226, 4.0e-3, 2.480},
      {"Table 10.2 flat foot", hm_foot(0.0, 0.1860, 0.400, 1e-8, 0.21, 1e-8, 10.0), 0.132, 0.0230, 1.3e-3, 2.487},
  };
  for (const Row& row : rows) {
    const WalkerModel<double> m = make_walker_model(row.spec);
    std::printf("%s: m_F %.4f (seed %.3f) r_F %.4f (%.4f) J_F %.3e (%.1e) theta_F0 %.4f (%.3f)\n", row.name,
                m.segments[m_F], row.m, m.segments[r_F], row.r, m.segments[J_F], row.J, m.foot_zero_angle, row.theta);
    EXPECT_NEAR(m.segments[m_F], row.m, 0.03 * row.m) << row.name;
    EXPECT_NEAR(m.segments[r_F], row.r, 0.03 * row.r) << row.name;
    EXPECT_NEAR(m.segments[J_F], row.J, 0.06 * row.J) << row.name;  // printed with 2 digits
    EXPECT_NEAR(m.foot_zero_angle, row.theta, 0.01) << row.name;
  }
}

// Item 2 of issue 15: the limits the seed's optima reach (h_F -> 0, the polygon a line; h_F and
// l_HA -> 0, the massless stilt; l_MT -> 0, HMT becomes HM; every k at 1e-8) give finite mass
// properties with finite exact derivatives, and the gait at the reference x is either real with
// finite values and derivatives or flagged with its reason - never NaN.
TEST(FootDensity, DegenerateLimitsGiveFiniteValuesAndDerivatives) {
  foot::FootSpec toe_less = foot::foot_preset("P2-shoes-left-HMT").spec;
  toe_less.parameters[foot::hmt::l_MT] = 0.0;
  toe_less.density = 30.0;
  const foot::FootSpec cases[] = {
      hm_foot(0.0, 0.186, 0.400, 1e-8, 0.21, 1e-8, 10.0),   // h_F = 0 (Table 10.2)
      hm_foot(0.0, 0.186, 0.400, 1e-8, 1e-8, 1e-8, 10.0),   // h_F = 0, all k = 1e-8: a line, no area
      hm_foot(0.0, 0.0, 0.300, 1e-8, 1e-8, 1e-8, 40.0),     // the stilt: every length but l_HM vanishes
      hm_foot(1e-6, 0.1, 0.300, 1e-8, 1e-8, 1e-8, 40.0),    // h_F -> 0+
      toe_less,                                               // l_MT = 0
      with_density(foot::testing::with_all_k(foot::foot_preset("P2-shoes-left-HMT").spec, 1e-8), 36.9),
  };
  using D = ad::Dual<foot::kMaxFootParameters + 1>;
  int real = 0, flagged = 0;
  for (const foot::FootSpec& spec : cases) {
    const int nf = static_cast<int>(spec.parameters.size());
    foot::FootParameters<D> fp(nf);
    for (int i = 0; i < nf; ++i) fp(i) = D::variable(spec.parameters(i), i);
    const auto mp = foot::mass_properties(foot::make_profile<D>(spec.model, fp), D::variable(*spec.density, nf));
    for (const D& v : {mp.area, mp.mass, mp.com_distance, mp.inertia_com, mp.theta_F0})
      EXPECT_TRUE(ad::isfinite(v)) << io::to_json(spec).dump() << ": " << v;
    const auto& ref = testing::reference_gait(spec.model == foot::FootModel::hm ? "P1-barefoot-left-HM" : "P2-shoes-left-HMT");
    const WalkerModel<double> model = make_walker_model(spec);
    GaitProblemOptions o{Objective::mechanical, 1.3, Quadrature::trapezoid, {"density"}};
    for (const foot::ParameterInfo& info : foot::parameter_layout(model.foot_model)) o.free_parameters.emplace_back(info.name);
    GaitProblem problem(model, o);
    nlp::Evaluation e;
    const nlp::EvaluationStatus st = problem.evaluate(problem.initial_point(ref.start.x), true, e);
    if (st.ok) {
      ++real;
      EXPECT_TRUE(std::isfinite(e.objective) && e.equalities.allFinite() && e.inequalities.allFinite() &&
                  e.gradient.allFinite() && e.equality_jacobian.allFinite() && e.inequality_jacobian.allFinite())
          << io::to_json(spec).dump();
    } else {
      ++flagged;
      EXPECT_FALSE(st.reason.empty());
    }
    std::printf("%s: m_F %.3g kg, NLP evaluation %s\n", io::to_json(spec).dump().c_str(), ad::value(mp.mass),
                st.ok ? "ok, values and derivatives finite" : st.reason.c_str());
  }
  EXPECT_GT(real, 0);
}

// The NLP of section 10.2 as the optimiser sees it: P2 with a density, every foot parameter and rho
// free, the bounds of eq. (10.1) as rows; its Jacobian columns of the free parameters against
// central differences of the problem's own values (relative steps, scaled as in test_gait_problem).
TEST(FootDensity, DesignProblemJacobianMatchesCentralDifferences) {
  const auto& ref = testing::reference_gait("P2-shoes-left-HMT");
  foot::FootSpec spec = with_density(foot::foot_preset("P2-shoes-left-HMT").spec, 36.9);  // m_F = 0.96 kg as in Table 5.1
  spec.theta_F0 = kFootZeroAngle;  // fixed, so the reference gait stays real; then a parameter of its own
  // k_H = k_T = 1e-8 would need difference steps of 1e-13, below the rounding noise of the values;
  // the complex-step test above covers that range.
  spec.parameters[foot::hmt::k_H] = spec.parameters[foot::hmt::k_T] = 1e-3;
  const WalkerModel<double> m = make_walker_model(spec);
  GaitProblemOptions o{Objective::mechanical, 1.3, Quadrature::trapezoid, {}};
  for (const foot::ParameterInfo& info : foot::parameter_layout(m.foot_model)) o.free_parameters.emplace_back(info.name);
  o.free_parameters.emplace_back("theta_F0");
  o.free_parameters.emplace_back("density");
  o.design_bounds = foot::DesignBounds{};
  GaitProblem problem(m, o);
  EXPECT_EQ(problem.num_inequalities(), 10 * 200 + 3 + 11 + 5 + 1);  // (5.104), (3.24), (10.1), toe margin
  EXPECT_NE(problem.constraint_name(false, 10 * 200 + 3 + 11).find("10.1"), std::string::npos);
  const Eigen::VectorXd z = problem.initial_point(ref.start.x);
  nlp::Evaluation e;
  ASSERT_TRUE(problem.evaluate(z, true, e).ok);
  double worst = 0.0;
  for (int j = static_cast<int>(ref.start.x.size()); j < problem.num_variables(); ++j) {
    const double h = 1e-5 * std::abs(z(j));
    Eigen::VectorXd zp = z, zm = z;
    zp(j) += h;
    zm(j) -= h;
    nlp::Evaluation ep, em;
    ASSERT_TRUE(problem.evaluate(zp, false, ep).ok && problem.evaluate(zm, false, em).ok) << problem.variable_name(j);
    auto scaled = [](double fd, double ad, double scale) { return std::abs(fd - ad) / (1.0 + scale); };
    worst = std::max(worst, scaled((ep.objective - em.objective) / (2 * h), e.gradient(j), e.gradient.cwiseAbs().maxCoeff()));
    worst = std::max(worst, scaled((ep.equalities(0) - em.equalities(0)) / (2 * h), e.equality_jacobian(0, j),
                                   e.equality_jacobian.cwiseAbs().maxCoeff()));
    const Eigen::VectorXd fd = (ep.inequalities - em.inequalities) / (2 * h);
    Eigen::Index row = 0;
    const double c = (fd - e.inequality_jacobian.col(j)).cwiseAbs().maxCoeff(&row) /
                     (1.0 + e.inequality_jacobian.col(j).cwiseAbs().maxCoeff());
    std::printf("  %-9s objective AD %.6e FD %.6e; worst inequality %s: AD %.6e FD %.6e (scaled %.1e)\n",
                problem.variable_name(j).c_str(), e.gradient(j), (ep.objective - em.objective) / (2 * h),
                problem.constraint_name(false, static_cast<int>(row)).c_str(), e.inequality_jacobian(row, j), fd(row), c);
    worst = std::max(worst, c);
  }
  std::printf("P2 with rho free and eq. (10.1): max scaled difference AD - central differences %.2e\n", worst);
  EXPECT_LE(worst, 1e-5);
}

// All scalar outputs and constraints of a gait, stacked: [f; f_mech; f_usq; c_g; L; T; v; Lambda; c_u].
template <class T>
Eigen::Matrix<T, Eigen::Dynamic, 1> outputs(const PeriodicGait<T>& g) {
  Eigen::Matrix<T, Eigen::Dynamic, 1> y(8 + g.inequalities.size());
  y << g.objective, g.f_mech, g.f_usq, g.speed_equality, g.step_length, g.step_period, g.mean_speed, g.floquet,
      g.inequalities;
  return y;
}

struct Agreement {
  int feet = 0, draws = 0, entries = 0;
  double worst = 0.0;  // max relative error over entries with |complex step| >= 1e-6
  std::string worst_at;
};

// `wanted` random admissible feet (k log-uniform in [k_min, 0.5], rho uniform in [5, 80] kg/m^2)
// at which the reference gait x of their model is real: every derivative of every output with
// respect to every foot parameter and rho, AD (one Dual pass through appendix E) vs complex step.
Agreement agreement_on_random_feet(unsigned seed, double k_min, int wanted) {
  foot::testing::RandomFeet feet(seed, k_min, 0.5);
  std::mt19937_64 rng(seed);
  const GaitOptions opt{Objective::mechanical, 1.3, false};
  Agreement a;
  while (a.feet < wanted && a.draws < 3000) {
    ++a.draws;
    const foot::FootSpec spec = with_density(feet.any(), std::uniform_real_distribution<double>(5.0, 80.0)(rng));
    const auto& ref = testing::reference_gait(spec.model == foot::FootModel::hm ? "P1-barefoot-left-HM" : "P2-shoes-left-HMT");
    const GaitEvaluator ev(make_walker_model(spec));
    const WalkerModel<double>& m = ev.model();
    std::vector<int> directions;
    for (int i = segment_parameter_count; i < model_parameter_count(m); ++i)
      if (!follows_foot_geometry(m, i)) directions.push_back(i);  // the foot parameters and rho
    const GaitEvaluation e = ev.evaluate_with_derivatives(ref.start.x, opt, directions);
    if (!e.gait.real) continue;  // the reference gait need not exist for every foot
    ++a.feet;
    const Eigen::MatrixXd J = e.derivatives.stacked();
    const int nx = ev.parameter_count();
    const Eigen::VectorXd p = model_parameters(m);
    for (std::size_t k = 0; k < directions.size(); ++k) {
      Eigen::VectorXcd pc = p.cast<C>();
      pc(directions[k]) += C(0.0, kStep);
      const PeriodicGait<C> g = periodic_gait(with_model_parameters<C>(m, pc), ev.basis(), ref.start.x.cast<C>().eval(), opt);
      EXPECT_TRUE(g.real);
      if (!g.real) continue;
      const Eigen::VectorXcd y = outputs(g);
      const int col = nx + static_cast<int>(k);
      for (int r = 0; r < y.size(); ++r) {
        const double cs = y(r).imag() / kStep;
        if (std::abs(cs) < 1e-6) continue;
        const double err = std::abs(J(r, col) - cs) / std::abs(cs);
        if (err > a.worst) {
          a.worst = err;
          a.worst_at = io::to_json(spec).dump() + ", output " + std::to_string(r) + " w.r.t. " +
                       model_parameter_names(m)[static_cast<std::size_t>(directions[k])] + ": AD " +
                       std::to_string(J(r, col)) + ", complex step " + std::to_string(cs);
        }
        ++a.entries;
      }
    }
  }
  return a;
}

// Acceptance 1 of issue 15 on feet whose transitions the phase grid resolves (k >= 1e-3; docs/walker-jobs.md
// names k_HM ~ 1e-2 as the limit at P = 200), then the same check down to k = 1e-8, where d/dk of
// tanh(a/k) cancels terms of size 1/k^2 and both methods lose digits to rounding: reported, with a
// looser bound. Rounding sets that figure: 5.5e-6 in an SSE2 build, 1.2e-5 with
// FMA contraction (CYCLOPT_ARCH x86-64-v3 and above) on the same feet - a wrong derivative is O(1).
TEST(FootDensity, GaitDerivativesWithRespectToFootAndDensityMatchComplexStepOnRandomFeet) {
  const auto t0 = std::chrono::steady_clock::now();
  const Agreement resolved = agreement_on_random_feet(1015, 1e-3, 50);
  const double t1 = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const Agreement sharp = agreement_on_random_feet(1016, 1e-8, 20);
  const double t2 = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() - t1;
  for (const auto& [label, a, seconds] : {std::tuple{"k in [1e-3, 0.5]", resolved, t1}, std::tuple{"k in [1e-8, 0.5]", sharp, t2}})
    std::printf("%s: %d random feet with a real gait (%d drawn), %d entries >= 1e-6 w.r.t. foot parameters and rho, "
                "max relative error AD vs complex step %.2e (%.1f s)\n  worst: %s\n",
                label, a.feet, a.draws, a.entries, a.worst, seconds, a.worst_at.c_str());
  EXPECT_GE(resolved.feet, 50);
  EXPECT_GT(resolved.entries, 10000);
  EXPECT_LE(resolved.worst, 1e-6);
  EXPECT_GE(sharp.feet, 20);
  EXPECT_LE(sharp.worst, 3e-5);
}

}  // namespace
}  // namespace cyclopt::walker
