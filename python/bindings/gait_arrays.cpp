#include "gait_arrays.hpp"

#include <pybind11/numpy.h>

#include <array>
#include <vector>

namespace cyclopt::python {

namespace py = pybind11;
using records::GaitRecord;
using records::GaitTrajectoryRecord;

std::span<const GaitScalarColumn> gait_scalar_columns() {
  static constexpr std::array<GaitScalarColumn, 12> columns{{
      {"objective [-]", &GaitRecord::objective},  // f_mech or f_usq, what the job minimised
      {"f_mech [-]", &GaitRecord::f_mech},        // eq. 5.102
      {"f_usq [-]", &GaitRecord::f_usq},          // eq. 5.101, per c_A
      {"mean_speed [m/s]", &GaitRecord::mean_speed},
      {"step_length [m]", &GaitRecord::step_length},
      {"step_period [s]", &GaitRecord::step_period},
      {"floquet_multiplier [-]", &GaitRecord::floquet_multiplier},  // eq. 5.89
      {"impact_energy_loss [J]", &GaitRecord::impact_energy_loss},
      {"max_inequality [-]", &GaitRecord::max_inequality},  // eq. 5.104, scaled by m g and m (1 m/s)
      {"speed_equality [m/s]", &GaitRecord::speed_equality},  // eq. 5.103
      {"theta_plus [rad]", &GaitRecord::theta_plus},
      {"theta_minus [rad]", &GaitRecord::theta_minus},
  }};
  return columns;
}

namespace {

py::array_t<double> numpy_array(const std::vector<double>& v) { return py::array_t<double>(v.size(), v.data()); }

// Rows of equal length as a 2-D array (rows x samples).
py::array_t<double> numpy_array(const std::vector<std::vector<double>>& rows) {
  const std::size_t n = rows.size(), m = rows.empty() ? 0 : rows.front().size();
  py::array_t<double> a({n, m});
  auto out = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < n; ++i) {
    if (rows[i].size() != m) throw std::invalid_argument("trajectory rows of unequal length");
    for (std::size_t j = 0; j < m; ++j) out(i, j) = rows[i][j];
  }
  return a;
}

}  // namespace

py::dict gait_scalars(const GaitRecord& gait) {
  py::dict d;
  d["real"] = gait.real;
  d["failure"] = gait.failure;
  d["stable"] = gait.stable;  // eq. 5.90
  for (const GaitScalarColumn& c : gait_scalar_columns()) d[c.name] = gait.*c.member;
  d["bezier_coefficients [rad]"] = numpy_array(gait.bezier_coefficients);  // eq. 5.16, one row per joint
  return d;
}

py::dict gait_trajectories(const GaitTrajectoryRecord& t) {
  return trajectory_arrays(t, [](const auto& v) { return numpy_array(v); });
}

}  // namespace cyclopt::python
