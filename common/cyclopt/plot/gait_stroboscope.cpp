#include "cyclopt/plot/gait_stroboscope.hpp"

#include "cyclopt/plot/foot_figures.hpp"
#include "cyclopt/plot/walker_pose.hpp"

#include <algorithm>
#include <cmath>
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

std::string leg_label(const Color& c) {
  return c.b == kLegA.b ? "leg A (stance in step 1)" : "leg B (swing in step 1)";
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
  scene.axes = {"v = " + fixed(point.gait.mean_speed, 2) + " m/s" +
                    (o.legend ? ": " + std::to_string(o.steps * o.frames_per_step + 1) + " poses " + fixed(dt * 1000, 0) +
                                    " ms apart"
                              : std::string()),
                o.legend ? "x (m), stance ankle at impact at 0" : "x (m)", "z (m)", false};
  scene.ground_z = 0.0;
  scene.pad = 0.04;
  const double peak_clearance = *std::max_element(swing_z.begin(), swing_z.end());
  for (int k = 0; k < o.steps; ++k) {
    const double dx = k * step;  // step k: the same motion one step length on, the legs swapped
    // Leg "A" is the stance leg of even steps; the legs swap roles at every impact.
    const Color stance = k % 2 == 0 ? kLegA : kLegB, swing = k % 2 == 0 ? kLegB : kLegA;
    for (int f = k == 0 ? 0 : 1; f <= o.frames_per_step; ++f) {
      const WalkerPose p = walker_pose(model, q_at(tr, f * dt), outline);
      const double fade = 0.3 + 0.7 * (k * o.frames_per_step + f) / double(o.steps * o.frames_per_step);
      auto faded = [fade](Color c) { return Color{c.r, c.g, c.b, fade}; };
      // Legends on the last, fully opaque frame (the legend takes the first labelled shape's colour).
      const bool last = o.legend && k + 1 == o.steps && f == o.frames_per_step;
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
      scene.markers.push_back({p.contact[0] + dx, p.contact[1], kContact, 4.0, o.legend ? "contact point C_{1}" : ""});
      scene.markers.push_back({p.hip[0] + dx, p.hip[1], kTorso, 3.0, ""});
    }
    // The swing foot's lowest point over the step, where it is.
    Shape clearance{{}, kClearance, 1.8, true, false, std::nullopt,
                    o.legend ? "swing foot C_{2} (peak " + fixed(peak_clearance * 100, 1) + " cm up)" : ""};
    for (std::size_t i = 0; i < swing_x.size(); ++i) clearance.points.push_back({swing_x[i] + dx, swing_z[i]});
    scene.shapes.push_back(std::move(clearance));
  }
  // The legend above the figures: one 18 px row per entry, box and margins.
  std::set<std::string> entries;
  for (const Shape& sh : scene.shapes)
    if (!sh.legend.empty()) entries.insert(sh.legend);
  for (const Marker& m : scene.markers)
    if (!m.legend.empty()) entries.insert(m.legend);
  scene.legend_headroom = 18.0 * static_cast<double>(entries.size()) + 8 + 16;
  return scene;
}

}  // namespace cyclopt::plot
