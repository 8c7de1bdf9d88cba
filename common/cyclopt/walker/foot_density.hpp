#pragma once
// Foot mass properties that follow the foot geometry (seed 001, section 10.2): with an area
// density rho the foot's mass m_F, ankle-to-CoM distance r_F, inertia J_F and zero angle
// theta_F,0 are functions of the foot parameters (appendix E, eq. E.1-E.7) instead of independent
// entries of p_mech. Templated on the scalar, so a Dual model carries their exact derivatives with
// respect to the foot parameters and rho through the same forward-mode pass as the gait.

#include "cyclopt/foot/mass_properties.hpp"
#include "cyclopt/walker/segment_parameters.hpp"

#include <optional>

namespace cyclopt::walker {

template <class T>
struct FootDensity {
  std::optional<T> rho;                   // kg/m^2; none: m_F, r_F, J_F, theta_F,0 are independent
  bool zero_angle_from_geometry = true;   // false when the foot spec fixes theta_F,0 itself

  bool active() const { return rho.has_value(); }
};

// Replaces m_F, r_F, J_F (and theta_F,0 unless fixed) by the values of appendix E for the given
// profile; does nothing without a density. J_F is the inertia about the foot's CoM (eq. E.6).
template <class T>
void apply_foot_density(const FootDensity<T>& density, const foot::FootProfile<T>& profile, SegmentParameters<T>& p,
                        T& zero_angle) {
  if (!density.active() || profile.transition_count == 0) return;
  const foot::FootMassProperties<T> mp = foot::mass_properties(profile, *density.rho);
  p[m_F] = mp.mass;
  p[r_F] = mp.com_distance;
  p[J_F] = mp.inertia_com;
  if (density.zero_angle_from_geometry) zero_angle = mp.theta_F0;
}

}  // namespace cyclopt::walker
