#include "cyclopt/walker/walker_model.hpp"

namespace cyclopt::walker {

WalkerModel<double> make_walker_model(const foot::FootSpec& foot, const WalkingConstants& constants) {
  const bool feet = foot.model != foot::FootModel::point;
  const SegmentParameters<double> p = feet ? table_5_1() : table_d_1();
  FootDensity<double> density;
  if (feet && foot.density) {
    // Section 10.2 / appendix E: m_F, r_F, J_F and (unless the spec fixes it) theta_F,0 follow the outline.
    density.rho = *foot.density;
    density.zero_angle_from_geometry = !foot.theta_F0;
  }
  return make_walker_model<double>(p, foot.model, foot.parameters, foot.theta_F0.value_or(kFootZeroAngle), constants,
                                   foot.periodic_terms, density);
}

}  // namespace cyclopt::walker
