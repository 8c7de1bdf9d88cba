#include "cyclopt/plot/gait_stroboscope.hpp"

#include "cyclopt/plot/foot_figures.hpp"
#include "cyclopt/plot/walker_pose.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

namespace cyclopt::plot {
namespace {

constexpr Color kLegA{0.12, 0.47, 0.71, 1}, kLegB{0.84, 0.37, 0.0, 1}, kTorso{0.25, 0.25, 0.25, 1};
constexpr Color kContact{0.84, 0.15, 0.16, 1}, kClearance{0.17, 0.63, 0.17, 1};

std::vector<Xz> shifted(std::vector<Xz> pts, double dx) {
  for (Xz& p : pts) p[0] += dx;
  return pts;
}

// Gap between the rightmost point of one drawn pose and the leftmost of the next (m).
constexpr double kPoseGap = 0.04;

// Leftmost and rightmost x of everything drawn for one pose.
std::array<double, 2> x_extent(const WalkerPose& p) {
  std::array<double, 2> e{p.contact[0], p.contact[0]};
  auto add = [&e](const Xz& q) { e = {std::min(e[0], q[0]), std::max(e[1], q[0])}; };
  for (const Xz& q : {p.torso_tip, p.hip, p.knee1, p.knee2, p.ankle1, p.ankle2}) add(q);
  for (const std::vector<Xz>* foot : {&p.foot1, &p.foot2})
    for (const Xz& q : *foot) add(q);
  return e;
}

std::string leg_label(const Color& c) {
  return c.b == kLegA.b ? "leg A (stance in steps 1, 3, ...)" : "leg B (stance in steps 2, 4, ...)";
}

std::string fixed(double v, int digits) {
  char b[32];
  std::snprintf(b, sizeof b, "%.*f", digits, v);
  return b;
}

}  // namespace

Scene gait_stroboscope(const WalkerJobResults& job, const GaitPoint& point, const StroboscopeOptions& o) {
  if (o.steps < 1 || o.frames_per_step < 1)
    throw std::invalid_argument("gait stroboscope: steps (" + std::to_string(o.steps) + ") and frames_per_step (" +
                                std::to_string(o.frames_per_step) + ") must be >= 1");
  if (!point.trajectory) throw std::invalid_argument("gait stroboscope: the point has no stored trajectory");
  const walker::WalkerModel<double> model = job.walker.model();
  const std::vector<Xz> outline = model.has_feet() ? foot_outline(job.walker.foot) : std::vector<Xz>{};
  const records::GaitTrajectoryRecord& tr = *point.trajectory;
  if (tr.time.size() < 2 || tr.swing_contact.size() != 2)
    throw std::invalid_argument("gait stroboscope: the stored trajectory has " + std::to_string(tr.time.size()) +
                                " samples and " + std::to_string(tr.swing_contact.size()) +
                                " swing-contact rows (needs >= 2 and 2)");
  const double period = tr.time.back(), step = point.gait.step_length;
  const std::vector<double>& swing_x = tr.swing_contact[0];
  const std::vector<double>& swing_z = tr.swing_contact[1];

  Scene scene;
  const double dt = period / o.frames_per_step;
  scene.axes = {std::to_string(o.steps) + " steps at v = " + fixed(point.gait.mean_speed, 2) +
                    " m/s, every " + fixed(dt * 1000, 0) + " ms (seed 001 Fig. 9.2)",
                "x (m)", "z (m)", false};
  scene.ground_z = 0.0;
  scene.pad = 0.04;
  const double peak_clearance = *std::max_element(swing_z.begin(), swing_z.end());
  // Fig. 9.2 draws consecutive poses side by side: frame f of step k stands at its place in the
  // walk (k step lengths on) plus spread[k][f] >= the previous frame's, just far enough right that
  // it clears the previous pose. Frame 0 of step k > 0 is the last frame of step k - 1.
  std::vector<std::vector<WalkerPose>> poses(static_cast<std::size_t>(o.steps));
  std::vector<std::vector<double>> spread(static_cast<std::size_t>(o.steps));
  double previous_right = -std::numeric_limits<double>::infinity(), extra = 0;
  for (std::size_t k = 0; k < poses.size(); ++k)
    for (int f = 0; f <= o.frames_per_step; ++f) {
      poses[k].push_back(walker_pose(model, q_at(tr, f * dt), outline));
      if (k > 0 && f == 0) {
        spread[k].push_back(spread[k - 1].back());
        continue;
      }
      const std::array<double, 2> e = x_extent(poses[k].back());
      const double at = static_cast<double>(k) * step;
      extra = std::max(extra, previous_right + kPoseGap - (at + e[0]));
      spread[k].push_back(extra);
      previous_right = at + extra + e[1];
    }
  for (int k = 0; k < o.steps; ++k) {
    const std::size_t ks = static_cast<std::size_t>(k);
    // Leg "A" is the stance leg of even steps; the legs swap roles at every impact.
    const Color stance = k % 2 == 0 ? kLegA : kLegB, swing = k % 2 == 0 ? kLegB : kLegA;
    for (int f = k == 0 ? 0 : 1; f <= o.frames_per_step; ++f) {
      const WalkerPose& p = poses[ks][static_cast<std::size_t>(f)];
      const double dx = k * step + spread[ks][static_cast<std::size_t>(f)];
      const double fade = 0.35 + 0.65 * (k * o.frames_per_step + f) / double(o.steps * o.frames_per_step);
      auto faded = [fade](Color c) { return Color{c.r, c.g, c.b, fade}; };
      // Legends on the last, fully opaque frame (the legend takes the first labelled shape's colour).
      const bool last = k + 1 == o.steps && f == o.frames_per_step;
      auto label = [last](std::string text) { return last ? text : std::string(); };
      scene.shapes.push_back({shifted({p.hip, p.torso_tip}, dx), faded(kTorso), 3.0, false, false, std::nullopt, label("torso")});
      scene.shapes.push_back({shifted({p.hip, p.knee1, p.ankle1}, dx), faded(stance), 2.4, false, false, std::nullopt,
                              label(leg_label(stance))});
      scene.shapes.push_back({shifted({p.hip, p.knee2, p.ankle2}, dx), faded(swing), 2.4, false, false, std::nullopt,
                              label(leg_label(swing))});
      if (!outline.empty()) {
        scene.shapes.push_back({shifted(p.foot1, dx), faded(stance), 1.4, false, true, Color{stance.r, stance.g, stance.b, 0.12}, ""});
        scene.shapes.push_back({shifted(p.foot2, dx), faded(swing), 1.4, false, true, Color{swing.r, swing.g, swing.b, 0.12}, ""});
      }
      scene.markers.push_back({p.contact[0] + dx, p.contact[1], kContact, 4.5, "rolling contact point C1 (every frame)"});
      scene.markers.push_back({p.hip[0] + dx, p.hip[1], kTorso, 3.0, ""});
    }
    // The swing foot's path, spread with the frames: between two frames its shift is interpolated
    // in time, so it passes through every drawn swing foot.
    Shape clearance{{}, kClearance, 1.8, true, false, std::nullopt,
                    "swing-foot lowest point C2 (peak clearance " + fixed(peak_clearance * 100, 1) + " cm)"};
    for (std::size_t i = 0; i < swing_x.size(); ++i) {
      const double s_f = std::clamp(tr.time[i] / dt, 0.0, double(o.frames_per_step));
      const std::size_t f0 = std::min(static_cast<std::size_t>(s_f), static_cast<std::size_t>(o.frames_per_step - 1));
      const double w = s_f - static_cast<double>(f0);
      const double extra_i = (1 - w) * spread[ks][f0] + w * spread[ks][f0 + 1];
      clearance.points.push_back({swing_x[i] + k * step + extra_i, swing_z[i]});
    }
    scene.shapes.push_back(std::move(clearance));
  }
  scene.axes.x_label = "x (m); each pose moved right by its spread (the last by " +
                       fixed(spread.back().back(), 2) + " m) so the poses stand side by side";
  // The legend above the figures, which now fill the width: one 18 px row per entry, box and margins.
  std::set<std::string> entries;
  for (const Shape& sh : scene.shapes)
    if (!sh.legend.empty()) entries.insert(sh.legend);
  for (const Marker& m : scene.markers)
    if (!m.legend.empty()) entries.insert(m.legend);
  scene.legend_headroom = 18.0 * static_cast<double>(entries.size()) + 8 + 16;
  return scene;
}

}  // namespace cyclopt::plot
