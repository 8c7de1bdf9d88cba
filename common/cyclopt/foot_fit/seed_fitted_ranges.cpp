#include "cyclopt/foot_fit/seed_fitted_ranges.hpp"

#include <numbers>
#include <stdexcept>

namespace cyclopt::foot_fit {

SeedRange seed_fitted_range(foot::FootModel model, int parameter) {
  constexpr double deg = std::numbers::pi / 180.0;
  if (model == foot::FootModel::hm) {
    switch (parameter) {
      case foot::hm::h_F: return {0.0441, 0.0973};   // mm in the tables: 44.1 (B.4) .. 97.3 (B.2)
      case foot::hm::l_HA: return {0.0069, 0.2283};  // 6.9 (B.1) .. 228.3 (B.5)
      case foot::hm::l_HM: return {0.1612, 0.4421};  // 161.2 (B.1) .. 442.1 (B.5)
      case foot::hm::k_HM: return {3.2e-6, 0.34};    // rad^-1 in the tables
      case foot::hm::k_H:
      case foot::hm::k_M: return {};
    }
  } else if (model == foot::FootModel::hmt) {
    switch (parameter) {
      case foot::hmt::h_F: return {0.0611, 0.1161};      // 61.1 (B.7) .. 116.1 (B.11)
      case foot::hmt::l_HA: return {0.0065, 0.1536};     // 6.5 (B.7) .. 153.6 (B.11)
      case foot::hmt::l_HM: return {0.1611, 0.3788};     // 161.1 (B.7) .. 378.8 (B.11)
      case foot::hmt::l_MT: return {0.0, 0.1264};        // 0.0 (B.8) .. 126.4 (B.11)
      case foot::hmt::gamma_F: return {29.5 * deg, 89.8 * deg};  // B.10 .. B.8
      case foot::hmt::k_HM: return {1.4e-11, 0.23};
      case foot::hmt::k_MT: return {3.7e-10, 0.29};
      case foot::hmt::k_H:
      case foot::hmt::k_T: return {};
    }
  }
  throw std::invalid_argument("seed_fitted_range: parameter " + std::to_string(parameter) + " of an HM or HMT foot");
}

}  // namespace cyclopt::foot_fit
