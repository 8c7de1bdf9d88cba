#pragma once
// The walker fields of a job spec (scene "walker"), shared by the walker job kinds and the
// command line:
//
//   {"scene": "walker", "task": "optimise", "foot": "P1-barefoot-left-HM", "speed": 1.3,
//    "objective": "f_mech", "points": 200, "bezier_degree": 6, "quadrature": "trapezoid",
//    "free_parameters": ["l_HM"], "start": [30 numbers], "solver": {"solver": "sqp"},
//    "multistart": {"starts": 20, "seed": 1, "scale": 0.05}}
//
// foot: a preset name (cyclopt-foot --list-presets) or a foot spec (foot.schema.json); speed
// (m/s, [0.1, 3]) for evaluate / optimise / multistart, speeds ("lo:step:hi", a number or an
// array) for sweep; objective f_mech (5.102, default) or f_usq (5.101); points P in [25, 20000]
// (eq. 5.93, default 200); bezier_degree M in [3, 10] (default 6); quadrature trapezoid (the
// seed's) or corrected_trapezoid; positive_power_band (W, [0, 1]; > 0 with the trapezoid rule
// only; default kIpoptPositivePowerBand when the solver is Ipopt and the rule the trapezoid, else
// 0, the seed's rule): walker::GaitProblemOptions::positive_power_band; free_parameters: model
// parameters optimised with the gait
// (with foot.density: the foot parameters and "density", not m_F, r_F, J_F, theta_F0, which then
// follow the geometry); design_bounds: the foot dimension bounds of eq. (10.1)
// (design_bounds_spec.hpp);
// start: the gait parameters x (default: the automatic starting gait); multistart: starts
// [1, 1000], seed [0, 2^31) or (sweeps) seeds, up to kMaxSeeds distinct, scale (0, 1] rad of the
// random perturbation. The solver defaults to
// the seed's SQP with Table 6.2 (nlp::seed_table_6_2_options()); "solver" overrides it.

#include "cyclopt/foot/foot_spec.hpp"
#include "cyclopt/nlp/solver_options.hpp"
#include "cyclopt/service/common_job_fields.hpp"
#include "cyclopt/service/job_kind.hpp"
#include "cyclopt/walker/gait_problem.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace cyclopt::jobs {

inline constexpr double kMinWalkingSpeed = 0.1, kMaxWalkingSpeed = 3.0;  // m/s
inline constexpr int kMinGaitPoints = 25, kMaxGaitPoints = 20000;    // P of (5.93), "points"
inline constexpr int kMaxSeeds = 20;                                  // "multistart.seeds"
// The band of an Ipopt job that names none. An interior-point method needs a smooth problem, and
// f_mech's max(u q_dot, 0) has a kink at every joint the optimum holds still: from the starting gait
// at 1.3 m/s Ipopt stopped at MaxIter on the large rolling HM foot of issue 16 with the seed's rule
// and reached KKT points on all four feet of issue 16 with 1 mW, at the SQP's optima to 9 digits on
// point, P1 and P2 feet (bench/results/walker_solvers.txt). f_mech moves by at most band/4 per
// still joint. The SQP keeps the seed's rule: with the band as every job's default, the parameter
// continuation of a sensitivity job (point feet, 1.0 m/s, m_T) stopped after +0.2 %.
inline constexpr double kIpoptPositivePowerBand = 1e-3;

struct WalkerJob {
  foot::FootSpec foot;
  walker::WalkingConstants constants;
  walker::GaitProblemOptions problem;    // objective, quadrature, free parameters (speed per point)
  std::vector<double> speeds;            // one for evaluate / optimise / multistart
  std::optional<Eigen::VectorXd> start;  // gait parameters x
  nlp::SolverOptions solver;
  int starts = 20;
  // multistart.seed, or multistart.seeds (several only where the kind runs a search per seed:
  // sweep, foot_comparison, foot_design): base seeds of the random perturbations.
  std::vector<std::uint64_t> seeds{1};
  double scale = 0.05;

  walker::WalkerModel<double> model() const { return walker::make_walker_model(foot, constants); }
  // The problem at one speed.
  walker::GaitProblemOptions problem_at(double speed) const {
    walker::GaitProblemOptions o = problem;
    o.speed = speed;
    return o;
  }
  // The options of one gait evaluation at one speed, with trajectories.
  walker::GaitOptions gait_options(double speed) const { return walker::gait_options_of(problem_at(speed), true); }
};

// Parses and validates the walker fields; `sweep` selects "speeds" instead of "speed"; the
// objective and the solver come from the parsed common fields. Throws SpecError naming the first
// invalid field and its admissible range.
WalkerJob parse_walker_job(const nlohmann::json& spec, const service::CommonJobFields& common, bool sweep);

// The walker fields a job kind accepts (for JobKind::fields).
std::vector<std::string> walker_job_fields(bool sweep);

// The kind `task` of the walker fields at one speed (evaluate, optimise, multistart), which `run`s
// them: parsed by parse_walker_job, resolved by walker_job_json ("multistart" when
// `random_starts`), its cost estimated by walker_job_cost.
service::JobKind one_speed_kind(const std::string& task, bool random_starts,
                                std::function<void(const WalkerJob&, service::JobContext&)> run);

}  // namespace cyclopt::jobs
