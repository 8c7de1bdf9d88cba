#include "cyclopt/plot/speed_charts.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace cyclopt::plot {
namespace {

std::string with_omitted(const std::string& label, int omitted) {
  return omitted == 0 ? label : label + " (" + std::to_string(omitted) + " unconverged omitted)";
}

// One series per job of value(point) over the mean speed of the converged points.
LineChart per_job_chart(const std::vector<WalkerJobResults>& jobs, const AxesStyle& axes,
                        const std::function<double(const GaitPoint&)>& value) {
  LineChart chart;
  chart.axes = axes;
  for (const WalkerJobResults& job : jobs) {
    Series s{job.label, {}, {}, true, false, std::nullopt};
    int omitted = 0;
    for (const GaitPoint& p : job.points) {
      if (!p.converged) {
        ++omitted;
        continue;
      }
      s.x.push_back(p.gait.value("mean_speed", p.speed));
      s.y.push_back(value(p));
    }
    s.label = with_omitted(s.label, omitted);
    if (!s.x.empty()) chart.series.push_back(std::move(s));
  }
  if (chart.series.empty()) throw std::invalid_argument("'" + axes.title + "': no converged gait in the given jobs");
  return chart;
}

// Quantities that are >= 0 get a y axis from zero, so curves compare by ratio at a glance.
void start_at_zero(LineChart& chart) {
  double hi = 0;
  for (const Series& s : chart.series)
    for (double y : s.y)
      if (std::isfinite(y)) hi = std::max(hi, y);
  chart.y_range = Range{0.0, hi > 0 ? 1.08 * hi : 1.0};
}

// Joint names of q_b (eq. 5.3) for 4 (point feet) or 6 joints.
const char* joint_name(int j) {
  static const char* names[] = {"H1 stance hip", "H2 swing hip", "K1 stance knee", "K2 swing knee",
                                "A1 stance ankle", "A2 swing ankle"};
  return names[j];
}

double max_abs_torque(const GaitPoint& p, int joint) {
  const nlohmann::json& rows = p.trajectory.at("torque");
  if (joint >= static_cast<int>(rows.size())) return std::nan("");
  double m = 0;
  for (const nlohmann::json& u : rows[joint]) m = std::max(m, std::abs(u.get<double>()));
  return m;
}

}  // namespace

LineChart cost_of_transport_chart(const std::vector<WalkerJobResults>& jobs) {
  LineChart chart = per_job_chart(jobs,
                                  {"Cost of transport of the optimal gaits (seed 001 Fig. 9.19a)", "mean speed v (m/s)",
                                   "mechanical cost of transport f_mech (eq. 5.102) (-)", true},
                                  [](const GaitPoint& p) { return p.gait.at("f_mech").get<double>(); });
  start_at_zero(chart);
  return chart;
}

LineChart max_torque_chart(const std::vector<WalkerJobResults>& jobs) {
  LineChart chart;
  chart.axes = {"Maximal joint torques (seed 001 Fig. 9.4)", "mean speed v (m/s)",
                "max |u| over the step (N m)", true};
  int omitted = 0;  // points, counted once per job
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    const int joints = jobs[k].job.foot.model == foot::FootModel::point ? 4 : 6;
    for (int j = 0; j < joints; ++j) {
      Series s{std::string(joint_name(j)) + (jobs.size() > 1 ? ", " + jobs[k].label : ""), {}, {}, true, k > 0,
               palette(j)};
      for (const GaitPoint& p : jobs[k].points)
        if (p.converged && p.trajectory.contains("torque")) {
          s.x.push_back(p.gait.value("mean_speed", p.speed));
          s.y.push_back(max_abs_torque(p, j));
        } else {
          omitted += j == 0;
        }
      if (!s.x.empty()) chart.series.push_back(std::move(s));
    }
  }
  if (chart.series.empty()) throw std::invalid_argument("'" + chart.axes.title + "': no converged gait with torques");
  if (omitted > 0) chart.axes.title += ", " + std::to_string(omitted) + " unconverged point(s) not drawn";
  start_at_zero(chart);
  return chart;
}

LineChart step_length_chart(const std::vector<WalkerJobResults>& jobs) {
  return per_job_chart(jobs,
                       {"Step length of the optimal gaits (seed 001 Fig. 9.6a)", "mean speed v (m/s)",
                        "step length x_H- - x_H+ (m)", true},
                       [](const GaitPoint& p) { return p.gait.at("step_length").get<double>(); });
}

LineChart floquet_chart(const std::vector<WalkerJobResults>& jobs) {
  return per_job_chart(jobs,
                       {"Floquet multiplier of the optimal gaits (seed 001 Fig. 9.6b; stable for 0 < Lambda < 1)",
                        "mean speed v (m/s)", "Floquet multiplier Lambda (eq. 5.89) (-)", true},
                       [](const GaitPoint& p) { return p.gait.at("floquet_multiplier").get<double>(); });
}

}  // namespace cyclopt::plot
