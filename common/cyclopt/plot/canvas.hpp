#pragma once
// A drawing surface that writes PNG, SVG or PDF (chosen by the file extension), on cairo.
//
// Why cairo: one drawing code path gives raster (PNG) and vector (SVG, PDF) output, in process,
// without a plotting program to spawn; it is a single Debian package (libcairo2-dev), and PNGs
// can be read back in tests to check what was drawn.
// Coordinates are pixels (points for SVG/PDF), origin top left, y down.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

typedef struct _cairo cairo_t;
typedef struct _cairo_surface cairo_surface_t;

namespace cyclopt::plot {

struct Color {
  double r = 0, g = 0, b = 0, a = 1;
};

// Ten well-separated colours for curves (the "tab10" palette); index k and k + kPaletteSize
// share a colour.
inline constexpr int kPaletteSize = 10;
Color palette(int index);

struct Point {
  double x = 0, y = 0;
};

enum class Align { left, center, right };

class Canvas {
 public:
  // Throws std::invalid_argument for an unknown extension (allowed: .png .svg .pdf).
  Canvas(const std::string& path, double width, double height);
  // Draws into `cr`, e.g. a page of a multi-page PDF (pdf_report.hpp), from its current origin;
  // the caller owns the context and its surface, finish() does nothing.
  Canvas(cairo_t* cr, double width, double height);
  ~Canvas();
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;

  double width() const { return width_; }
  double height() const { return height_; }

  void fill_background(Color c);
  void line(Point a, Point b, Color c, double width, bool dashed = false);
  void polyline(const std::vector<Point>& pts, Color c, double width, bool dashed = false, bool closed = false);
  void fill_polygon(const std::vector<Point>& pts, Color c);
  void circle(Point center, double radius, Color fill);
  void rectangle(Point top_left, double w, double h, Color stroke, Color fill, double width);
  // Text with its baseline at p.y, aligned horizontally at p.x; rotated by `degrees` about p.
  // `s` may hold sub- and superscripts (rich_text.hpp: "x_{H}^{-}").
  void text(Point p, std::string_view s, double size, Color c, Align align = Align::left, double degrees = 0,
            bool bold = false);
  double text_width(std::string_view s, double size, bool bold = false);
  // Restricts drawing to a rectangle until reset_clip().
  void clip(Point top_left, double w, double h);
  void reset_clip();

  // Writes the file (PNG) or finishes it (SVG, PDF). Called by the destructor if not before;
  // throws std::runtime_error when the file cannot be written.
  void finish();

 private:
  std::string path_;
  double width_, height_;
  bool png_;
  bool finished_ = false;
  bool owned_ = true;  // the surface and context are this canvas's
  cairo_surface_t* surface_ = nullptr;
  cairo_t* cr_ = nullptr;
};

}  // namespace cyclopt::plot
