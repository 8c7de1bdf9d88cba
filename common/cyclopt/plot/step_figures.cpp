#include "cyclopt/plot/step_figures.hpp"

#include "cyclopt/plot/foot_figures.hpp"
#include "cyclopt/plot/html_report.hpp"
#include "cyclopt/plot/gait_energy.hpp"
#include "cyclopt/plot/walker_pose.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace cyclopt::plot {
namespace {

constexpr double kDegrees = 180.0 / M_PI;

const records::GaitTrajectoryRecord& trajectory_of(const GaitPoint& p) {
  if (!p.trajectory || p.trajectory->time.size() < 2)
    throw std::invalid_argument("the point at " + report_number(p.speed, "%.3g") + " m/s has no stored trajectory");
  return *p.trajectory;
}

std::vector<double> relative_time(const records::GaitTrajectoryRecord& tr) {
  std::vector<double> t;
  for (double x : tr.time) t.push_back(x / tr.time.back());
  return t;
}

int joints_of(const records::GaitTrajectoryRecord& tr) { return static_cast<int>(tr.torque.size()); }

std::string at_speed(const GaitPoint& p) {
  char b[96];
  std::snprintf(b, sizeof b, " at v = %.2f m/s (T = %.3f s)", p.gait.mean_speed, p.trajectory->time.back());
  return b;
}

// One series per joint of row(j) over t/T, coloured by joint as in the torque chart over speed.
template <class Row>
LineChart per_joint_chart(const records::GaitTrajectoryRecord& tr, AxesStyle axes, Row row) {
  LineChart chart;
  chart.axes = std::move(axes);
  chart.x_range = Range{0, 1};
  for (int j = 0; j < joints_of(tr); ++j)
    chart.series.push_back({joint_name(j), relative_time(tr), row(j), false, false, palette(j)});
  return chart;
}

const char* kStepTime = "relative step time t/T (-), impact to impact";

// P_j = u_j dq_{b,j}/dt at sample k (eq. 5.100).
double joint_power(const records::GaitTrajectoryRecord& tr, int j, std::size_t k) {
  return tr.torque[static_cast<std::size_t>(j)].at(k) * tr.q_dot.at(static_cast<std::size_t>(1 + j)).at(k);
}

// sum_j P_j at sample k.
double total_joint_power(const records::GaitTrajectoryRecord& tr, std::size_t k) {
  double p = 0;
  for (int j = 0; j < joints_of(tr); ++j) p += joint_power(tr, j, k);
  return p;
}

}  // namespace

LineChart joint_angle_chart(const WalkerJobResults&, const GaitPoint& p) {
  const records::GaitTrajectoryRecord& tr = trajectory_of(p);
  return per_joint_chart(tr, {"Joint angles within the step" + at_speed(p), kStepTime, "joint angle q_{b,i} (°)", true},
                         [&tr](int j) {
                           std::vector<double> deg;
                           for (double q : tr.q.at(static_cast<std::size_t>(1 + j))) deg.push_back(kDegrees * q);
                           return deg;
                         });
}

LineChart joint_torque_chart(const WalkerJobResults&, const GaitPoint& p) {
  const records::GaitTrajectoryRecord& tr = trajectory_of(p);
  return per_joint_chart(tr, {"Joint torques within the step" + at_speed(p), kStepTime, "joint torque u_{i} (N m)", true},
                         [&tr](int j) { return tr.torque[static_cast<std::size_t>(j)]; });
}

LineChart joint_power_chart(const WalkerJobResults&, const GaitPoint& p) {
  const records::GaitTrajectoryRecord& tr = trajectory_of(p);
  const std::vector<double> t = relative_time(tr);
  auto power = [&tr](int j) {
    std::vector<double> out;
    for (std::size_t k = 0; k < tr.time.size(); ++k) out.push_back(joint_power(tr, j, k));
    return out;
  };
  LineChart chart = per_joint_chart(
      tr, {"Joint powers within the step" + at_speed(p) + ", positive part shaded", kStepTime,
           "joint power P_{i} = u_{i} dq_{b,i}/dt (W)", true},
      power);
  for (int j = 0; j < joints_of(tr); ++j) {
    const std::vector<double> pw = power(j);
    Band b{{}, {}, {}, palette(j)};
    for (std::size_t i = 0; i < pw.size(); ++i) {
      if (i > 0 && (pw[i - 1] > 0) != (pw[i] > 0) && pw[i - 1] != pw[i]) {  // the crossing of zero
        const double w = pw[i - 1] / (pw[i - 1] - pw[i]);
        b.x.push_back(t[i - 1] + w * (t[i] - t[i - 1]));
        b.low.push_back(0);
        b.high.push_back(0);
      }
      b.x.push_back(t[i]);
      b.low.push_back(0);
      b.high.push_back(std::max(pw[i], 0.0));
    }
    chart.bands.push_back(std::move(b));
  }
  return chart;
}

