#include "cyclopt/plot/gait_animation.hpp"

#include "cyclopt/plot/foot_figures.hpp"
#include "cyclopt/plot/walker_pose.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace cyclopt::plot {
namespace {

constexpr double kHeight = 300;  // px of the drawing between its lowest and highest point
constexpr double kMargin = 16;   // px around it

// The drawn parts of one pose, legs named by leg (A: stance in even steps), not by role.
struct Parts {
  std::vector<Xz> torso, leg_a, leg_b, foot_a, foot_b;
};

Parts parts_of(const WalkerPose& p, int step, double dx) {
  auto at = [dx](std::vector<Xz> pts) {
    for (Xz& q : pts) q[0] += dx;
    return pts;
  };
  const bool even = step % 2 == 0;
  const std::vector<Xz> stance = at({p.hip, p.knee1, p.ankle1}), swing = at({p.hip, p.knee2, p.ankle2});
  return {at({p.hip, p.torso_tip}), even ? stance : swing, even ? swing : stance, at(even ? p.foot1 : p.foot2),
          at(even ? p.foot2 : p.foot1)};
}

}  // namespace

std::string gait_animation_svg(const WalkerJobResults& job, const GaitPoint& point, int frames_per_step) {
  if (frames_per_step < 1)
    throw std::invalid_argument("gait animation: frames_per_step is " + std::to_string(frames_per_step) + " (needs >= 1)");
  if (!point.trajectory || point.trajectory->time.size() < 2)
    throw std::invalid_argument("gait animation: the point at " + std::to_string(point.speed) +
                                " m/s has no stored trajectory of >= 2 samples");
  const walker::WalkerModel<double> model = job.job.model();
  const std::vector<Xz> outline = model.has_feet() ? foot_outline(job.job.foot) : std::vector<Xz>{};
  const records::GaitTrajectoryRecord& tr = *point.trajectory;
  const double period = tr.time.back(), step = point.gait.step_length, dt = period / frames_per_step;
  // Two steps, so both legs stand and swing once; the last pose ends where the loop starts again.
  std::vector<Parts> poses;
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, z1 = 0;  // the ground z = 0 is the bottom
  for (int k = 0; k < 2; ++k)
    for (int f = k == 0 ? 0 : 1; f <= frames_per_step; ++f) {
      poses.push_back(parts_of(walker_pose(model, q_at(tr, f * dt), outline), k, k * step));
      for (const std::vector<Xz>* part : {&poses.back().torso, &poses.back().leg_a, &poses.back().leg_b,
                                          &poses.back().foot_a, &poses.back().foot_b})
        for (const Xz& q : *part) {
          x0 = std::min(x0, q[0]);
          x1 = std::max(x1, q[0]);
          z1 = std::max(z1, q[1]);
        }
    }
  const double scale = kHeight / z1, width = (x1 - x0) * scale + 2 * kMargin, height = kHeight + 2 * kMargin;
  auto points = [&](const std::vector<Xz>& pts) {
    std::string s;
    char b[48];
    for (const Xz& q : pts) {
      if (!s.empty()) s += ' ';
      std::snprintf(b, sizeof b, "%.1f,%.1f", kMargin + (q[0] - x0) * scale, kMargin + (z1 - q[1]) * scale);
      s += b;
    }
    return s;
  };
  char head[400];
  std::snprintf(head, sizeof head,
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\">\n"
                "<rect width=\"100%%\" height=\"100%%\" fill=\"#ffffff\"/>\n"
                "<line x1=\"0\" y1=\"%.1f\" x2=\"%.0f\" y2=\"%.1f\" stroke=\"#59402a\" stroke-width=\"2\"/>\n",
                width, height + 8, width, height + 8, kMargin + z1 * scale, width, kMargin + z1 * scale);
  std::string svg = std::string(head);
  char duration[32];
  std::snprintf(duration, sizeof duration, "%.4fs", 2 * period);  // real time: two steps
  auto animated = [&](const std::string& element, const std::string& style, std::vector<Xz> Parts::*part) {
    if ((poses.front().*part).empty()) return;  // point feet
    std::string values;
    for (const Parts& p : poses) {
      if (!values.empty()) values += ';';
      values += points(p.*part);
    }
    svg.append("<").append(element).append(" ").append(style).append(" points=\"").append(points(poses.front().*part));
    svg.append("\"><animate attributeName=\"points\" dur=\"").append(duration);
    svg.append("\" repeatCount=\"indefinite\" values=\"").append(values).append("\"/></").append(element).append(">\n");
  };
  const std::string line = "fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\"";
  animated("polyline", line + " stroke=\"#404040\" stroke-width=\"4\"", &Parts::torso);
  animated("polyline", line + " stroke=\"#d65f00\" stroke-width=\"3\"", &Parts::leg_b);
  animated("polygon", "fill=\"#d65f00\" fill-opacity=\"0.15\" stroke=\"#d65f00\" stroke-width=\"1.5\"", &Parts::foot_b);
  animated("polyline", line + " stroke=\"#1f77b5\" stroke-width=\"3\"", &Parts::leg_a);
  animated("polygon", "fill=\"#1f77b5\" fill-opacity=\"0.15\" stroke=\"#1f77b5\" stroke-width=\"1.5\"", &Parts::foot_a);
  return svg + "</svg>\n";
}

}  // namespace cyclopt::plot
