#include "cyclopt/studies/design_class.hpp"

#include "cyclopt/foot/mass_properties.hpp"
#include "cyclopt/foot/rolling_kinematics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace cyclopt::studies {
namespace {

double range(const Eigen::VectorXd& v) { return v.size() == 0 ? 0.0 : v.maxCoeff() - v.minCoeff(); }

std::string measured(const char* format, double a, double b) {
  char buf[160];
  std::snprintf(buf, sizeof buf, format, a, b);
  return buf;
}

}  // namespace

const char* to_string(DesignClass c) {
  switch (c) {
    case DesignClass::admissible: return "admissible";
    case DesignClass::stilt: return "stilt";
    case DesignClass::wheel: return "wheel";
    case DesignClass::no_rolling: return "no rolling";
    case DesignClass::under_resolved: return "under-resolved";
  }
  return "?";
}

bool resolved(double objective, double refined_objective, double tolerance) {
  return std::abs(refined_objective - objective) <= tolerance * std::abs(refined_objective);
}

DesignClassification classify_design(const walker::WalkerModel<double>& model, const walker::PeriodicGait<double>& gait,
                                     double refined_objective, double resolution_tolerance) {
  DesignClassification c;
  c.objective = gait.objective;
  c.refined_objective = refined_objective;
  if (!resolved(gait.objective, refined_objective, resolution_tolerance)) {
    c.design_class = DesignClass::under_resolved;
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "under-resolved: objective %.3g on the grid, %.3g on a grid %d times finer (more than %.3g %% apart "
                  "or no gait there: the optimum exploits the quadrature)",
                  gait.objective, refined_objective, kResolutionFactor, 100.0 * resolution_tolerance);
    c.reason = buf;
    return c;
  }
  if (!model.has_feet()) return c;
  const walker::GaitTrajectory<double>& tr = gait.trajectory;
  const Eigen::Index n = tr.stance_foot_angle.size();
  if (n < 2 || tr.hip.cols() != n) throw std::invalid_argument("classify_design: the gait has no stored trajectory");
  c.foot_area = foot::mass_properties(model.foot, 1.0).area;
  c.step_frequency = gait.step_period > 0.0 ? 1.0 / gait.step_period : 0.0;
  Eigen::VectorXd ankle(n), contact(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const foot::RollingContact<double> rc = foot::rolling_contact(model.foot, tr.stance_foot_angle(j) - model.foot_zero_angle);
    ankle(j) = foot::ankle_position(rc)(0);
    contact(j) = foot::contact_point_on_ground(rc);
  }
  c.ankle_travel = range(ankle);
  c.leg_swing = range(tr.hip.row(0).transpose() - ankle);
  c.contact_travel = range(contact);
  const auto& p = model.foot_parameters;
  c.sole_length = model.foot_model == foot::FootModel::hmt ? p[foot::hmt::l_HM] + p[foot::hmt::l_MT] : p[foot::hm::l_HM];
  const double step = std::max(gait.step_length, 1e-12);

  if (c.foot_area < kStiltArea || c.step_frequency > kStiltFrequency) {
    c.design_class = DesignClass::stilt;
    c.reason = measured("stilt: foot area %.3g m^2 (< 1e-4 makes a stilt), step frequency %.3g Hz (> 15 makes a stilt)",
                        c.foot_area, c.step_frequency);
  } else if (c.ankle_travel > kWheelRolling * step && c.leg_swing < kWheelLegSwing * step) {
    c.design_class = DesignClass::wheel;
    c.reason = measured("wheel: the ankle rolls %.3g step lengths while the hip stays within %.3g step lengths of it "
                        "(> 0.5 and < 0.25 make a wheel)",
                        c.ankle_travel / step, c.leg_swing / step);
  } else if (c.contact_travel < kRollingFraction * c.sole_length) {
    c.design_class = DesignClass::no_rolling;
    c.reason = measured("no rolling: the contact point travels %.3g m of a %.3g m sole (< 20 %% is heel or toe walking)",
                        c.contact_travel, c.sole_length);
  } else {
    c.reason = measured("rolls over %.0f %% of the sole, step frequency %.3g Hz", 100.0 * c.contact_travel / c.sole_length,
                        c.step_frequency);
  }
  return c;
}

}  // namespace cyclopt::studies
