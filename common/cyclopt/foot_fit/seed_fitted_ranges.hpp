#pragma once
// The range each shape parameter spans over the seed's own fits to human feet (seed 001,
// appendix B: HM in Table 4.2 and B.1-B.5, HMT in B.6-B.11; nine subjects, both feet, the ankle
// as SG, AK or IK, barefoot and with shoes). The scale against which a fit's uncertainty is
// judged (fit_spread.hpp): a spread that is a good part of it does not tell feet apart.

#include "cyclopt/foot/foot_parameters.hpp"

namespace cyclopt::foot_fit {

struct SeedRange {
  double low = 0.0, high = 0.0;  // SI (m, rad); low == high == 0 for the fixed k_H, k_M, k_T
  double width() const { return high - low; }
};

// `parameter` in the order of foot::parameter_layout(model); HM and HMT only.
SeedRange seed_fitted_range(foot::FootModel model, int parameter);

}  // namespace cyclopt::foot_fit
