#include "cyclopt/plot/legend.hpp"

#include <algorithm>
#include <array>

namespace cyclopt::plot {
namespace {

constexpr double kTextSize = 12, kRow = 18, kMargin = 8;

double box_height(std::size_t entries) { return kRow * static_cast<double>(entries) + 8; }

}  // namespace

double legend_height(std::size_t entries) { return entries == 0 ? 0.0 : box_height(entries) + 2 * kMargin; }

void draw_legend(Canvas& canvas, const Axes& axes, const std::vector<LegendEntry>& entries,
                 const std::vector<Point>& occupied) {
  if (entries.empty()) return;
  double w = 0;
  for (const LegendEntry& e : entries) w = std::max(w, canvas.text_width(e.text, kTextSize));
  const double box_w = w + 46, box_h = box_height(entries.size());
  const Point pa = axes.plot_top_left();
  const double left = pa.x + kMargin, right = pa.x + axes.plot_width() - box_w - kMargin;
  const double top = pa.y + kMargin, bottom = pa.y + axes.plot_height() - box_h - kMargin;
  const std::array<Point, 4> corners = {{{right, top}, {left, top}, {right, bottom}, {left, bottom}}};
  Point best = corners[0];
  long fewest = -1;
  for (const Point& c : corners) {
    const long covered = std::count_if(occupied.begin(), occupied.end(), [&](const Point& p) {
      return p.x >= c.x && p.x <= c.x + box_w && p.y >= c.y && p.y <= c.y + box_h;
    });
    if (fewest < 0 || covered < fewest) {
      fewest = covered;
      best = c;
    }
  }
  canvas.rectangle(best, box_w, box_h, {0.6, 0.6, 0.6, 1}, {1, 1, 1, 0.85}, 0.8);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const LegendEntry& e = entries[i];
    const double y = best.y + 4 + kRow * (static_cast<double>(i) + 0.5);
    if (e.line) canvas.line({best.x + 6, y}, {best.x + 32, y}, e.color, 2.2, e.dashed);
    if (e.marker) canvas.circle({best.x + 19, y}, e.line ? 3.2 : 4.0, e.color);
    canvas.text({best.x + 38, y + 4}, e.text, kTextSize, {0.1, 0.1, 0.1, 1});
  }
}

}  // namespace cyclopt::plot
