#include "cyclopt/plot/axes.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace cyclopt::plot {
namespace {

constexpr Color kInk{0.1, 0.1, 0.1, 1};
constexpr Color kGrid{0.88, 0.88, 0.88, 1};

// Enough decimals to tell neighbouring ticks apart (one more for steps of 2.5 x 10^n).
std::string tick_label(double v, double step) {
  if (std::abs(v) < 1e-12 * step) v = 0.0;
  const double exponent = std::floor(std::log10(step) + 1e-9);
  const bool quarter = std::abs(step / std::pow(10.0, exponent) - 2.5) < 1e-9;
  const int decimals = std::clamp(static_cast<int>(-exponent) + (quarter ? 1 : 0), 0, 6);
  char buf[32];
  const double mag = std::abs(v);
  if (mag != 0.0 && (mag >= 1e5 || mag < 1e-3))
    std::snprintf(buf, sizeof buf, "%.2g", v);
  else
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

Range widen_to(Range r, double width) {
  const double mid = 0.5 * (r.lo + r.hi);
  return {mid - 0.5 * width, mid + 0.5 * width};
}

}  // namespace

std::vector<double> nice_ticks(Range r, int target) {
  const double span = r.hi - r.lo;
  if (!(span > 0) || !std::isfinite(span)) return {r.lo};
  const double raw = span / std::max(target, 1);
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10 * mag;
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * mag >= raw) {
      step = m * mag;
      break;
    }
  std::vector<double> t;
  const double first = std::floor(r.lo / step + 1e-9) * step;
  for (double v = first; v <= r.hi + step * (1 - 1e-9); v += step) t.push_back(v);
  if (t.back() < r.hi - 1e-9 * step) t.push_back(t.back() + step);
  return t;
}

Range data_range(const std::vector<double>& values, double pad) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double v : values)
    if (std::isfinite(v)) {
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  if (!std::isfinite(lo)) return {0.0, 1.0};
  if (hi - lo <= 1e-12 * std::max(1.0, std::abs(lo))) return {lo - 0.5, hi + 0.5};
  const double w = hi - lo;
  return {lo - pad * w, hi + pad * w};
}

Range value_range(const std::vector<double>& values) {
  const Range r = data_range(values, 0.05);
  double magnitude = 0;
  for (double v : values)
    if (std::isfinite(v)) magnitude = std::max(magnitude, std::abs(v));
  const double min_span = kMinRelativeSpan * magnitude;
  return r.hi - r.lo < min_span ? widen_to(r, min_span) : r;
}

Axes::Axes(Canvas& canvas, Range x, Range y, const AxesStyle& style, bool equal_scale)
    : canvas_(canvas), style_(style) {
  left_ = kAxesLeft;
  top_ = style.title.empty() ? kAxesTopUntitled : kAxesTopTitled;
  width_ = canvas.width() - left_ - kAxesRight;
  height_ = canvas.height() - top_ - kAxesBottom;
  if (equal_scale) {
    const double scale = std::min(width_ / (x.hi - x.lo), height_ / (y.hi - y.lo));
    x = widen_to(x, width_ / scale);
    y = widen_to(y, height_ / scale);
    x_ = x;
    y_ = y;
    xticks_ = nice_ticks(x_, 8);
    yticks_ = nice_ticks(y_, 6);
    // keep only ticks inside the (exactly fitted) ranges
    auto inside = [](const Range& r) { return [r](double v) { return v < r.lo - 1e-9 * (r.hi - r.lo) || v > r.hi + 1e-9 * (r.hi - r.lo); }; };
    xticks_.erase(std::remove_if(xticks_.begin(), xticks_.end(), inside(x_)), xticks_.end());
    yticks_.erase(std::remove_if(yticks_.begin(), yticks_.end(), inside(y_)), yticks_.end());
  } else {
    xticks_ = nice_ticks(x, 7);
    yticks_ = nice_ticks(y, 6);
    x_ = {xticks_.front(), xticks_.back()};
    y_ = {yticks_.front(), yticks_.back()};
  }
}

Point Axes::to_pixel(double x, double y) const {
  return {left_ + (x - x_.lo) / (x_.hi - x_.lo) * width_, top_ + (y_.hi - y) / (y_.hi - y_.lo) * height_};
}

void Axes::draw_grid() {
  if (!style_.grid) return;
  for (double t : xticks_) canvas_.line(to_pixel(t, y_.lo), to_pixel(t, y_.hi), kGrid, 1.0);
  for (double t : yticks_) canvas_.line(to_pixel(x_.lo, t), to_pixel(x_.hi, t), kGrid, 1.0);
}

void Axes::clip_to_plot_area() { canvas_.clip({left_, top_}, width_, height_); }
void Axes::reset_clip() { canvas_.reset_clip(); }

void Axes::draw_frame() {
  canvas_.polyline({{left_, top_}, {left_ + width_, top_}, {left_ + width_, top_ + height_}, {left_, top_ + height_}},
                   kInk, 1.2, false, true);
  const double xstep = xticks_.size() > 1 ? xticks_[1] - xticks_[0] : 1.0;
  const double ystep = yticks_.size() > 1 ? yticks_[1] - yticks_[0] : 1.0;
  for (double t : xticks_) {
    const Point p = to_pixel(t, y_.lo);
    canvas_.line(p, {p.x, p.y - 5}, kInk, 1.0);
    canvas_.text({p.x, p.y + 18}, tick_label(t, xstep), 12, kInk, Align::center);
  }
  for (double t : yticks_) {
    const Point p = to_pixel(x_.lo, t);
    canvas_.line(p, {p.x + 5, p.y}, kInk, 1.0);
    canvas_.text({p.x - 7, p.y + 4}, tick_label(t, ystep), 12, kInk, Align::right);
  }
  if (!style_.title.empty()) canvas_.text({left_ + width_ / 2, 30}, style_.title, 16, kInk, Align::center, 0, true);
  canvas_.text({left_ + width_ / 2, top_ + height_ + 44}, style_.x_label, 14, kInk, Align::center);
  canvas_.text({22, top_ + height_ / 2}, style_.y_label, 14, kInk, Align::center, -90);
}

}  // namespace cyclopt::plot
