#include "cyclopt/foot_fit/synthetic_trials.hpp"

#include "cyclopt/foot/foot_profile.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace cyclopt::foot_fit {
namespace {

foot::FootProfile<double> profile_of(const foot::FootSpec& f) {
  if (f.model == foot::FootModel::point) throw std::invalid_argument("foot: the point foot does not roll");
  return foot::make_profile(f.model, f.parameters, f.periodic_terms);
}

double theta_at(const std::vector<FootAngleKnot>& knots, double t) {
  if (t <= knots.front().t) return knots.front().theta;
  for (std::size_t i = 1; i < knots.size(); ++i)
    if (t <= knots[i].t) {
      const double s = (t - knots[i - 1].t) / (knots[i].t - knots[i - 1].t);
      return knots[i - 1].theta + s * (knots[i].theta - knots[i - 1].theta);
    }
  return knots.back().theta;
}

}  // namespace

Eigen::Vector2d synthetic_ankle(const foot::FootSpec& f, double theta, double offset) {
  const foot::FootProfile<double> prof = profile_of(f);
  const double f0 = foot::rolling_contact(prof, 0.0).F;
  const foot::RollingContact<double> c = foot::rolling_contact(prof, theta);
  return {offset + c.F - f0, c.dF};  // eq. (3.9)-(3.10a), origin as eq. (4.15a)
}

std::vector<FootAngleKnot> default_foot_angle_history(const foot::FootSpec& f) {
  const foot::FootProfile<double> prof = profile_of(f);
  const double toe_off = f.model == foot::FootModel::hmt ? f.parameters[foot::hmt::gamma_F] + 0.35 : 0.9;
  auto clip = [&](double th) { return std::clamp(th, prof.theta_min + 0.05, prof.theta_max - 0.05); };
  return {{0.0, clip(-0.35)}, {0.12, clip(0.0)}, {0.40, clip(0.03)}, {0.62, clip(toe_off)}};
}

MarkerTrial synthetic_trial(const foot::FootSpec& f, const SyntheticTrialOptions& o) {
  const foot::FootProfile<double> prof = profile_of(f);
  const std::vector<FootAngleKnot> knots = o.foot_angle.empty() ? default_foot_angle_history(f) : o.foot_angle;
  if (knots.size() < 2) throw std::invalid_argument("foot_angle: needs at least two knots (t, theta)");
  for (std::size_t i = 0; i < knots.size(); ++i) {
    const std::string field = "foot_angle[" + std::to_string(i) + "]";
    if (i > 0 && !(knots[i].t > knots[i - 1].t)) throw std::invalid_argument(field + ".t: times must increase");
    if (!(knots[i].theta > prof.theta_min && knots[i].theta < prof.theta_max))
      throw std::invalid_argument(field + ".theta: " + std::to_string(knots[i].theta) + " rad is outside the foot's admissible (" +
                                  std::to_string(prof.theta_min) + ", " + std::to_string(prof.theta_max) + ") rad");
  }
  if (!(o.rate >= 1.0 && o.rate <= 1e5)) throw std::invalid_argument("rate: " + std::to_string(o.rate) + " Hz is not in [1, 1e5]");
  if (!(o.noise >= 0.0 && o.noise <= 0.05)) throw std::invalid_argument("noise: " + std::to_string(o.noise) + " m is not in [0, 0.05]");
  if (!(o.swing_time >= 0.0)) throw std::invalid_argument("swing_time: must be >= 0 s");
  if (o.vertical_axis < 0 || o.vertical_axis > 2) throw std::invalid_argument("vertical_axis: not in 0..2");
  if (o.markers.empty() || o.markers.size() > 2) throw std::invalid_argument("markers: one or two names");

  const int up = o.vertical_axis, h1 = up == 0 ? 1 : 0, h2 = up == 2 ? 1 : 2;
  const Eigen::Vector2d e(std::cos(o.walking_direction), std::sin(o.walking_direction));
  const Eigen::Vector2d side(-e.y(), e.x());
  const double t_end = knots.back().t - knots.front().t;
  const Eigen::Vector2d strike = synthetic_ankle(f, knots.front().theta, o.offset);
  const Eigen::Vector2d toe_off = synthetic_ankle(f, knots.back().theta, o.offset);
  const double lift = 0.3;  // rad: the swinging ankle moves up and away from the ground

  MarkerTrial t;
  t.source = o.source;
  t.units = "m";
  t.marker_names = o.markers;
  t.positions.assign(o.markers.size(), {});
  t.analog_names = {"Fz"};
  t.analog.assign(1, {});
  std::mt19937_64 rng(o.seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const int samples = static_cast<int>(std::floor((t_end + 2.0 * o.swing_time) * o.rate + 1e-9)) + 1;
  for (int i = 0; i < samples; ++i) {
    const double time = i / o.rate, tr = time - o.swing_time;  // tr: time from heel strike
    Eigen::Vector2d sag;                                         // along the walk, up
    bool rolling = false;
    if (tr < 0.0) {
      sag = strike + o.swing_speed * tr * Eigen::Vector2d(std::cos(lift), -std::sin(lift));
    } else if (tr > t_end) {
      sag = toe_off + o.swing_speed * (tr - t_end) * Eigen::Vector2d(std::cos(lift), std::sin(lift));
    } else {
      sag = synthetic_ankle(f, theta_at(knots, knots.front().t + tr), o.offset);
      rolling = true;
    }
    t.time.push_back(time);
    t.line_of_sample.push_back(i + 1);
    t.analog[0].push_back(rolling ? o.body_force : 0.0);
    for (std::size_t m = 0; m < o.markers.size(); ++m) {
      const double sideways = o.lateral + (o.markers.size() == 1 ? 0.0 : (m == 0 ? 0.5 : -0.5) * o.malleolus_spacing);
      const Eigen::Vector2d horizontal = sag.x() * e + sideways * side;
      Eigen::Vector3d p;
      p[h1] = horizontal.x();
      p[h2] = horizontal.y();
      p[up] = sag.y();
      for (int a = 0; a < 3; ++a) p[a] += o.noise * gauss(rng);
      t.positions[m].push_back(p);
    }
  }
  return t;
}

}  // namespace cyclopt::foot_fit
