#include "cyclopt/plot/gait_animation.hpp"

#include "cyclopt/plot/foot_figures.hpp"
#include "cyclopt/plot/walker_pose.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace cyclopt::plot {
namespace {

constexpr double kHeight = 230;  // px of the drawing between its lowest and highest point
constexpr double kMargin = 12;   // px around it
constexpr double kHeader = 30;   // px above it: the clock
constexpr double kFooter = 44;   // px below the ground: the time bar and its marks
constexpr double kMinWidth = 300;  // px, so that the time bar's marks fit
constexpr const char* kFont = "font-family=\"DejaVu Sans,Helvetica,Arial,sans-serif\" fill=\"#1a1a1a\"";

std::string format(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

// The clock "t = ... s": one <text> per interval between two poses, shown during its interval
// only (SMIL animates attributes, not text content); the first is also the static picture's.
std::string clock_svg(int intervals, double dt, const std::string& duration, double x, double y) {
  std::string svg = "<g id=\"gait-clock\" " + std::string(kFont) + " font-size=\"14\" font-weight=\"bold\">\n";
  for (int k = 0; k < intervals; ++k) {
    const std::string from = format("%.6f", static_cast<double>(k) / intervals),
                      to = format("%.6f", static_cast<double>(k + 1) / intervals);
    std::string values = "hidden;visible;hidden", times = "0;" + from + ";" + to;
    if (k == 0) values = "visible;hidden", times = "0;" + to;
    if (k + 1 == intervals) values = k == 0 ? "visible" : "hidden;visible", times = k == 0 ? "0" : "0;" + from;
    svg += format("<text x=\"%.1f\"", x) + format(" y=\"%.1f\"", y) + " visibility=\"" + (k == 0 ? "visible" : "hidden") +
           "\">t = " + format("%.2f", k * dt) + " s<animate attributeName=\"visibility\" calcMode=\"discrete\" dur=\"" +
           duration + "\" repeatCount=\"indefinite\" values=\"" + values + "\" keyTimes=\"" + times + "\"/></text>\n";
  }
  return svg + "</g>\n";
}

// The time bar: fills from left to right over the loop of two steps, marked at 0, T and 2 T.
std::string time_bar_svg(double period, const std::string& duration, double x0, double x1, double y) {
  const double mid = 0.5 * (x0 + x1);
  std::string svg = "<g id=\"gait-time-bar\">\n";
  svg += format("<rect x=\"%.1f\"", x0) + format(" y=\"%.1f\"", y) + format(" width=\"%.1f\"", x1 - x0) +
         " height=\"8\" fill=\"#e6e6e6\" stroke=\"#999999\" stroke-width=\"0.5\"/>\n";
  svg += format("<rect x=\"%.1f\"", x0) + format(" y=\"%.1f\"", y) +
         " width=\"0\" height=\"8\" fill=\"#404040\"><animate attributeName=\"width\" from=\"0\" to=\"" +
         format("%.1f", x1 - x0) + "\" dur=\"" + duration + "\" repeatCount=\"indefinite\"/></rect>\n";
  for (const double x : {x0, mid, x1})
    svg += format("<line x1=\"%.1f\"", x) + format(" y1=\"%.1f\"", y - 3) + format(" x2=\"%.1f\"", x) +
           format(" y2=\"%.1f\"", y + 11) + " stroke=\"#404040\" stroke-width=\"1.5\"/>\n";
  const std::string text = "<text " + std::string(kFont) + " font-size=\"12\"" + format(" y=\"%.1f\"", y + 24);
  svg += text + format(" x=\"%.1f\"", x0) + ">0 s</text>\n";
  svg += text + format(" x=\"%.1f\"", mid) + " text-anchor=\"middle\">T = " + format("%.3f", period) + " s</text>\n";
  svg += text + format(" x=\"%.1f\"", x1) + " text-anchor=\"end\">2T</text>\n";
  return svg + "</g>\n";
}

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
  const walker::WalkerModel<double> model = job.walker.model();
  const std::vector<Xz> outline = model.has_feet() ? foot_outline(job.walker.foot) : std::vector<Xz>{};
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
  const double scale = kHeight / z1, drawing = (x1 - x0) * scale + 2 * kMargin, width = std::max(drawing, kMinWidth);
  const double left = 0.5 * (width - drawing) + kMargin, ground = kHeader + kMargin + kHeight;
  const double height = ground + kFooter;
  auto points = [&](const std::vector<Xz>& pts) {
    std::string s;
    char b[48];
    for (const Xz& q : pts) {
      if (!s.empty()) s += ' ';
      std::snprintf(b, sizeof b, "%.1f,%.1f", left + (q[0] - x0) * scale, ground - q[1] * scale);
      s += b;
    }
    return s;
  };
  char head[400];
  std::snprintf(head, sizeof head,
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\">\n"
                "<rect width=\"100%%\" height=\"100%%\" fill=\"#ffffff\"/>\n"
                "<line x1=\"0\" y1=\"%.1f\" x2=\"%.0f\" y2=\"%.1f\" stroke=\"#59402a\" stroke-width=\"2\"/>\n",
                width, height, width, height, ground, width, ground);
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
  svg += clock_svg(2 * frames_per_step, dt, duration, kMargin, 22);
  svg += time_bar_svg(period, duration, kMargin, width - kMargin, ground + 10);
  return svg + "</svg>\n";
}

}  // namespace cyclopt::plot
