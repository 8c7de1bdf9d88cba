#include "cyclopt/plot/line_chart.hpp"

#include "cyclopt/plot/legend.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cyclopt::plot {

void start_at_zero(LineChart& chart) {
  double hi = 0;
  for (const Series& s : chart.series)
    for (double y : s.y)
      if (std::isfinite(y)) hi = std::max(hi, y);
  for (const Band& b : chart.bands)
    for (double y : b.high)
      if (std::isfinite(y)) hi = std::max(hi, y);
  chart.y_range = Range{0.0, hi > 0 ? 1.08 * hi : 1.0};
}

namespace {

void draw_band(const Axes& axes, Canvas& canvas, const Band& b) {
  const Color c{b.color.r, b.color.g, b.color.b, 0.18};
  std::vector<Point> low, high;
  auto flush = [&]() {
    if (low.size() >= 2) {
      low.insert(low.end(), high.rbegin(), high.rend());
      canvas.fill_polygon(low, c);
    }
    low.clear();
    high.clear();
  };
  for (std::size_t j = 0; j < b.x.size(); ++j) {
    if (!std::isfinite(b.x[j]) || !std::isfinite(b.low[j]) || !std::isfinite(b.high[j])) {
      flush();
      continue;
    }
    low.push_back(axes.to_pixel(b.x[j], b.low[j]));
    high.push_back(axes.to_pixel(b.x[j], b.high[j]));
  }
  flush();
}

// The finite data of the chart; throws for mismatched or empty series.
void data_of(const LineChart& chart, std::vector<double>& xs, std::vector<double>& ys) {
  for (const Series& s : chart.series) {
    if (s.x.size() != s.y.size())
      throw std::invalid_argument("series '" + s.label + "': x has " + std::to_string(s.x.size()) + " values, y has " +
                                  std::to_string(s.y.size()));
    bool any = false;
    for (std::size_t i = 0; i < s.x.size(); ++i)
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i])) {
        xs.push_back(s.x[i]);
        ys.push_back(s.y[i]);
        any = true;
      }
    if (!any) throw std::invalid_argument("series '" + s.label + "' has no finite point");
  }
  for (const Band& b : chart.bands) {
    if (b.low.size() != b.x.size() || b.high.size() != b.x.size())
      throw std::invalid_argument("band: x has " + std::to_string(b.x.size()) + " values, low " +
                                  std::to_string(b.low.size()) + ", high " + std::to_string(b.high.size()));
    for (std::size_t i = 0; i < b.x.size(); ++i)
      if (std::isfinite(b.x[i]) && std::isfinite(b.high[i])) {
        xs.push_back(b.x[i]);
        ys.push_back(b.high[i]);
      }
  }
  for (const ReferenceLine& r : chart.reference_lines) ys.push_back(r.y);
}

}  // namespace

void render(const LineChart& chart, const std::string& path, const RenderOptions& options) {
  std::vector<double> xs, ys;
  data_of(chart, xs, ys);  // throws before a file is made
  Canvas canvas(path, options.width, options.height);
  draw(chart, canvas);
  canvas.finish();
}

void draw(const LineChart& chart, Canvas& canvas) {
  std::vector<double> xs, ys;
  data_of(chart, xs, ys);
  canvas.fill_background({1, 1, 1, 1});
  Axes axes(canvas, chart.x_range.value_or(data_range(xs, 0.02)), chart.y_range.value_or(value_range(ys)),
            chart.axes);
  axes.draw_grid();
  axes.clip_to_plot_area();
  std::vector<Point> occupied;
  std::vector<LegendEntry> legend;
  for (const Band& b : chart.bands) draw_band(axes, canvas, b);
  for (const ReferenceLine& r : chart.reference_lines) {
    const Point a = axes.to_pixel(axes.x_range().lo, r.y), b = axes.to_pixel(axes.x_range().hi, r.y);
    canvas.line(a, b, kReferenceLineColor, 1.6, true);
    canvas.text({b.x - 6, b.y - 6}, r.label, 13, kReferenceLineColor, Align::right);
    occupied.push_back({b.x - 60, b.y - 10});
  }
  for (std::size_t i = 0; i < chart.series.size(); ++i) {
    const Series& s = chart.series[i];
    const Color c = s.color.value_or(palette(static_cast<int>(i)));
    std::vector<Point> run;
    auto flush = [&]() {
      canvas.polyline(run, c, s.width, s.dashed);
      run.clear();
    };
    for (std::size_t j = 0; j < s.x.size(); ++j) {
      if (!std::isfinite(s.x[j]) || !std::isfinite(s.y[j])) {
        flush();
        continue;
      }
      run.push_back(axes.to_pixel(s.x[j], s.y[j]));
      occupied.push_back(run.back());
      if (s.markers) canvas.circle(run.back(), 3.2, c);
    }
    flush();
    legend.push_back({s.label, c, s.dashed, true, s.markers});
  }
  axes.reset_clip();
  axes.draw_frame();
  draw_legend(canvas, axes, legend, occupied);
}

}  // namespace cyclopt::plot
