#pragma once
// A legend box placed in the corner of the plot area that covers the fewest drawn points.

#include "cyclopt/plot/axes.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace cyclopt::plot {

struct LegendEntry {
  std::string text;
  Color color;
  bool dashed = false;
  bool line = true;    // a line sample
  bool marker = false; // a dot sample
};

// Pixels of plot-area height that a legend of `entries` rows takes, its margins included.
double legend_height(std::size_t entries);

// `occupied`: pixel positions of the data, used to choose the corner.
void draw_legend(Canvas& canvas, const Axes& axes, const std::vector<LegendEntry>& entries,
                 const std::vector<Point>& occupied);

}  // namespace cyclopt::plot
