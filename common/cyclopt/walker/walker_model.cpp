#include "cyclopt/walker/walker_model.hpp"

#include "cyclopt/foot/mass_properties.hpp"

namespace cyclopt::walker {

WalkerModel<double> make_walker_model(const foot::FootSpec& foot, const WalkingConstants& constants) {
  const bool feet = foot.model != foot::FootModel::point;
  SegmentParameters<double> p = feet ? table_5_1() : table_d_1();
  double zero_angle = foot.theta_F0.value_or(kFootZeroAngle);
  if (feet && foot.density) {
    // Appendix E: foot mass, CoM distance, inertia and theta_F,0 from the outline (section 10.2).
    const auto mp = foot::mass_properties(foot::make_profile<double>(foot.model, foot.parameters, foot.periodic_terms),
                                          *foot.density);
    p[m_F] = mp.mass;
    p[r_F] = mp.com_distance;
    p[J_F] = mp.inertia_com;
    if (!foot.theta_F0) zero_angle = mp.theta_F0;
  }
  return make_walker_model<double>(p, foot.model, foot.parameters, zero_angle, constants, foot.periodic_terms);
}

}  // namespace cyclopt::walker
