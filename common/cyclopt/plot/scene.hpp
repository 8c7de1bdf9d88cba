#pragma once
// A 2-D drawing in metres with equal scales on both axes: foot outlines (seed 001, Fig. 3.5),
// stick-figure stroboscopes of gaits (Fig. 9.2) and giant swings (seed 000, Fig. 5.5).

#include "cyclopt/plot/axes.hpp"
#include "cyclopt/plot/line_chart.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace cyclopt::plot {

struct Shape {
  std::vector<std::array<double, 2>> points;  // (x, z) in metres
  Color color{0.1, 0.1, 0.1, 1};
  double width = 1.6;  // pixels
  bool dashed = false;
  bool closed = false;
  std::optional<Color> fill;
  std::string legend;  // shown in the legend when not empty
};

struct Marker {
  double x = 0, z = 0;
  Color color{0.84, 0.15, 0.16, 1};
  double radius = 4;   // pixels
  std::string legend;  // shown in the legend when not empty (once per distinct text)
};

struct Label {
  double x = 0, z = 0;  // the text's centre (m)
  std::string text;
  Color color{0.1, 0.1, 0.1, 1};
  double size = 11;  // pixels
};

struct Scene {
  AxesStyle axes;
  std::vector<Shape> shapes;
  std::vector<Marker> markers;
  std::vector<Label> labels;       // e.g. time stamps at frames
  std::optional<double> ground_z;  // draws the ground line and hatching at this height
  double pad = 0.05;               // margin around the content, fraction of its size
  double legend_room = 0;          // pixels kept empty right of the content for the legend
  double legend_headroom = 0;      // pixels kept empty above the content for the legend
};

// The width (px) of the HTML report's column: a figure at most this wide is shown at its own size,
// so its letters are as large as every other figure's.
inline constexpr double kPageWidth = 940;

// Options whose size gives the scene's content (with its pad and legend room) the plot area's
// aspect ratio, so equal scales waste no space: `height` pixels high, or, where that would be wider
// than max_width, max_width wide and as high as the content then needs; at least min_width wide,
// and high enough that the plot area holds the scene's legend.
RenderOptions fitted_options(const Scene& scene, double height, double min_width = 600, double max_width = 1800);

// Writes the scene to `path` (.png, .svg or .pdf); throws std::invalid_argument for an empty scene.
void render(const Scene& scene, const std::string& path, const RenderOptions& options = {});
// The same drawing on a canvas of the caller's (a PDF page).
void draw(const Scene& scene, Canvas& canvas);

}  // namespace cyclopt::plot
