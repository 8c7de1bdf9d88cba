#pragma once
// Reads a PNG back (cairo) so tests can check what a plot really drew.

#include "cyclopt/plot/canvas.hpp"

#include <cairo.h>

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

inline int PngImage::count(const Color& c, double tol) const {
  cairo_surface_t* s = cairo_image_surface_create_from_png(path.c_str());
  int n = 0;
  if (cairo_surface_status(s) == CAIRO_STATUS_SUCCESS) {
    const unsigned char* data = cairo_image_surface_get_data(s);
    const int stride = cairo_image_surface_get_stride(s);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const unsigned char* px = data + y * stride + 4 * x;
        if (std::abs(px[2] / 255.0 - c.r) < tol && std::abs(px[1] / 255.0 - c.g) < tol && std::abs(px[0] / 255.0 - c.b) < tol) ++n;
      }
  }
  cairo_surface_destroy(s);
  return n;
}

}  // namespace cyclopt::plot::testing
