#pragma once
// Foot models and the layout of their parameter vectors (seed 001, section 3.3).
//
// All lengths in metres, angles in radians; the regularisation parameters k are angles (rad) in
// the sense of eq. (3.7): tanh(alpha / k).
//
//   point: no parameters. The ankle is the contact point (F = 0); a point-foot scene has no foot
//          segments at all (Table D.1).
//   HM   (eq. 3.19-3.21): p = [h_F, l_HA, l_HM, k_H, k_HM, k_M]
//   HMT  (eq. 3.22-3.24): p = [h_F, l_HA, l_HM, l_MT, gamma_F, k_H, k_HM, k_MT, k_T]

#include <Eigen/Core>

#include <span>
#include <string_view>

namespace cyclopt::foot {

enum class FootModel { point, hm, hmt };

// Parameter vector of a foot model; at most 9 entries, never heap-allocated.
inline constexpr int kMaxFootParameters = 9;
template <class S>
using FootParameters = Eigen::Matrix<S, Eigen::Dynamic, 1, 0, kMaxFootParameters, 1>;

// What a foot parameter measures: a length of the generating polygon, an angle of it (gamma_F),
// or a regularisation k of eq. (3.7) (the corners' and the sole's sharpness).
enum class ParameterKind { length, angle, regularisation };

// One entry of a parameter layout: its JSON name, kind, unit and the range a specification may use.
struct ParameterInfo {
  std::string_view name;
  ParameterKind kind;
  std::string_view unit;
  double min;
  double max;
  std::string_view meaning;
};

// The ordered layout of p for a model (empty for the point foot).
std::span<const ParameterInfo> parameter_layout(FootModel model);

std::string_view to_string(FootModel model);
// Parses "point", "HM" or "HMT" (case-insensitive); throws std::invalid_argument otherwise.
FootModel foot_model_from_string(std::string_view name);

// Index constants into p, so code reads p[hmt::l_MT] instead of p[3].
namespace hm {
enum Index { h_F = 0, l_HA, l_HM, k_H, k_HM, k_M, count };
}
namespace hmt {
enum Index { h_F = 0, l_HA, l_HM, l_MT, gamma_F, k_H, k_HM, k_MT, k_T, count };
}

}  // namespace cyclopt::foot
