#pragma once
// The gymnast on the high bar (seed 000, ch. 2.2 and 3.1, Fig. 3.1): two planar rigid bodies -
// upper body (head, trunk, arms; body 1) and legs (body 2) - joined by a hinge at the hip; body 1
// hangs from a rigid bar by a second hinge at the hands. Angles: phi = orientation of body 1,
// zero in the handstand, increasing along the swing; psi = phi + alpha orientation of body 2;
// alpha = hip angle, zero when fully stretched. The bar is the origin, y points up.
//
// Model holds the constants only (Pinocchio style); the algorithms are free functions in
// equations_of_motion.hpp, energy_momentum.hpp and friends.

#include <cmath>
#include <numbers>

namespace cyclopt::giant_swing {

struct Model {
  double m1 = 0.0;  // kg, upper body (seed 000, B.2 "Gesamt_Masse" of the upper body)
  double m2 = 0.0;  // kg, legs
  double S1 = 0.0;  // m, bar -> centre of mass of body 1
  double L1 = 0.0;  // m, bar -> hip joint
  double S2 = 0.0;  // m, hip joint -> centre of mass of body 2
  double I1 = 0.0;  // kg m^2, body 1 about its centre of mass
  double I2 = 0.0;  // kg m^2, body 2 about its centre of mass
  double g = 9.81;  // m/s^2
  double bar_radius = 0.014;        // m, lever arm r of the friction force (eq. A.71)
  double friction_coefficient = 0.5;  // mu, steel on leather (eq. A.72)

  double total_mass() const { return m1 + m2; }
};

// Male gymnast, 1.74 m, 72 kg (seed 000, appendix B.1/B.2, Calcman data B.3):
//   m1 = 48.8092 kg, S1 = 0.7242315221 m, L1 = 1.125414 m, I1 = 3.925803327 kg m^2,
//   m2 = 23.1868 kg, I2 = 1.804420253 kg m^2.
// The OCR text lost S2; it follows from the B.2 leg data: the leg centre of mass lies at
// z = -0.6390494 m in the trunk frame, the hip joint at z = -0.28834 m, so S2 = 0.3507094 m. (The
// same centre of mass reproduces the printed I2 = 1.804420253 to all digits via Steiner's theorem.)
inline Model appendix_b_gymnast() {
  Model m;
  m.m1 = 48.8092;
  m.S1 = 0.7242315221;
  m.L1 = 1.125414;
  m.I1 = 3.925803327;
  m.m2 = 23.1868;
  m.S2 = 0.3507094046;
  m.I2 = 1.804420253;
  return m;
}

// The abbreviations of seed 000, eq. (3.1) = (A.52)-(A.56).
struct InertiaConstants {
  double Theta1;  // I1 + m1 S1^2 + m2 L1^2
  double Theta2;  // I2 + m2 S2^2
  double chi1;    // m2 L1 S2
  double chi2;    // m1 S1 + m2 L1
  double chi3;    // m2 S2
};

inline InertiaConstants inertia_constants(const Model& m) {
  return {m.I1 + m.m1 * m.S1 * m.S1 + m.m2 * m.L1 * m.L1, m.I2 + m.m2 * m.S2 * m.S2, m.m2 * m.L1 * m.S2,
          m.m1 * m.S1 + m.m2 * m.L1, m.m2 * m.S2};
}

// The seed's reference angular rate in the handstand: omega = 40 deg/s (ch. 4.2).
inline constexpr double kReferenceRate = 40.0 * std::numbers::pi / 180.0;
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;
inline constexpr double kDegPerRad = 180.0 / std::numbers::pi;

}  // namespace cyclopt::giant_swing
