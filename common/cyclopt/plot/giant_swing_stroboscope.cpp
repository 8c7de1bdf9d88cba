#include "cyclopt/plot/giant_swing_stroboscope.hpp"

#include "cyclopt/giant_swing/hip_torque_law.hpp"
#include "cyclopt/giant_swing/swing_simulation.hpp"
#include "cyclopt/io/task_spec_json.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace cyclopt::plot {
namespace {

constexpr Color kUpper{0.12, 0.47, 0.71, 1}, kLegs{0.84, 0.37, 0.0, 1}, kBar{0.1, 0.1, 0.1, 1};

}  // namespace

Scene giant_swing_stroboscope(const giant_swing::Model& model, const nlohmann::json& result, double rate_hz) {
  using namespace giant_swing;
  if (!result.contains("task") || !result.contains("support_values_Nm"))
    throw std::invalid_argument("giant swing result: needs \"task\" and \"support_values_Nm\" (cyclopt-giant-swing output)");
  const TaskSpec spec = io::task_spec_from_json(result["task"]);
  const std::vector<double> z = result["support_values_Nm"].get<std::vector<double>>();
  const HipTorqueProfile profile{Eigen::Map<const Eigen::VectorXd>(z.data(), static_cast<Eigen::Index>(z.size()))};
  // Accepted steps of the simulation, sampled at rate_hz by linear interpolation.
  std::vector<std::pair<double, State<double>>> frames;
  double t_prev = 0, next = 0;
  State<double> x_prev = initial_state(spec);
  const SimulationResult sim = simulate_swings(
      model, PiecewiseLinearTorque(profile), x_prev, spec.rounds, simulation_options(spec),
      [&](double t, const AugmentedState& y) {
        const State<double> x = y.head<4>();
        for (; next <= t; next += 1.0 / rate_hz) {
          const double w = t > t_prev ? (next - t_prev) / (t - t_prev) : 1.0;
          frames.push_back({next, (1 - w) * x_prev + w * x});
        }
        t_prev = t;
        x_prev = x;
      });
  // The model has no leg length: legs are drawn to twice their centre-of-mass distance S2.
  const double leg = 2.0 * model.S2;
  Scene scene;
  char title[120];
  std::snprintf(title, sizeof title, "Giant swing at %g Hz, %zu round(s) (seed 000 Fig. 5.5)", rate_hz, sim.rounds.size());
  scene.axes = {title, "x from the bar (m)", "height above the bar (m)", false};
  scene.legend_room = 260;  // the legend beside the circle of swings
  Shape hip_path{{}, {0.45, 0.45, 0.45, 1}, 1.2, true, false, std::nullopt,
                 sim.failed ? "hip path (failed: " + sim.failure_reason + ")" : "hip path"};
  Shape feet_path{{}, kLegs, 1.2, true, false, std::nullopt, "feet path"};
  for (const auto& [t, x] : frames) {
    // phi: body 1 from the handstand (eq. 3.1), psi = phi + alpha: legs; e = [sin; cos] from the bar.
    const double phi = x[0], psi = x[0] + x[1];
    const std::array<double, 2> hip{model.L1 * std::sin(phi), model.L1 * std::cos(phi)};
    const std::array<double, 2> feet{hip[0] + leg * std::sin(psi), hip[1] + leg * std::cos(psi)};
    scene.shapes.push_back({{{0, 0}, hip}, kUpper, 2.0, false, false, std::nullopt, "upper body (hands to hip, L1)"});
    scene.shapes.push_back({{hip, feet}, kLegs, 2.0, false, false, std::nullopt, "legs (hip to 2 S2)"});
    hip_path.points.push_back(hip);
    feet_path.points.push_back(feet);
  }
  scene.shapes.push_back(hip_path);
  scene.shapes.push_back(feet_path);
  scene.markers.push_back({0, 0, kBar, 6, "high bar"});
  return scene;
}

}  // namespace cyclopt::plot
