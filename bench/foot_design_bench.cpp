// Issue 15, acceptance 2 (reduced): the design step of seed 001 section 10.2 at the design speed
// only. Per density rho: the start foot P2-shoes-left-HMT with mass properties from its geometry
// (appendix E), every foot parameter free with the gait, the bounds of eq. (10.1), a multistart of
// N perturbations of the automatic starting gait at v; the best KKT point against the optimal
// gaits of the start foot (P2 with the masses of Table 5.1, fixed) and of point feet (Table D.1)
// at the same speed and objective. Not yet: the continuation over 0.3:0.1:2.3 m/s with the foot
// free and the fixed-foot sweeps, so "speeds" counts the design speed only.
//
// usage: foot_design_bench [densities = 10] [starts = 6] [speed = 2.3] [configuration = sqp-dh]
#include "cyclopt/foot/design_bounds.hpp"
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/foot/mass_properties.hpp"
#include "cyclopt/nlp/multistart.hpp"
#include "cyclopt/nlp/solve.hpp"
#include "cyclopt/walker/gait_problem.hpp"
#include "cyclopt/walker/model_parameters.hpp"
#include "cyclopt/walker/starting_gait.hpp"
#include "machine_info.hpp"
#include "solver_configuration.hpp"

#include <chrono>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

using namespace cyclopt;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// f_mech of the optimal gait of a fixed foot at v from its automatic starting gait (NaN if no KKT point).
double fixed_foot_optimum(const foot::FootSpec& spec, double v, const nlp::SolverOptions& so) {
  const walker::WalkerModel<double> model = walker::make_walker_model(spec);
  walker::GaitProblem problem(model, {walker::Objective::mechanical, v, walker::Quadrature::trapezoid, {}});
  const walker::GaitEvaluator ev(model);
  const nlp::SolverSummary s = nlp::solve(problem, so, problem.initial_point(walker::gait_start(ev, v, {}).x));
  return s.success() ? s.objective : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<double> densities = {10.0};
  if (argc > 1) {
    densities.clear();
    std::stringstream in(argv[1]);
    for (std::string item; std::getline(in, item, ',');) densities.push_back(std::stod(item));
  }
  const int starts = argc > 2 ? std::atoi(argv[2]) : 6;
  const double v = argc > 3 ? std::atof(argv[3]) : 2.3;
  const nlp::SolverOptions so = bench::solver_configuration(argc > 4 ? argv[4] : "sqp-dh");
  std::printf("foot_design_bench on %s\n", bench::machine_line().c_str());
  const foot::FootSpec p2 = foot::foot_preset("P2-shoes-left-HMT").spec;
  auto t0 = std::chrono::steady_clock::now();
  const double f_start = fixed_foot_optimum(p2, v, so);
  const double f_point = fixed_foot_optimum(foot::foot_preset("point").spec, v, so);
  std::printf("references at %.2f m/s: start foot P2 (Table 5.1 masses) f_mech %.5f, point feet %.5f (%.1f s)\n", v, f_start,
              f_point, seconds_since(t0));
  const foot::DesignBounds bounds;
  std::vector<std::string> free;
  for (const foot::ParameterInfo& info : foot::parameter_layout(foot::FootModel::hmt)) free.emplace_back(info.name);
  for (double rho : densities) {
    t0 = std::chrono::steady_clock::now();
    foot::FootSpec start = p2;
    start.density = rho;
    start.parameters = foot::project_into_design_bounds(start.model, start.parameters, bounds, free);
    const walker::WalkerModel<double> model = walker::make_walker_model(start);
    walker::GaitProblemOptions po{walker::Objective::mechanical, v, walker::Quadrature::trapezoid, free};
    po.design_bounds = bounds;
    const walker::GaitEvaluator ev(model);
    const Eigen::VectorXd centre = walker::gait_start(ev, v, {}).x;
    const walker::GaitProblem shape(model, po);
    nlp::MultistartOptions mo;
    mo.num_starts = starts;
    mo.base_seed = 1;
    mo.solver = so;
    mo.objective_tolerance = 1e-5;
    mo.x_tolerance = 1e-2;
    const nlp::MultistartResult r = nlp::multistart(
        [&] { return std::make_unique<walker::GaitProblem>(model, po); },
        [&](std::mt19937_64& rng) { return shape.initial_point(walker::perturbed_gait(ev, centre, 0.05, rng)); }, mo);
    std::printf("rho %.0f kg/m^2: %d/%d starts KKT, %zu optima\n", rho, r.successes, starts, r.optima.size());
    double f_best = std::numeric_limits<double>::quiet_NaN();
    if (!r.optima.empty()) {
      const Eigen::VectorXd& z = r.optima.front().x;
      f_best = r.optima.front().objective;
      const walker::WalkerModel<double> best = shape.model_at(z);
      std::printf("  design:");
      for (std::size_t k = 0; k < free.size(); ++k) std::printf(" %s %.4g", free[k].c_str(), best.foot_parameters(static_cast<Eigen::Index>(k)));
      std::printf("\n  m_F %.3f kg, r_F %.1f mm, J_F %.2e kg m^2, theta_F0 %.3f rad, f_mech %.5f\n", best.segments[walker::m_F],
                  1e3 * best.segments[walker::r_F], best.segments[walker::J_F], best.foot_zero_angle, f_best);
      const foot::LinearInequalities li = foot::design_constraints(best.foot_model, bounds);
      const Eigen::VectorXd margin = li.A * best.foot_parameters + li.b;
      std::printf("  active bounds (10.1):");
      for (Eigen::Index i = 0; i < margin.size(); ++i)
        if (margin(i) <= 1e-6) std::printf(" [%s]", li.names[static_cast<std::size_t>(i)].c_str());
      std::printf("\n");
    }
    std::printf("rho %.0f: saving vs start %.1f %%, vs point feet %.1f %%, speeds %d/21, wall %.1f s\n", rho,
                100.0 * (1.0 - f_best / f_start), 100.0 * (1.0 - f_best / f_point), r.optima.empty() ? 0 : 1,
                seconds_since(t0));
  }
}
