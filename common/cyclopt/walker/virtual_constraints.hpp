#pragma once
// Impact-invariant virtual constraints from the independent gait parameters (seed 001 eq. 5.55-5.62):
//   x = alpha_tilde = [alpha_2; ...; alpha_{M-1}; alpha_tilde_M],  size (M-1) n_b (30 for M = 6),
// with alpha_tilde_M = [H1-; H2-; K1-; K2-; F1-; F2-] (absolute foot angles instead of ankle
// angles, so theta_T- follows explicitly from z_C2 = 0, eq. 5.55). Point feet: n_b = 4 and
// alpha_tilde_M = [H1-; H2-; K1-; K2-].

#include "cyclopt/walker/impact_map.hpp"

#include "cyclopt/autodiff/scalar.hpp"

#include <cmath>
#include <numbers>
#include <string>

namespace cyclopt::walker {

template <class T>
using BezierCoefficients = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxJoints, 13>;

template <class T>
struct VirtualConstraints {
  BezierCoefficients<T> alpha;  // n_b x (M+1): columns alpha_0 .. alpha_M
  T theta_plus, theta_minus;    // range of the phase variable
  CoordinateVector<T> q_minus;  // configuration just before impact
  ImpactResult<T> unit_impact;  // impact of q_dot- = [1; q_b,d'(theta-)] (i.e. per unit theta_dot-)
  T theta_dot_ratio;            // theta_dot+ / theta_dot- (eq. 5.61)
  bool ok = true;
  std::string failure;          // why no impact-invariant constraint exists
};

inline int gait_parameter_count(int joints, int degree) { return (degree - 1) * joints; }

// Builds alpha_0..alpha_M, theta+- from x (eq. 5.55-5.62); the scalar is that of model and x combined.
template <class MT, class Vector, class T = ad::promoted_t<MT, typename Vector::Scalar>>
VirtualConstraints<T> virtual_constraints(const WalkerModel<MT>& m, const Vector& x) {
  using std::acos, std::cos, std::sin, std::sqrt, std::atan2;
  using ad::atan2;
  const int nb = m.joint_count, M = m.constants.bezier_degree;
  VirtualConstraints<T> vc;
  vc.alpha.resize(nb, M + 1);
  for (int i = 2; i < M; ++i)
    for (int j = 0; j < nb; ++j) vc.alpha(j, i) = T(x((i - 2) * nb + j));
  const auto xm = [&](int j) { return T(x((M - 2) * nb + j)); };
  const T H1 = xm(joint_H1), H2 = xm(joint_H2), K1 = xm(joint_K1), K2 = xm(joint_K2);
  const T lO = m.segments[l_O], lU = m.segments[l_U];
  // eq. (5.55): 0 = a + b cos theta_T + c sin theta_T
  T a = T(0.0);
  if (m.has_feet()) a = foot_contact(m, xm(joint_A1)).dF - foot_contact(m, xm(joint_A2)).dF;
  const T b = lO * (cos(H2) - cos(H1)) + lU * (cos(H2 + K2) - cos(H1 + K1));
  const T c = lO * (sin(H1) - sin(H2)) + lU * (sin(H1 + K1) - sin(H2 + K2));
  const T R = sqrt(b * b + c * c);
  if (!(ad::value(R) > 1e-12) || std::abs(ad::value(a) / ad::value(R)) >= 1.0) {
    vc.ok = false;
    vc.failure = "no torso angle puts both feet on the ground (eq. 5.55 has no solution)";
    return vc;
  }
  const T delta = atan2(c, b), spread = acos(-a / R);
  // Of the two roots delta +- spread take the one in [-pi/2, pi/2] (closest to upright).
  auto wrapped = [](const T& t) {
    const double k = std::round(ad::value(t) / (2.0 * std::numbers::pi));
    return T(t - 2.0 * std::numbers::pi * k);
  };
  const T r1 = wrapped(T(delta + spread)), r2 = wrapped(T(delta - spread));
  const T theta_T = std::abs(ad::value(r1)) <= std::abs(ad::value(r2)) ? r1 : r2;
  if (std::abs(ad::value(theta_T)) > std::numbers::pi / 2) {
    vc.ok = false;
    vc.failure = "torso angle at impact outside [-pi/2, pi/2] (eq. 5.55)";
    return vc;
  }
  // eq. (5.56): ankle angles from absolute foot angles.
  vc.alpha(joint_H1, M) = H1;
  vc.alpha(joint_H2, M) = H2;
  vc.alpha(joint_K1, M) = K1;
  vc.alpha(joint_K2, M) = K2;
  if (m.has_feet()) {
    vc.alpha(joint_A1, M) = xm(joint_A1) - theta_T - H1 - K1;
    vc.alpha(joint_A2, M) = xm(joint_A2) - theta_T - H2 - K2;
  }
  vc.q_minus.resize(nb + 1);
  vc.q_minus(0) = theta_T + H1 + 0.5 * K1;
  vc.q_minus.tail(nb) = vc.alpha.col(M);
  vc.theta_minus = vc.q_minus(0);
  // eq. (5.47): the swing foot must touch down in front of the stance foot.
  const StanceFrame<T> f = stance_frame(m, vc.q_minus);
  const Vec2<T> c1 = m.has_feet() ? Vec2<T>(f.stance_ankle + Vec2<T>(f.stance_foot.ddF, -f.stance_foot.dF)) : f.stance_ankle;
  if (!(ad::value(swing_contact_point(m, f).x()) > ad::value(c1.x()))) {
    vc.ok = false;
    vc.failure = "swing foot touches down behind the stance foot (eq. 5.47)";
    return vc;
  }
  // eq. (5.57): configuration after impact.
  const CoordinateVector<T> q_plus = swap_configuration(vc.q_minus);
  vc.theta_plus = q_plus(0);
  vc.alpha.col(0) = q_plus.tail(nb);
  const T span = vc.theta_minus - vc.theta_plus;
  if (!(ad::value(span) > 1e-6)) {
    vc.ok = false;
    vc.failure = "phase variable does not increase over the step (theta- <= theta+)";
    return vc;
  }
  // eq. (5.58)-(5.62): alpha_1 from the velocity impact map.
  CoordinateVector<T> gamma_minus(nb + 1);
  gamma_minus(0) = T(1.0);
  gamma_minus.tail(nb) = (double(M) / span) * (vc.alpha.col(M) - vc.alpha.col(M - 1));
  vc.unit_impact = impact_map(m, vc.q_minus, gamma_minus);
  const CoordinateVector<T>& ups = vc.unit_impact.q_dot_plus;  // Upsilon (eq. 5.60)
  vc.theta_dot_ratio = ups(0);
  if (!(ad::value(ups(0)) > 1e-9)) {
    vc.ok = false;
    vc.failure = "impact reverses or stops the phase variable (theta_dot+ / theta_dot- <= 0, eq. 5.61)";
    return vc;
  }
  vc.alpha.col(1) = vc.alpha.col(0) + (span / double(M)) * ups.tail(nb) / ups(0);  // (5.62)
  return vc;
}

}  // namespace cyclopt::walker
