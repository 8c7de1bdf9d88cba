#pragma once
// Mass, centre of mass, inertia and zero angle theta_F,0 of a foot of homogeneous area density
// rho, from its regularised outline (seed 001, appendix E, eq. E.1-E.7).
//
// With r^2 phi' = f (f + f'') = f R (eq. E.1; f = F', R = F' + F''') and the outline point
// C(alpha) = (r sin phi, -r cos phi) in the foot frame, the integrals E.2-E.5 become
//   A = 1/2 int f R,  x_AS = 1/(3A) int C_x f R,  z_AS = 1/(3A) int C_z f R,
//   J_A = rho/4 int |C|^2 f R.
// The seed evaluates them with a 1000-point trapezoid rule, which cannot resolve transitions
// with k = 1e-8 (the whole edge is traversed within ~1e-8 rad: R is a spike of height l/(2k)).
// Here they are integrated with 10-point Gauss-Legendre panels whose breakpoints sit at
// delta_i + k_i u for a fixed set of u around every transition, so each panel sees a smooth
// integrand on its own scale whatever k is; the rest of the turn is cut into panels no wider
// than max_panel_width.
//
// Integration window: one full turn of the body, starting in the middle of the angular range
// where the ankle vertex A touches the ground (between the last and the first transition), where
// f = 0 and nothing is contributed.

#include "cyclopt/foot/foot_profile.hpp"
#include "cyclopt/foot/rolling_kinematics.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace cyclopt::foot {

struct MassPropertyOptions {
  double max_panel_width = 0.2;  // rad (bench/results/foot_bench.txt: converged to 1e-13 at 0.4)
};

// Results in the foot frame: origin at the ankle A, x forward (towards the toes), z up, sole
// flat (theta = 0 of the profile).
template <class S>
struct FootMassProperties {
  S area;            // A (m^2), eq. (E.2)
  S mass;            // m = rho A (kg), eq. (E.3)
  S com_x;           // x_AS (m), eq. (E.4a)
  S com_z;           // z_AS (m), eq. (E.4b)
  S inertia_ankle;   // J_A (kg m^2), eq. (E.5)
  S inertia_com;     // J_S = J_A - m (x_AS^2 + z_AS^2) (kg m^2), eq. (E.6)
  S com_distance;    // r_F = |r_AS| (m), the walker's ankle-to-CoM length
  S theta_F0;        // pi - atan(x_AS / -z_AS) (rad), eq. (E.7)
};

// Outline point C(alpha) in the foot frame: r_BC = f' e_x - f e_z with e_x, e_z of eq. (2.27).
template <class T>
Vector2<T> outline_point(const RollingContact<T>& c, const T& alpha) {
  using std::cos, std::sin;
  const T ca = cos(alpha), sa = sin(alpha);
  return Vector2<T>(c.ddF * ca + c.dF * sa, c.ddF * sa - c.dF * ca);
}

