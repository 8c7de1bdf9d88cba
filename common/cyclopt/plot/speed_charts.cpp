#include "cyclopt/plot/speed_charts.hpp"

#include "cyclopt/plot/gait_energy.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>

namespace cyclopt::plot {
namespace {

// "label (left out: 2 max_iterations, 1 not found)": how many points were not drawn and why.
std::string with_omitted(const std::string& label, const std::vector<std::string>& statuses) {
  if (statuses.empty()) return label;
  std::map<std::string, int> count;
  for (const std::string& s : statuses) ++count[s.empty() ? "no status" : s];
  std::string why;
  for (const auto& [status, n] : count) why += (why.empty() ? "" : ", ") + std::to_string(n) + " " + status;
  return label + " (left out: " + why + ")";
}

// Why nothing can be drawn: "no converged gait (job 3: 1 max_iterations)".
std::string no_converged_gait(const std::vector<WalkerJobResults>& jobs) {
  std::string why;
  for (const WalkerJobResults& job : jobs) {
    std::vector<std::string> statuses;
    for (const GaitPoint& p : job.points) statuses.push_back(p.status);
    why += (why.empty() ? "" : "; ") + with_omitted("job " + std::to_string(job.id), statuses);
  }
  return "no converged gait (" + why + ")";
}

// One series per job of value(point) over the mean speed of the converged points; with
// band_high, a band in the series' colour from value up to band_high where that is given.
LineChart per_job_chart(const std::vector<WalkerJobResults>& jobs, const AxesStyle& axes,
                        const std::function<double(const GaitPoint&)>& value,
                        const std::function<std::optional<double>(const GaitPoint&)>& band_high = nullptr,
                        const std::function<std::string(const Band&)>& band_label = nullptr) {
  LineChart chart;
  chart.axes = axes;
  for (const WalkerJobResults& job : jobs) {
    Series s{job.label, {}, {}, true, false, std::nullopt};
    Band band;
    std::vector<std::string> omitted;
    for (const GaitPoint& p : job.points) {
      if (!p.converged) {
        omitted.push_back(p.status);
        continue;
      }
      s.x.push_back(p.gait.mean_speed);
      s.y.push_back(value(p));
      if (const std::optional<double> high = band_high ? band_high(p) : std::nullopt) {
        band.x.push_back(s.x.back());
        band.low.push_back(s.y.back());
        band.high.push_back(*high);
      }
    }
    s.label = with_omitted(s.label, omitted);
    if (s.x.empty()) continue;
    if (!band.x.empty()) {
      band.color = palette(static_cast<int>(chart.series.size()));
      if (band_label) s.label += band_label(band);
      chart.bands.push_back(std::move(band));
    }
    chart.series.push_back(std::move(s));
  }
  if (chart.series.empty()) throw std::invalid_argument(no_converged_gait(jobs));
  return chart;
}

double max_abs_torque(const GaitPoint& p, int joint) {
  const std::vector<std::vector<double>>& rows = p.trajectory->torque;
  if (joint >= static_cast<int>(rows.size())) return std::nan("");
  double m = 0;
  for (double u : rows[static_cast<std::size_t>(joint)]) m = std::max(m, std::abs(u));
  return m;
}

}  // namespace

LineChart cost_of_transport_chart(const std::vector<WalkerJobResults>& jobs) {
  LineChart chart = per_job_chart(jobs,
                                  {"Cost of transport of the optimal gaits (seed 001 Fig. 9.19a)", "mean speed v (m/s)",
                                   "mechanical cost of transport f_{mech} (eq. 5.102) (-)", true},
                                  [](const GaitPoint& p) { return p.gait.f_mech; },
                                  // several seeds: up to the worst seed's own best, f * (1 + spread)
                                  [](const GaitPoint& p) -> std::optional<double> {
                                    if (!p.seed_spread) return std::nullopt;
                                    return p.gait.f_mech * (1.0 + *p.seed_spread);
                                  },
                                  [](const Band& b) {
                                    double widest = 0.0;
                                    for (std::size_t i = 0; i < b.x.size(); ++i) widest = std::max(widest, b.high[i] / b.low[i] - 1.0);
                                    char text[80];
                                    std::snprintf(text, sizeof text, "; shaded: spread over the seeds, at most %.1f %%", 100.0 * widest);
                                    return std::string(text);
                                  });
  start_at_zero(chart);
  return chart;
}

LineChart max_torque_chart(const std::vector<WalkerJobResults>& jobs) {
  LineChart chart;
  chart.axes = {"Maximal joint torques (seed 001 Fig. 9.4)", "mean speed v (m/s)",
                "max |u| over the step (N m)", true};
  std::vector<std::string> omitted;  // statuses of the points not drawn, once per job
  for (std::size_t k = 0; k < jobs.size(); ++k) {
    const int joints = jobs[k].walker.foot.model == foot::FootModel::point ? 4 : 6;
    for (int j = 0; j < joints; ++j) {
      Series s{std::string(joint_name(j)) + (jobs.size() > 1 ? ", " + jobs[k].label : ""), {}, {}, true, k > 0,
               palette(j)};
      for (const GaitPoint& p : jobs[k].points)
        if (p.converged && p.trajectory) {
          s.x.push_back(p.gait.mean_speed);
          s.y.push_back(max_abs_torque(p, j));
        } else if (j == 0) {
          omitted.push_back(p.converged ? "without torques" : p.status);
        }
      if (!s.x.empty()) chart.series.push_back(std::move(s));
    }
  }
  if (chart.series.empty()) throw std::invalid_argument(no_converged_gait(jobs));
  chart.axes.title = with_omitted(chart.axes.title, omitted);
  start_at_zero(chart);
  return chart;
}

LineChart step_length_chart(const std::vector<WalkerJobResults>& jobs) {
  return per_job_chart(jobs,
                       {"Step length of the optimal gaits (seed 001 Fig. 9.6a)", "mean speed v (m/s)",
                        "step length x_{H}^{−} − x_{H}^{+} (m)", true},
                       [](const GaitPoint& p) { return p.gait.step_length; });
}

LineChart floquet_chart(const std::vector<WalkerJobResults>& jobs) {
  LineChart chart = per_job_chart(jobs,
                                  {"Floquet multiplier of the optimal gaits (seed 001 Fig. 9.6b; stable for |Λ| < 1)",
                                   "mean speed v (m/s)", "Floquet multiplier Λ (eq. 5.89) (-)", true},
                                  [](const GaitPoint& p) { return p.gait.floquet_multiplier; });
  chart.reference_lines.push_back({1.0, "|Λ| = 1: stability limit"});
  for (const Series& s : chart.series)
    if (std::any_of(s.y.begin(), s.y.end(), [](double y) { return y < 0; })) {
      chart.reference_lines.push_back({-1.0, "Λ = −1: stability limit"});
      break;
    }
  return chart;
}

LineChart impact_loss_chart(const std::vector<WalkerJobResults>& jobs) {
  std::map<const GaitPoint*, double> percent;  // per drawn point, from its job's walker
  for (const WalkerJobResults& job : jobs) {
    const walker::WalkerModel<double> model = job.walker.model();
    for (const GaitPoint& p : job.points)
      if (p.converged && p.trajectory && !p.trajectory->time.empty())
        percent[&p] = 100.0 * p.gait.impact_energy_loss / kinetic_energy_at(model, *p.trajectory, 0);
  }
  LineChart chart = per_job_chart(
      jobs,
      {"Kinetic energy dissipated in the impact (seed 001 Fig. 9.5b)", "mean speed v (m/s)",
       "(E_{kin}^{−} − E_{kin}^{+}) / E_{kin}^{+} (%)", true},
      [&percent](const GaitPoint& p) {
        const auto at = percent.find(&p);
        return at == percent.end() ? std::nan("") : at->second;
      });
  start_at_zero(chart);
  return chart;
}

LineChart solution_curves_chart(const WalkerJobResults& job) {
  const std::string objective = job.spec.value("objective", std::string("f_mech"));
  const std::string name = objective == "f_usq" ? "f_{usq} (eq. 5.101)" : "f_{mech} (eq. 5.102)";
  LineChart chart;
  chart.axes = {"All solution curves and the best per speed (seed 001 Fig. 9.1)", "mean speed v (m/s)",
                "objective " + name + " (-)", true};
  auto series_of = [](const std::vector<GaitPoint>& points, Series s) {
    for (const GaitPoint& p : points)
      if (p.converged) {
        s.x.push_back(p.gait.mean_speed);
        s.y.push_back(p.gait.objective);
      }
    return s;
  };
  // The envelope first, wide and pale beneath the curves it is taken from.
  Series best = series_of(job.points, {"curve 0: best per speed (envelope)", {}, {}, true, false, Color{0, 0, 0, 0.28}, 9.0});
  if (!best.x.empty()) chart.series.push_back(std::move(best));
  for (const SolutionCurve& c : job.curves) {
    Series s = series_of(c.points, {"curve " + std::to_string(c.curve), {}, {}, true, false, palette(c.curve - 1), 2.0});
    if (!s.x.empty()) chart.series.push_back(std::move(s));
  }
  if (chart.series.empty()) throw std::invalid_argument(no_converged_gait({job}));
  return chart;
}

}  // namespace cyclopt::plot
