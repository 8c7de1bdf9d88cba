#pragma once
// Cartesian axes on a canvas: data-to-pixel mapping, "nice" ticks, grid, frame and labels.
// Shared by line charts (independent x and y scales) and 2-D scenes (equal scales).

#include "cyclopt/plot/canvas.hpp"

#include <string>
#include <vector>

namespace cyclopt::plot {

struct Range {
  double lo = 0, hi = 1;
};

// Tick positions covering [lo, hi] with a step of 1, 2, 2.5 or 5 times a power of ten, about
// `target` of them; the first and last tick enclose the range.
std::vector<double> nice_ticks(Range r, int target = 6);

// Smallest range containing all finite values, padded by `pad` of its width on both sides;
// a degenerate or empty set gets a unit-width range around its value (or [0, 1]).
Range data_range(const std::vector<double>& values, double pad = 0.0);

// Share of the largest magnitude that a chart's value axis spans at least (value_range()).
inline constexpr double kMinRelativeSpan = 0.1;

// The range a chart's value (y) axis shows for `values`: data_range(values, 0.05), widened about
// its middle to at least kMinRelativeSpan of the largest |value|, so a near-constant quantity
// (a step length of 0.9818 to 0.9828 m) reads as the flat line it is, not as a steep one.
Range value_range(const std::vector<double>& values);

// Pixels Axes keeps around its plot area for tick labels, axis labels and the title.
inline constexpr double kAxesLeft = 80, kAxesRight = 24, kAxesBottom = 62;
inline constexpr double kAxesTopTitled = 48, kAxesTopUntitled = 20;

struct AxesStyle {
  std::string title;
  std::string x_label;  // with unit, e.g. "mean speed v (m/s)"
  std::string y_label;
  bool grid = true;
};

class Axes {
 public:
  // The plot area is the canvas minus margins for labels. With equal_scale the ranges are
  // widened so one metre is as long on both axes.
  Axes(Canvas& canvas, Range x, Range y, const AxesStyle& style, bool equal_scale = false);

  Point to_pixel(double x, double y) const;
  Range x_range() const { return x_; }
  Range y_range() const { return y_; }
  // Draws title, frame, ticks, tick labels and axis labels; call after the data so the frame
  // is on top, or before for a grid under the data (draw_grid()).
  void draw_grid();
  void draw_frame();
  // Restricts drawing to the plot area (curves leaving the ranges are cut).
  void clip_to_plot_area();
  void reset_clip();
  Point plot_top_left() const { return {left_, top_}; }
  double plot_width() const { return width_; }
  double plot_height() const { return height_; }

 private:
  Canvas& canvas_;
  Range x_, y_;
  AxesStyle style_;
  std::vector<double> xticks_, yticks_;
  double left_, top_, width_, height_;
};

}  // namespace cyclopt::plot
