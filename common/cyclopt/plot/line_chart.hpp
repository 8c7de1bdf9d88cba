#pragma once
// Curves over a common x axis with a legend, e.g. cost of transport over walking speed for
// several feet (seed 001, Fig. 9.19a) or maximal joint torques over speed (Fig. 9.4).

#include "cyclopt/plot/axes.hpp"

#include <optional>
#include <string>
#include <vector>

namespace cyclopt::plot {

struct Series {
  std::string label;
  std::vector<double> x, y;  // same length; non-finite y values break the curve
  bool markers = true;
  bool dashed = false;
  std::optional<Color> color;  // default: palette(index)
  double width = 2.2;          // line width (px)
};

// A shaded area between two edges over the same x (e.g. the spread of several searches above
// their best), drawn beneath every series; non-finite values break it.
struct Band {
  std::vector<double> x, low, high;  // same length
  Color color;                       // drawn translucent
};

// A horizontal line across the plot area (e.g. the stability limit |Λ| = 1), dashed, its label
// above its right end; the value axis always shows it.
struct ReferenceLine {
  double y = 0;
  std::string label;
};
inline constexpr Color kReferenceLineColor{0.45, 0.1, 0.45, 1};

struct LineChart {
  AxesStyle axes;
  std::vector<Series> series;
  std::vector<Band> bands;
  std::vector<ReferenceLine> reference_lines;
  std::optional<Range> x_range, y_range;  // default: fitted to the data (y: value_range())
};

struct RenderOptions {
  double width = 900, height = 600;
};

// For quantities >= 0: the y axis from zero to 8 % above the largest finite value, so curves
// compare by ratio at a glance.
void start_at_zero(LineChart& chart);

// Writes the chart to `path` (.png, .svg or .pdf). Throws std::invalid_argument for series with
// mismatched lengths or no finite point at all, std::runtime_error when the file cannot be written.
void render(const LineChart& chart, const std::string& path, const RenderOptions& options = {});
// The same drawing on a canvas of the caller's (a PDF page).
void draw(const LineChart& chart, Canvas& canvas);

}  // namespace cyclopt::plot