namespace detail {

// 10-point Gauss-Legendre rule on [-1, 1]: the positive nodes and their weights.
inline constexpr std::array<double, 5> kGaussNodes10 = {0.1488743389816312, 0.4333953941292472, 0.6794095682990244,
                                                        0.8650633666889845, 0.9739065285171717};
inline constexpr std::array<double, 5> kGaussWeights10 = {0.2955242247147529, 0.2692667193099963, 0.2190863625159820,
                                                          0.1494513491505806, 0.0666713443086881};

// Panel breakpoints over one turn (see the file comment), sorted by value.
template <class S>
std::vector<S> panel_breakpoints(const FootProfile<S>& prof, double max_width) {
  constexpr double two_pi = 2.0 * std::numbers::pi;
  S start = S(-std::numbers::pi);
  if (prof.transition_count > 0) {
    const S gap = two_pi - (prof.transitions[prof.transition_count - 1].angle - prof.transitions[0].angle);
    start = prof.transitions[0].angle - 0.5 * gap;
  }
  const S end = start + two_pi;
  std::vector<S> br = {start, end};
  constexpr std::array<double, 13> kU = {-30, -16, -8, -4, -2, -1, 0, 1, 2, 4, 8, 16, 30};
  for (int i = 0; i < prof.transition_count; ++i)
    for (double u : kU) {
      const S a = prof.transitions[i].angle + u * prof.transitions[i].k;
      if (ad::value(a) > ad::value(start) && ad::value(a) < ad::value(end)) br.push_back(a);
    }
  std::sort(br.begin(), br.end(), [](const S& l, const S& r) { return ad::value(l) < ad::value(r); });
  std::vector<S> out = {br.front()};
  for (std::size_t j = 1; j < br.size(); ++j) {
    const S from = out.back();
    const S width = br[j] - from;
    const int pieces = std::max(1, static_cast<int>(std::ceil(ad::value(width) / max_width)));
    for (int m = 1; m < pieces; ++m) out.push_back(from + width * (double(m) / pieces));
    out.push_back(br[j]);
  }
  return out;
}

}  // namespace detail

template <class S>
FootMassProperties<S> mass_properties(const FootProfile<S>& prof, const S& density,
                                      const MassPropertyOptions& opt = {}) {
  using std::atan2, std::sqrt;
  using ad::atan2;
  const std::vector<S> br = detail::panel_breakpoints(prof, opt.max_panel_width);
  // Integrals of f R, C_x f R, C_z f R and |C|^2 f R over the turn.
  S i0 = S(0.0), ix = S(0.0), iz = S(0.0), i2 = S(0.0);
  auto add_node = [&](const S& alpha, const S& weight) {
    const RollingContact<S> c = rolling_contact(prof, alpha);
    const Vector2<S> C = outline_point(c, alpha);
    const S w = weight * c.dF * curvature_radius(prof, alpha);
    i0 += w;
    ix += w * C.x();
    iz += w * C.y();
    i2 += w * (C.x() * C.x() + C.y() * C.y());  // not squaredNorm(): it conjugates complex steps
  };
  for (std::size_t j = 0; j + 1 < br.size(); ++j) {
    const S mid = 0.5 * (br[j] + br[j + 1]);
    const S half = 0.5 * (br[j + 1] - br[j]);
    for (std::size_t g = 0; g < detail::kGaussNodes10.size(); ++g) {
      add_node(mid - half * detail::kGaussNodes10[g], half * detail::kGaussWeights10[g]);
      add_node(mid + half * detail::kGaussNodes10[g], half * detail::kGaussWeights10[g]);
    }
  }
  FootMassProperties<S> mp;
  if (!(ad::value(i0) > 0.0)) {
    // No enclosed area (every edge vanished, the massless "stilt" of section 10.2): a massless
    // foot with its centre of mass at the ankle and theta_F,0 = pi, finite and constant.
    mp.area = mp.mass = mp.com_x = mp.com_z = mp.inertia_ankle = mp.inertia_com = mp.com_distance = S(0.0);
    mp.theta_F0 = S(std::numbers::pi);
    return mp;
  }
  mp.area = 0.5 * i0;                      // (E.2)
  mp.mass = density * mp.area;             // (E.3)
  mp.com_x = ix / (3.0 * mp.area);         // (E.4a)
  mp.com_z = iz / (3.0 * mp.area);         // (E.4b)
  mp.inertia_ankle = 0.25 * density * i2;  // (E.5)
  mp.com_distance = sqrt(mp.com_x * mp.com_x + mp.com_z * mp.com_z);
  mp.inertia_com = mp.inertia_ankle - mp.mass * mp.com_distance * mp.com_distance;  // (E.6)
  mp.theta_F0 = std::numbers::pi - atan2(mp.com_x, -mp.com_z);                        // (E.7)
  return mp;
}

}  // namespace cyclopt::foot
