#include "cyclopt/plot/scene.hpp"

#include "cyclopt/plot/legend.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

namespace cyclopt::plot {
namespace {

constexpr Color kGround{0.35, 0.25, 0.15, 1};

std::vector<LegendEntry> legend_entries(const Scene& scene) {
  std::vector<LegendEntry> out;
  std::set<std::string> seen;
  for (const Shape& s : scene.shapes)
    if (!s.legend.empty() && seen.insert(s.legend).second) out.push_back({s.legend, s.color, s.dashed, true, false});
  for (const Marker& m : scene.markers)
    if (!m.legend.empty() && seen.insert(m.legend).second) out.push_back({m.legend, m.color, false, false, true});
  return out;
}

// All drawn coordinates of the scene (shapes, markers, ground height).
void content(const Scene& scene, std::vector<double>& xs, std::vector<double>& zs) {
  for (const Shape& s : scene.shapes)
    for (const auto& p : s.points) {
      xs.push_back(p[0]);
      zs.push_back(p[1]);
    }
  for (const Marker& m : scene.markers) {
    xs.push_back(m.x);
    zs.push_back(m.z);
  }
  for (const Label& l : scene.labels) {
    xs.push_back(l.x);
    zs.push_back(l.z);
  }
  if (scene.ground_z) zs.push_back(*scene.ground_z);
}

// Margins Axes keeps around the plot area of a titled scene, across and down.
constexpr double kMarginsX = kAxesLeft + kAxesRight, kMarginsZ = kAxesTopTitled + kAxesBottom;

// The plot area's data ranges on a canvas of w x h: the padded content at the largest equal scale
// (px/m) that fits it beside legend_room and under legend_headroom, those pixels added as metres.
struct Layout {
  Range x, z;
};
Layout layout(const Scene& scene, const std::vector<double>& xs, const std::vector<double>& zs, double w, double h) {
  Layout l{data_range(xs, scene.pad), data_range(zs, scene.pad)};
  const double scale = std::min((w - kMarginsX - scene.legend_room) / (l.x.hi - l.x.lo),
                                (h - kMarginsZ - scene.legend_headroom) / (l.z.hi - l.z.lo));
  l.x.hi += scene.legend_room / scale;
  l.z.hi += scene.legend_headroom / scale;
  return l;
}

}  // namespace

RenderOptions fitted_options(const Scene& scene, double height, double min_width, double max_width) {
  std::vector<double> xs, zs;
  content(scene, xs, zs);
  const Range x = data_range(xs, scene.pad), z = data_range(zs, scene.pad);
  const double fixed_x = kMarginsX + scene.legend_room, fixed_z = kMarginsZ + scene.legend_headroom;
  // The legend is drawn inside the plot area, so that is at least as high as the legend.
  const double legend_fits = kMarginsZ + legend_height(legend_entries(scene).size());
  height = std::max(height, legend_fits);
  const double width = fixed_x + (height - fixed_z) * (x.hi - x.lo) / (z.hi - z.lo);
  if (width <= max_width) return {std::max(width, min_width), height};
  return {max_width, std::max(legend_fits, fixed_z + (max_width - fixed_x) * (z.hi - z.lo) / (x.hi - x.lo))};
}

void render(const Scene& scene, const std::string& path, const RenderOptions& options) {
  std::vector<double> xs, zs;
  content(scene, xs, zs);
  if (xs.empty()) throw std::invalid_argument("scene '" + scene.axes.title + "' has nothing to draw");
  Canvas canvas(path, options.width, options.height);
  draw(scene, canvas);
  canvas.finish();
}

void draw(const Scene& scene, Canvas& canvas) {
  std::vector<double> xs, zs;
  content(scene, xs, zs);
  if (xs.empty()) throw std::invalid_argument("scene '" + scene.axes.title + "' has nothing to draw");
  canvas.fill_background({1, 1, 1, 1});
  const Layout l = layout(scene, xs, zs, canvas.width(), canvas.height());
  Axes axes(canvas, l.x, l.z, scene.axes, /*equal_scale=*/true);
  axes.draw_grid();
  axes.clip_to_plot_area();
  if (scene.ground_z) {
    const Range xr = axes.x_range();
    const Point a = axes.to_pixel(xr.lo, *scene.ground_z), b = axes.to_pixel(xr.hi, *scene.ground_z);
    canvas.fill_polygon({a, b, {b.x, b.y + 14}, {a.x, a.y + 14}}, {0.93, 0.89, 0.83, 1});
    for (double x = a.x; x < b.x; x += 12) canvas.line({x, a.y}, {x - 10, a.y + 12}, kGround, 0.8);
    canvas.line(a, b, kGround, 2.0);
  }
  std::vector<Point> occupied;
  for (const Shape& s : scene.shapes) {
    std::vector<Point> px;
    px.reserve(s.points.size());
    for (const auto& p : s.points) px.push_back(axes.to_pixel(p[0], p[1]));
    occupied.insert(occupied.end(), px.begin(), px.end());
    if (s.fill) canvas.fill_polygon(px, *s.fill);
    canvas.polyline(px, s.color, s.width, s.dashed, s.closed);
  }
  for (const Marker& m : scene.markers) {
    occupied.push_back(axes.to_pixel(m.x, m.z));
    canvas.circle(occupied.back(), m.radius, m.color);
  }
  for (const Label& l : scene.labels) {
    const Point p = axes.to_pixel(l.x, l.z);
    canvas.text({p.x, p.y + 0.35 * l.size}, l.text, l.size, l.color, Align::center);
  }
  axes.reset_clip();
  axes.draw_frame();
  draw_legend(canvas, axes, legend_entries(scene), occupied);
}

}  // namespace cyclopt::plot
