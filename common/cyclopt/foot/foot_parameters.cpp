#include "cyclopt/foot/foot_parameters.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <numbers>
#include <stdexcept>
#include <string>

namespace cyclopt::foot {
namespace {

// Ranges a specification may use. Lengths: a human or robot foot (the seed's fits are 7-450 mm;
// §10.2 optimises up to l_HM = 400 mm). k: eq. (3.7) needs k > 0; the seed's own fits go down to
// 1.4e-11 (Table B.7, P5 right, k_HM), a transition still about 6e4 double ulps wide at an
// angle of order one; above 1 the "polygon" is no longer recognisable (the seed bounds k by 0.5
// in §10.2).
constexpr double kKMin = 1e-12;
constexpr double kKMax = 1.0;

constexpr std::array<ParameterInfo, hm::count> kHmLayout{{
    {"h_F", ParameterKind::length, "m", 0.0, 0.5, "height of the generating polygon (ankle above sole)"},
    {"l_HA", ParameterKind::length, "m", 0.0, 1.0, "heel H to the ankle's projection on the sole"},
    {"l_HM", ParameterKind::length, "m", 1e-3, 1.0, "heel H to the ball of the foot M (sole length)"},
    {"k_H", ParameterKind::regularisation, "rad", kKMin, kKMax, "regularisation at the heel edge A-H"},
    {"k_HM", ParameterKind::regularisation, "rad", kKMin, kKMax, "regularisation of the sole H-M"},
    {"k_M", ParameterKind::regularisation, "rad", kKMin, kKMax, "regularisation at the front edge M-A"},
}};

constexpr std::array<ParameterInfo, hmt::count> kHmtLayout{{
    {"h_F", ParameterKind::length, "m", 0.0, 0.5, "height of the generating polygon (ankle above sole)"},
    {"l_HA", ParameterKind::length, "m", 0.0, 1.0, "heel H to the ankle's projection on the sole"},
    {"l_HM", ParameterKind::length, "m", 1e-3, 1.0, "heel H to the ball of the foot M"},
    {"l_MT", ParameterKind::length, "m", 0.0, 0.5, "ball M to the toe tip T"},
    {"gamma_F", ParameterKind::angle, "rad", 0.0, std::numbers::pi / 2, "toe angle at M (eq. 3.24: 0 <= gamma_F <= pi/2)"},
    {"k_H", ParameterKind::regularisation, "rad", kKMin, kKMax, "regularisation at the heel edge A-H"},
    {"k_HM", ParameterKind::regularisation, "rad", kKMin, kKMax, "regularisation of the sole H-M"},
    {"k_MT", ParameterKind::regularisation, "rad", kKMin, kKMax, "regularisation of the toe segment M-T"},
    {"k_T", ParameterKind::regularisation, "rad", kKMin, kKMax, "regularisation at the front edge T-A"},
}};

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return std::tolower(c); });
  return out;
}

}  // namespace

std::span<const ParameterInfo> parameter_layout(FootModel model) {
  switch (model) {
    case FootModel::hm: return kHmLayout;
    case FootModel::hmt: return kHmtLayout;
    case FootModel::point: break;
  }
  return {};
}

std::string_view to_string(FootModel model) {
  switch (model) {
    case FootModel::point: return "point";
    case FootModel::hm: return "HM";
    case FootModel::hmt: return "HMT";
  }
  return "?";
}

FootModel foot_model_from_string(std::string_view name) {
  const std::string n = lower(name);
  if (n == "point") return FootModel::point;
  if (n == "hm") return FootModel::hm;
  if (n == "hmt") return FootModel::hmt;
  throw std::invalid_argument("foot model '" + std::string(name) + "' is not one of: point, HM, HMT");
}

}  // namespace cyclopt::foot
