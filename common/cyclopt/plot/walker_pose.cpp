#include "cyclopt/plot/walker_pose.hpp"

#include <algorithm>
#include <cmath>

namespace cyclopt::plot {
namespace {

Xz xz(const walker::Vec2<double>& v) { return {v.x(), v.y()}; }

// The outline turned clockwise by `turn` (positive angles lean towards +x) and put at `ankle`.
std::vector<Xz> placed(const std::vector<Xz>& outline, double turn, const Xz& ankle) {
  const double c = std::cos(turn), s = std::sin(turn);
  std::vector<Xz> out;
  out.reserve(outline.size());
  for (const Xz& p : outline) out.push_back({ankle[0] + c * p[0] + s * p[1], ankle[1] - s * p[0] + c * p[1]});
  return out;
}

}  // namespace

WalkerPose walker_pose(const walker::WalkerModel<double>& m, const walker::CoordinateVector<double>& q,
                       const std::vector<Xz>& foot_outline) {
  const walker::StanceFrame<double> f = walker::stance_frame(m, q);
  WalkerPose p;
  p.hip = xz(walker::point_position(f, m.hip));
  p.torso_tip = xz(walker::point_position(f, m.hip) + m.segments[walker::l_T] * walker::direction(f.angle(walker::seg_T)));
  p.knee1 = xz(walker::point_position(f, m.knee1));
  p.knee2 = xz(walker::point_position(f, m.knee2));
  p.ankle1 = xz(f.stance_ankle);
  p.ankle2 = xz(walker::point_position(f, m.swing_ankle));
  p.swing_lowest = xz(walker::swing_contact_point(m, f));
  p.contact = p.ankle1;
  p.contact_in_foot = {0, 0};
  if (m.has_feet()) {
    p.contact = {p.ankle1[0] + f.stance_foot.ddF, p.ankle1[1] - f.stance_foot.dF};
    const double turn = f.angle(walker::seg_F1) - m.foot_zero_angle, c = std::cos(turn), s = std::sin(turn);
    const double dx = p.contact[0] - p.ankle1[0], dz = p.contact[1] - p.ankle1[1];
    p.contact_in_foot = {c * dx - s * dz, s * dx + c * dz};  // placed() undone
    p.foot1 = placed(foot_outline, turn, p.ankle1);
    p.foot2 = placed(foot_outline, f.angle(walker::seg_F2) - m.foot_zero_angle, p.ankle2);
  }
  return p;
}

walker::CoordinateVector<double> q_at(const records::GaitTrajectoryRecord& tr, double t) {
  const std::vector<double>& time = tr.time;
  const auto hi = std::upper_bound(time.begin(), time.end(), t);
  const std::size_t j = std::clamp<std::size_t>(static_cast<std::size_t>(hi - time.begin()), 1, time.size() - 1);
  const double w = std::clamp((t - time[j - 1]) / (time[j] - time[j - 1]), 0.0, 1.0);
  const std::vector<std::vector<double>>& q = tr.q;
  walker::CoordinateVector<double> out(static_cast<Eigen::Index>(q.size()));
  for (std::size_t r = 0; r < q.size(); ++r) out(static_cast<Eigen::Index>(r)) = (1 - w) * q[r].at(j - 1) + w * q[r].at(j);
  return out;
}

}  // namespace cyclopt::plot
