#pragma once
// Reads a PNG back (cairo) so tests can check what a plot really drew.

#include "cyclopt/plot/canvas.hpp"

#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <string>

namespace cyclopt::plot::testing {

// A fresh-enough folder for a test binary's pictures under the temporary directory.
inline std::filesystem::path output_dir(const std::string& name) {
  const std::filesystem::path d = std::filesystem::temp_directory_path() / name;
  std::filesystem::create_directories(d);
  return d;
}

struct PngImage {
  int width = 0, height = 0;
  int drawn_pixels = 0;  // pixels that are not (near) white
  // Pixels within `tol` of colour c (RGB, 0..1).
  int count(const Color& c, double tol = 0.08) const;
  // Leftmost and rightmost column with a pixel within `tol` of colour c in rows [row0, row1)
  // ({-1, -1} when there is none).
  std::array<int, 2> columns_of(const Color& c, int row0, int row1, double tol = 0.08) const;
  std::string path;
};

inline PngImage inspect_png(const std::string& path) {
  PngImage img;
  img.path = path;
  cairo_surface_t* s = cairo_image_surface_create_from_png(path.c_str());
  if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(s);
    return img;
  }
  img.width = cairo_image_surface_get_width(s);
  img.height = cairo_image_surface_get_height(s);
  const unsigned char* data = cairo_image_surface_get_data(s);
  const int stride = cairo_image_surface_get_stride(s);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const unsigned char* px = data + y * stride + 4 * x;  // BGRA
      if (px[0] < 235 || px[1] < 235 || px[2] < 235) ++img.drawn_pixels;
    }
  cairo_surface_destroy(s);
  return img;
}

// Calls visit(x, y) for every pixel within `tol` of colour c in rows [row0, row1).
template <class Visit>
void for_pixels_of(const std::string& path, const Color& c, double tol, int row0, int row1, Visit visit) {
  cairo_surface_t* s = cairo_image_surface_create_from_png(path.c_str());
  if (cairo_surface_status(s) == CAIRO_STATUS_SUCCESS) {
    const int width = cairo_image_surface_get_width(s), height = cairo_image_surface_get_height(s);
    const unsigned char* data = cairo_image_surface_get_data(s);
    const int stride = cairo_image_surface_get_stride(s);
    for (int y = std::max(row0, 0); y < std::min(row1, height); ++y)
      for (int x = 0; x < width; ++x) {
        const unsigned char* px = data + y * stride + 4 * x;  // BGRA
        if (std::abs(px[2] / 255.0 - c.r) < tol && std::abs(px[1] / 255.0 - c.g) < tol && std::abs(px[0] / 255.0 - c.b) < tol)
          visit(x, y);
      }
  }
  cairo_surface_destroy(s);
}

inline int PngImage::count(const Color& c, double tol) const {
  int n = 0;
  for_pixels_of(path, c, tol, 0, height, [&n](int, int) { ++n; });
  return n;
}

inline std::array<int, 2> PngImage::columns_of(const Color& c, int row0, int row1, double tol) const {
  std::array<int, 2> cols{-1, -1};
  for_pixels_of(path, c, tol, row0, row1, [&cols](int x, int) {
    cols = {cols[0] < 0 ? x : std::min(cols[0], x), std::max(cols[1], x)};
  });
  return cols;
}

}  // namespace cyclopt::plot::testing
