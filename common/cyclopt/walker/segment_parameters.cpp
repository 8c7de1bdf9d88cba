#include "cyclopt/walker/segment_parameters.hpp"

#include <stdexcept>
#include <string>

namespace cyclopt::walker {

const SegmentParameterInfo& segment_parameter_info(int index) {
  static const std::array<SegmentParameterInfo, segment_parameter_count> info = {{
      {"l_T", "m", 0.05, 2.0}, {"l_O", "m", 0.05, 1.0}, {"l_U", "m", 0.05, 1.0},
      {"r_T", "m", 0.0, 2.0},  {"r_O", "m", 0.0, 1.0},  {"r_U", "m", 0.0, 1.0}, {"r_F", "m", 0.0, 0.3},
      {"m_T", "kg", 0.1, 500.0}, {"m_O", "kg", 0.01, 100.0}, {"m_U", "kg", 0.01, 100.0}, {"m_F", "kg", 0.0, 20.0},
      {"J_T", "kg m^2", 1e-4, 50.0}, {"J_O", "kg m^2", 1e-5, 10.0}, {"J_U", "kg m^2", 1e-5, 10.0},
      {"J_F", "kg m^2", 0.0, 1.0},
  }};
  if (index < 0 || index >= segment_parameter_count)
    throw std::out_of_range("segment parameter index " + std::to_string(index) + " outside [0, 14]");
  return info[index];
}

SegmentParameters<double> table_5_1() {
  return {0.809, 0.439, 0.440, 0.302, 0.188, 0.181, 0.059, 50.880, 9.840, 3.840, 0.960, 2.646, 0.171, 0.058, 0.004};
}

SegmentParameters<double> table_d_1() {
  return {0.809, 0.439, 0.440, 0.302, 0.188, 0.240, 0.0, 50.880, 9.840, 4.800, 0.0, 2.646, 0.171, 0.132, 0.0};
}

}  // namespace cyclopt::walker