LineChart contact_point_chart(const WalkerJobResults& job, const GaitPoint& p) {
  const records::GaitTrajectoryRecord& tr = trajectory_of(p);
  if (job.walker.foot.model == foot::FootModel::point)
    throw std::invalid_argument("point feet have no sole for the contact point to roll along");
  const walker::WalkerModel<double> model = job.walker.model();
  const std::vector<Xz> outline = foot_outline(job.walker.foot);
  LineChart chart;
  chart.axes = {"Contact point along the stance sole" + at_speed(p), kStepTime,
                "contact point C_{1} from the ankle along the sole (m)", true};
  chart.x_range = Range{0, 1};
  Series s{"C_{1} in the foot frame (+: towards the toes)", relative_time(tr), {}, false, false, palette(3)};
  for (double t : tr.time) s.y.push_back(walker_pose(model, q_at(tr, t), outline).contact_in_foot[0]);
  chart.series.push_back(std::move(s));
  const auto [heel, toe] = std::minmax_element(outline.begin(), outline.end(), [](const Xz& a, const Xz& b) { return a[0] < b[0]; });
  chart.reference_lines.push_back({(*toe)[0], "toe end of the sole"});
  chart.reference_lines.push_back({(*heel)[0], "heel end of the sole"});
  chart.reference_lines.push_back({0.0, "below the ankle"});
  return chart;
}

LineChart energy_chart(const WalkerJobResults& job, const GaitPoint& p) {
  const records::GaitTrajectoryRecord& tr = trajectory_of(p);
  const walker::WalkerModel<double> model = job.walker.model();
  Series energy{"E_{tot}(t) - E_{tot}(0), from q and dq/dt", relative_time(tr), {}, false, false, palette(0)};
  Series work{"work of the joint torques, ∫ Σ_{i} P_{i} dt", relative_time(tr), {}, false, true, palette(1)};
  double e0 = 0, w = 0;
  for (std::size_t k = 0; k < tr.time.size(); ++k) {
    const double e = total_energy_at(model, tr, k);
    if (k == 0) e0 = e;
    else w += 0.5 * (total_joint_power(tr, k - 1) + total_joint_power(tr, k)) * (tr.time[k] - tr.time[k - 1]);
    energy.y.push_back(e - e0);
    work.y.push_back(w);
  }
  LineChart chart;
  chart.axes = {"Increase of the total energy within the step" + at_speed(p), kStepTime,
                "E_{tot} - E_{tot}(0) (J), E_{tot} = E_{pot} + E_{kin}", true};
  chart.x_range = Range{0, 1};
  chart.series = {std::move(energy), std::move(work)};
  chart.reference_lines.push_back({0.0, ""});
  return chart;
}

std::vector<Figure> within_step_figures(const WalkerJobResults& job, const GaitPoint& p) {
  std::vector<Figure> out = {
      {"step_joint_angles", "Joint angles q_{b} over one step (eq. 5.3)", joint_angle_chart(job, p), {}},
      {"step_joint_torques", "Joint torques u over one step (eq. 5.35)", joint_torque_chart(job, p), {}},
      {"step_joint_powers", "Joint powers over one step; shaded: the positive part, which f_{mech} integrates (eq. 5.100, 5.102)",
       joint_power_chart(job, p), {}},
      {"step_energy", "Increase of the total energy over one step (Fig. 9.5a) and the joint torques' work: equal, the contact rolls without slipping",
       energy_chart(job, p), {}}};
  if (job.walker.foot.model != foot::FootModel::point)
    out.push_back({"step_contact_point", "Rolling contact point along the stance sole (seed 001 section 9.1)",
                   contact_point_chart(job, p), {}});
  return out;
}

}  // namespace cyclopt::plot
