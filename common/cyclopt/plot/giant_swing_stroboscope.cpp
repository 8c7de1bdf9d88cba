#include "cyclopt/plot/giant_swing_stroboscope.hpp"

#include "cyclopt/giant_swing/hip_torque_law.hpp"
#include "cyclopt/giant_swing/swing_simulation.hpp"
#include "cyclopt/io/task_spec_json.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace cyclopt::plot {
namespace {

constexpr Color kUpper{0.12, 0.47, 0.71, 1}, kLegs{0.84, 0.37, 0.0, 1}, kBar{0.1, 0.1, 0.1, 1};
constexpr Color kStamp{0.1, 0.1, 0.1, 1};
constexpr double kStampEvery = 0.2;    // s between time stamps
constexpr double kStampOffset = 0.16;  // m from the feet outwards to a time stamp
constexpr double kStampClearance = 0.3;  // m, least distance between two time stamps
constexpr double kArrow = 0.09;        // m, length of a direction arrowhead

Color faded(Color c, double alpha) { return {c.r, c.g, c.b, alpha}; }

std::string fixed_seconds(double t) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f s", t);
  return b;
}

struct Body {
  std::array<double, 2> hip, feet;
};

// Hip and feet at state x: phi, body 1 from the handstand (eq. 3.1), psi = phi + alpha, the legs;
// e = [sin; cos] from the bar. The model has no leg length: legs are drawn `leg` long.
Body body_at(const giant_swing::Model& model, const giant_swing::State<double>& x, double leg) {
  const double phi = x[0], psi = x[0] + x[1];
  const std::array<double, 2> hip{model.L1 * std::sin(phi), model.L1 * std::cos(phi)};
  return {hip, {hip[0] + leg * std::sin(psi), hip[1] + leg * std::cos(psi)}};
}

// A filled arrowhead at `feet`, pointing to `to`, where the feet are at the next frame.
Shape arrowhead(const std::array<double, 2>& feet, const std::array<double, 2>& to) {
  const double dx = to[0] - feet[0], dz = to[1] - feet[1], d = std::hypot(dx, dz);
  const double ux = d > 0 ? dx / d : 1, uz = d > 0 ? dz / d : 0;
  const std::array<double, 2> tip{feet[0] + kArrow * ux, feet[1] + kArrow * uz};
  const std::array<double, 2> left{feet[0] - 0.45 * kArrow * uz, feet[1] + 0.45 * kArrow * ux};
  const std::array<double, 2> right{feet[0] + 0.45 * kArrow * uz, feet[1] - 0.45 * kArrow * ux};
  return {{tip, left, right}, kStamp, 1.0, false, true, kStamp, "direction of motion (arrows), time since the start (s)"};
}

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
  // Legs drawn to twice their centre-of-mass distance S2.
  const double leg = 2.0 * model.S2;
  Scene scene;
  char title[160];
  std::snprintf(title, sizeof title, "Giant swing at %g Hz, %zu round(s) (seed 000 Fig. 5.5)",
                rate_hz, sim.rounds.size());
  scene.axes = {title, "x from the bar (m)", "height above the bar (m)", false};
  Shape hip_path{{}, {0.45, 0.45, 0.45, 1}, 1.2, true, false, std::nullopt,
                 sim.failed ? "hip path (failed: " + sim.failure_reason + ")" : "hip path"};
  Shape feet_path{{}, kLegs, 1.2, true, false, std::nullopt, "feet path"};
  // Time cues: frames fade in from light to full colour; every kStampEvery seconds a frame gets its
  // time beyond the feet and an arrowhead on the feet path pointing the way the feet move.
  const std::size_t stamp_every = std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(kStampEvery * rate_hz)));
  for (std::size_t n = 0; n < frames.size(); ++n) {
    const auto& [t, x] = frames[n];
    const auto [hip, feet] = body_at(model, x, leg);
    const double fade = 0.3 + 0.7 * static_cast<double>(n) / static_cast<double>(std::max<std::size_t>(frames.size() - 1, 1));
    const bool last = n + 1 == frames.size();  // legends on the last, fully coloured frame
    scene.shapes.push_back({{{0, 0}, hip}, faded(kUpper, fade), 2.0, false, false, std::nullopt,
                            last ? "upper body (hands to hip, L1), light to dark in time" : ""});
    scene.shapes.push_back({{hip, feet}, faded(kLegs, fade), 2.0, false, false, std::nullopt,
                            last ? "legs (hip to 2 S2)" : ""});
    hip_path.points.push_back(hip);
    feet_path.points.push_back(feet);
    if (n % stamp_every != 0 || n + 1 == frames.size()) continue;
    const double r = std::hypot(feet[0], feet[1]);
    const double out = r > 0 ? 1 + kStampOffset / r : 1;
    const Label stamp{feet[0] * out, feet[1] * out, fixed_seconds(t), kStamp, 11};
    // A later round passing the same place keeps the first stamp (and arrow) there.
    if (std::any_of(scene.labels.begin(), scene.labels.end(),
                    [&](const Label& l) { return std::hypot(l.x - stamp.x, l.z - stamp.z) < kStampClearance; }))
      continue;
    scene.labels.push_back(stamp);
    scene.shapes.push_back(arrowhead(feet, body_at(model, frames[n + 1].second, leg).feet));
  }
  scene.shapes.push_back(hip_path);
  scene.shapes.push_back(feet_path);
  scene.markers.push_back({0, 0, kBar, 6, "high bar"});
  // The legend above the circle of swings: one 18 px row per entry, box and margins.
  scene.legend_headroom = 18.0 * 6 + 8 + 16;
  return scene;
}

}  // namespace cyclopt::plot
