#include "cyclopt/plot/canvas.hpp"

#include "cyclopt/plot/rich_text.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <array>
#include <cmath>
#include <stdexcept>

namespace cyclopt::plot {
namespace {

bool ends_with(const std::string& s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

void set_color(cairo_t* cr, Color c) { cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a); }

}  // namespace

Color palette(int index) {
  static constexpr std::array<Color, kPaletteSize> kTab10 = {{{0.122, 0.467, 0.706, 1},
                                                    {1.000, 0.498, 0.055, 1},
                                                    {0.173, 0.627, 0.173, 1},
                                                    {0.839, 0.153, 0.157, 1},
                                                    {0.580, 0.404, 0.741, 1},
                                                    {0.549, 0.337, 0.294, 1},
                                                    {0.890, 0.467, 0.761, 1},
                                                    {0.498, 0.498, 0.498, 1},
                                                    {0.737, 0.741, 0.133, 1},
                                                    {0.090, 0.745, 0.812, 1}}};
  return kTab10[static_cast<std::size_t>(index) % kTab10.size()];
}

Canvas::Canvas(const std::string& path, double width, double height)
    : path_(path), width_(width), height_(height), png_(ends_with(path, ".png")) {
  if (png_) {
    surface_ = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, static_cast<int>(std::lround(width)),
                                          static_cast<int>(std::lround(height)));
  } else if (ends_with(path, ".svg")) {
    surface_ = cairo_svg_surface_create(path.c_str(), width, height);
  } else if (ends_with(path, ".pdf")) {
    surface_ = cairo_pdf_surface_create(path.c_str(), width, height);
  } else {
    throw std::invalid_argument("plot output '" + path + "': extension must be .png, .svg or .pdf");
  }
  if (cairo_surface_status(surface_) != CAIRO_STATUS_SUCCESS) {
    const std::string why = cairo_status_to_string(cairo_surface_status(surface_));
    cairo_surface_destroy(surface_);
    throw std::runtime_error("cannot create plot '" + path + "': " + why);
  }
  cr_ = cairo_create(surface_);
  cairo_set_line_join(cr_, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr_, CAIRO_LINE_CAP_ROUND);
}

Canvas::Canvas(cairo_t* cr, double width, double height)
    : width_(width), height_(height), png_(false), finished_(true), owned_(false), cr_(cr) {
  cairo_set_line_join(cr_, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr_, CAIRO_LINE_CAP_ROUND);
}

Canvas::~Canvas() {
  try {
    finish();
  } catch (...) {
    // A destructor must not throw; callers who care call finish() themselves.
  }
  if (!owned_) return;
  if (cr_) cairo_destroy(cr_);
  if (surface_) cairo_surface_destroy(surface_);
}

void Canvas::finish() {
  if (finished_) return;
  finished_ = true;
  cairo_surface_flush(surface_);
  if (png_) {
    if (cairo_surface_write_to_png(surface_, path_.c_str()) != CAIRO_STATUS_SUCCESS)
      throw std::runtime_error("cannot write plot '" + path_ + "'");
  } else {
    cairo_surface_finish(surface_);
    if (cairo_surface_status(surface_) != CAIRO_STATUS_SUCCESS)
      throw std::runtime_error("cannot write plot '" + path_ + "': " +
                               cairo_status_to_string(cairo_surface_status(surface_)));
  }
}

void Canvas::fill_background(Color c) {
  set_color(cr_, c);
  cairo_paint(cr_);
}

void Canvas::line(Point a, Point b, Color c, double width, bool dashed) { polyline({a, b}, c, width, dashed); }

void Canvas::polyline(const std::vector<Point>& pts, Color c, double width, bool dashed, bool closed) {
  if (pts.size() < 2) return;
  cairo_new_path(cr_);
  cairo_move_to(cr_, pts[0].x, pts[0].y);
  for (std::size_t i = 1; i < pts.size(); ++i) cairo_line_to(cr_, pts[i].x, pts[i].y);
  if (closed) cairo_close_path(cr_);
  const double dash[] = {6.0 * width, 4.0 * width};
  cairo_set_dash(cr_, dash, dashed ? 2 : 0, 0);
  cairo_set_line_width(cr_, width);
  set_color(cr_, c);
  cairo_stroke(cr_);
  cairo_set_dash(cr_, nullptr, 0, 0);
}

void Canvas::fill_polygon(const std::vector<Point>& pts, Color c) {
  if (pts.size() < 3) return;
  cairo_new_path(cr_);
  cairo_move_to(cr_, pts[0].x, pts[0].y);
  for (std::size_t i = 1; i < pts.size(); ++i) cairo_line_to(cr_, pts[i].x, pts[i].y);
  cairo_close_path(cr_);
  set_color(cr_, c);
  cairo_fill(cr_);
}

void Canvas::circle(Point center, double radius, Color fill) {
  cairo_new_path(cr_);
  cairo_arc(cr_, center.x, center.y, radius, 0, 2 * M_PI);
  set_color(cr_, fill);
  cairo_fill(cr_);
}

void Canvas::rectangle(Point top_left, double w, double h, Color stroke, Color fill, double width) {
  cairo_new_path(cr_);
  cairo_rectangle(cr_, top_left.x, top_left.y, w, h);
  set_color(cr_, fill);
  cairo_fill_preserve(cr_);
  set_color(cr_, stroke);
  cairo_set_line_width(cr_, width);
  cairo_stroke(cr_);
}

namespace {

// Sub- and superscripts (rich_text.hpp): 70 % of the size, lowered by a quarter or raised by
// 40 % of the size.
constexpr double kShiftedSize = 0.7, kSubscriptDrop = 0.25, kSuperscriptRise = 0.4;

double run_width(cairo_t* cr, const TextRun& r, double size, bool bold) {
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, r.shift == 0 ? size : kShiftedSize * size);
  cairo_text_extents_t ext;
  cairo_text_extents(cr, r.text.c_str(), &ext);
  return ext.x_advance;
}

}  // namespace

double Canvas::text_width(std::string_view s, double size, bool bold) {
  double w = 0;
  for (const TextRun& r : rich_text_runs(s)) w += run_width(cr_, r, size, bold);
  return w;
}

void Canvas::text(Point p, std::string_view s, double size, Color c, Align align, double degrees, bool bold) {
  const double w = text_width(s, size, bold);
  double x = align == Align::left ? 0.0 : align == Align::center ? -0.5 * w : -w;
  cairo_save(cr_);
  cairo_translate(cr_, p.x, p.y);
  cairo_rotate(cr_, degrees * M_PI / 180.0);
  set_color(cr_, c);
  for (const TextRun& r : rich_text_runs(s)) {
    const double advance = run_width(cr_, r, size, bold);  // also selects the run's font and size
    const double y = r.shift < 0 ? kSubscriptDrop * size : r.shift > 0 ? -kSuperscriptRise * size : 0.0;
    cairo_move_to(cr_, x, y);
    cairo_show_text(cr_, r.text.c_str());
    x += advance;
  }
  cairo_restore(cr_);
}

void Canvas::clip(Point top_left, double w, double h) {
  cairo_new_path(cr_);
  cairo_rectangle(cr_, top_left.x, top_left.y, w, h);
  cairo_clip(cr_);
}

void Canvas::reset_clip() { cairo_reset_clip(cr_); }

}  // namespace cyclopt::plot
