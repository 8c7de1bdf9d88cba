// The result contract (records/): every record survives to_json -> text -> from_json unchanged,
// NaN survives as null, and a missing or mistyped member is an error naming it.
#include "cyclopt/records/foot_comparison_records.hpp"
#include "cyclopt/records/foot_design_records.hpp"
#include "cyclopt/records/gait_records.hpp"
#include "cyclopt/records/solver_record.hpp"
#include "cyclopt/records/sensitivity_records.hpp"
#include "cyclopt/records/walker_point_record.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace cyclopt::records {
namespace {

// Through the text the database stores.
template <class Record>
Record round_trip(const Record& r) {
  return nlohmann::json::parse(nlohmann::json(r).dump()).get<Record>();
}

template <class Record>
std::string error_of(const nlohmann::json& j) {
  try {
    j.get<Record>();
  } catch (const RecordError& e) {
    return e.what();
  }
  return "";
}

GaitRecord gait() {
  GaitRecord g;
  g.real = true;
  g.objective = 0.11;
  g.f_mech = 0.12;
  g.f_usq = 3.5;
  g.mean_speed = 1.01;
  g.step_length = 0.52;
  g.step_period = 0.515;
  g.floquet_multiplier = 0.42;
  g.stable = true;
  g.impact_energy_loss = 4.25;
  g.max_inequality = -1e-3;
  g.speed_equality = 2e-12;
  g.theta_plus = 0.31;
  g.theta_minus = -0.29;
  g.bezier_coefficients = {{0.1, 0.2, 0.3}, {-0.1, -0.2, -0.3}};
  return g;
}

GaitTrajectoryRecord trajectory() {
  GaitTrajectoryRecord t;
  t.time = {0.0, 0.25, 0.5};
  t.theta = {0.3, 0.0, -0.3};
  t.q = {{0.3, 0.0, -0.3}, {1, 2, 3}};
  t.q_dot = {{4, 5, 6}, {7, 8, 9}};
  t.torque = {{10, 11, 12}};
  t.contact_force = {{13, 14, 15}, {16, 17, 18}};
  t.hip = {{0, 0.1, 0.2}, {0.9, 0.91, 0.9}};
  t.swing_contact = {{-0.2, 0, 0.2}, {0, 0.03, 0}};
  t.stance_foot_angle = {0.01, 0.02, 0.03};
  return t;
}

SolverRecord solver() {
  SolverRecord s;
  s.termination = "converged";
  s.success = true;
  s.message = "optimal";
  s.iterations = 17;
  s.function_evaluations = 20;
  s.jacobian_evaluations = 18;
  s.failed_evaluations = 1;
  s.wall_seconds = 0.75;
  s.objective = 0.12;
  s.kkt_error = 1e-9;
  s.constraint_violation = 1e-11;
  s.x = {0.1, -0.2};
  return s;
}

TEST(ResultRecords, GaitFamilyRoundTrips) {
  EXPECT_EQ(round_trip(gait()), gait());
  GaitRecord none;
  none.failure = "zeta became negative at grid point 7";
  EXPECT_FALSE(round_trip(none).real);
  EXPECT_EQ(round_trip(none).failure, none.failure);
  EXPECT_TRUE(std::isnan(round_trip(none).f_mech));
  EXPECT_FALSE(nlohmann::json(none).contains("f_mech"));  // a gait that does not exist has no numbers
  EXPECT_EQ(round_trip(trajectory()), trajectory());
  GaitTrajectoryRecord point_feet = trajectory();
  point_feet.stance_foot_angle.clear();
  EXPECT_FALSE(nlohmann::json(point_feet).contains("stance_foot_angle"));
  EXPECT_EQ(round_trip(point_feet), point_feet);
}

TEST(ResultRecords, SolverRecordRoundTrips) { EXPECT_EQ(round_trip(solver()), solver()); }

TEST(ResultRecords, WalkerPointRecordRoundTrips) {
  WalkerPointRecord p;
  p.gait = gait();
  p.solver = solver();
  p.start = "QP predictor";
  p.start_objective = 0.2;
  p.continuation = ContinuationStepRecord{.curve_id = 2, .on_grid = true, .converged = true, .predictor_attempts = 1,
                                          .predictor_steps = 3, .kappa = 0.4, .trust_region = 0.05, .point_seconds = 1.5};
  p.x = {0.5, 0.6};
  EXPECT_EQ(round_trip(p), p);
  EXPECT_TRUE(solved(p));
  p.solver->success = false;
  EXPECT_FALSE(solved(p));
  const WalkerPointRecord not_found;  // a speed no sweep step reached: nothing but the job kind's own members
  EXPECT_EQ(round_trip(not_found), not_found);
  EXPECT_FALSE(solved(not_found));
  // The members a job kind adds beside the record are left to it.
  nlohmann::json with_extras = p;
  with_extras["found_by"] = "multistart at 1.3 m/s";
  EXPECT_EQ(with_extras.get<WalkerPointRecord>(), p);
}

// Issue 15 item 6: the KKT sensitivities stored with an optimum, and a sensitivity job's points.
TEST(ResultRecords, SensitivityRecordsRoundTrip) {
  ParameterSensitivityRecord p{.name = "l_HM", .value = 0.25, .derivative = -0.0185, .relative = -0.09, .kink = true,
                               .decrease = {.relative_change = 4.6e-3, .constraint = "swing clearance (5.104e)[110]", .enters = true},
                               .increase = {},  // none predicted: infinity, stored as null
                               .weakly_active = {"friction (5.104d)[64]"}};
  KktSensitivitiesRecord k;
  k.multipliers = "Ipopt polish";
  k.objective = 0.05;
  k.lagrangian_gradient = 3e-11;
  k.active_constraints = 4;
  k.unique_multipliers = false;
  k.weakly_active = {"friction (5.104d)[64]"};
  k.parameters = {p};
  k.seconds = 0.5;
  const KktSensitivitiesRecord back = round_trip(k);
  EXPECT_EQ(back, k);
  EXPECT_TRUE(std::isinf(back.parameters[0].increase.relative_change));
  KktSensitivitiesRecord unavailable;  // every number set: NaN != NaN (NanIsStoredAsNull... checks those)
  unavailable.objective = 0.05;
  unavailable.lagrangian_gradient = 1e-2;
  unavailable.seconds = 0.1;
  unavailable.unavailable = "multipliers unusable: |grad_z L|_inf = 1.0e-02 > 1.0e-04";
  EXPECT_EQ(round_trip(unavailable), unavailable);
  WalkerPointRecord w;
  w.gait = gait();
  w.sensitivities = k;
  EXPECT_EQ(round_trip(w), w);
  const SensitivityStepRecord step{.parameter = "m_T", .value = 48.3, .relative_change = -0.05, .delta_objective = 6e-4, .curve_id = 1};
  EXPECT_EQ(round_trip(step), step);
  SensitivitySummaryRecord s;
  s.parameter = "m_T";
  s.value = 50.88;
  s.derivative = -2.3e-4;
  s.relative = -0.3;
  s.relative_range = 0.1;
  s.predicted_decrease = 1.2e-3;
  s.predicted_increase = -1.2e-3;
  s.continuation_decrease = 1.25e-3;
  s.continuation_increase = -1.1e-3;
  s.reached_decrease = -0.1;
  s.reached_increase = 0.1;
  s.quotient_decrease = -2.4e-4;
  s.quotient_increase = -2.29e-4;
  s.jumps = 1;
  s.verdict = "kink: the continuation jumped to another solution curve 1 time(s)";
  EXPECT_EQ(round_trip(s), s);
  EXPECT_TRUE(is_sensitivity_summary(nlohmann::json(s)));
  EXPECT_FALSE(is_sensitivity_summary(nlohmann::json(step)));
  EXPECT_TRUE(is_sensitivity_step(nlohmann::json(step)));
  nlohmann::json broken = s;
  broken.erase("verdict");
  try {
    (void)broken.get<SensitivitySummaryRecord>();
    ADD_FAILURE() << "a summary without its verdict was read";
  } catch (const RecordError& e) {
    EXPECT_NE(std::string(e.what()).find("verdict"), std::string::npos) << e.what();
  }
}

TEST(ResultRecords, FootComparisonRecordsRoundTrip) {
  ComparedSpeedRecord s;
  s.foot = "P2-shoes-left-HMT-SG";
  s.found_by = "continuation up from 1.3 m/s";
  s.f_mech = 0.031;
  s.sweep_seconds = 12.5;
  s.saving = 0.4;
  s.reference_f_mech = 0.052;
  s.seed_spread = 0.004;
  EXPECT_EQ(round_trip(s), s);
  ComparedSpeedRecord missing;
  missing.reason = "no compared foot has a point at this speed";
  EXPECT_EQ(round_trip(missing).reason, missing.reason);
  EXPECT_TRUE(std::isnan(round_trip(missing).f_mech));

  ComparedFootRecord f;
  f.foot = "point";
  f.reference = true;
  f.best_fitted = false;
  f.mean_f_mech = 0.05;
  f.saving = 0.0;
  f.common_speeds = 21;
  f.speeds_found = 21;
  f.speeds = 21;
  f.curves = 3;
  f.sweep_seconds = 30.0;
  f.foot_spec = {{"model", "point"}};
  f.envelope_saving = 0.35;
  f.envelope_common_speeds = 20;
  f.comparison_seconds = 300.0;
  EXPECT_EQ(round_trip(f), f);
  EXPECT_TRUE(is_compared_foot(nlohmann::json(f)));
  EXPECT_FALSE(is_compared_foot(nlohmann::json(s)));
  ComparedFootRecord other = f;
  other.reference = false;
  other.envelope_saving.reset();
  other.envelope_common_speeds.reset();
  other.comparison_seconds.reset();
  EXPECT_EQ(round_trip(other), other);
  other.seed_savings = {0.41, 0.43, 0.40};  // three seeds' searches
  other.rank = 2;
  other.order_held = false;
  EXPECT_EQ(round_trip(other), other);
}

DesignedFoot designed_foot(double h_F) {
  return {{{"h_F", h_F}, {"l_HM", 0.4}, {"k_HM", 0.06}}, 0.236, 0.1028, 1.98e-3, 2.354};
}

TEST(ResultRecords, FootDesignRecordsRoundTrip) {
  DesignPointRecord p;
  p.density = 10;
  p.foot = designed_foot(0.1);
  p.active_bounds = {"l_HM_max - l_HM >= 0", "h_F_max - h_F >= 0"};
  p.design_class = "admissible";
  p.class_reason = "rolls over 95 % of the sole";
  p.reached_by_starts = {0, 3};
  p.design = true;
  EXPECT_EQ(round_trip(p), p);
  DesignPointRecord free_foot;  // a continuation point: no class
  free_foot.density = 10;
  free_foot.foot = designed_foot(0.09);
  EXPECT_EQ(round_trip(free_foot), free_foot);
  DesignedFootRecord d;
  d.density = 10;
  d.admissible = true;
  d.starts = 20;
  d.kkt_starts = 7;
  d.admissible_optima = 2;
  d.stilt_optima = 1;
  d.wheel_optima = 1;
  d.no_rolling_optima = 0;
  d.under_resolved_optima = 3;
  d.best = 1;
  d.design_objective = 0.0343;
  d.design = designed_foot(0.1);
  d.active_bounds = p.active_bounds;
  d.speeds = 21;
  d.free_foot_speeds = 3;
  d.low_speed = 2.0;
  d.low_speed_design = designed_foot(0.08);
  d.speeds_reached = 21;
  d.mean_f_mech = 0.0297;
  d.saving_vs_start = 0.2;
  d.saving_vs_point = 0.67;
  d.low_speeds_reached = 20;
  d.low_mean_f_mech = 0.03;
  d.low_saving_vs_start = 0.19;
  d.low_saving_vs_point = 0.66;
  d.answer = "low-speed design";
  d.multistart_seconds = 80;
  d.continuation_seconds = 90;
  d.sweep_seconds = 280;
  d.seconds = 450;
  EXPECT_EQ(round_trip(d), d);
  EXPECT_TRUE(is_designed_foot(nlohmann::json(d)));
  EXPECT_FALSE(is_designed_foot(nlohmann::json(p)));
  DesignedFootRecord none;  // no admissible design: NaN and empty members survive as such
  none.density = 70;
  none.reason = "every optimum of the design multistart is degenerate";
  const DesignedFootRecord back = round_trip(none);
  EXPECT_EQ(back.reason, none.reason);
  EXPECT_TRUE(std::isnan(back.mean_f_mech) && std::isnan(back.design.m_F) && back.design.parameters.empty());
  EXPECT_EQ(error_of<DesignedFootRecord>({{"density", 10}}), "values.admissible: is missing");
  nlohmann::json older = d;  // stored before the answer existed: the design was the only one
  older.erase("answer");
  EXPECT_EQ(older.get<DesignedFootRecord>().answer, "design");
  older["optima"].erase("under_resolved");  // stored before the class existed
  EXPECT_EQ(older.get<DesignedFootRecord>().under_resolved_optima, 0);
  nlohmann::json unknown = d;
  unknown["answer"] = "wheel";
  EXPECT_EQ(error_of<DesignedFootRecord>(unknown), "values.answer: must be \"design\" or \"low-speed design\", got \"wheel\"");
}

TEST(ResultRecords, NanIsStoredAsNullAndReadBackAsNan) {
  GaitRecord g = gait();
  g.floquet_multiplier = std::nan("");
  const nlohmann::json j = nlohmann::json::parse(nlohmann::json(g).dump());
  EXPECT_TRUE(j.at("floquet_multiplier").is_null());
  EXPECT_TRUE(std::isnan(j.get<GaitRecord>().floquet_multiplier));
  ComparedFootRecord f;
  f.foot = "HM";
  f.foot_spec = {{"model", "HM"}};
  EXPECT_TRUE(nlohmann::json(f).at("mean_f_mech").is_null());
  EXPECT_TRUE(std::isnan(round_trip(f).mean_f_mech));
}

TEST(ResultRecords, AMissingOrMistypedMemberIsAnErrorNamingIt) {
  nlohmann::json g = gait();
  g.erase("step_length");
  EXPECT_EQ(error_of<GaitRecord>(g), "gait.step_length: is missing");
  g = gait();
  g["stable"] = "yes";
  EXPECT_EQ(error_of<GaitRecord>(g), "gait.stable: must be true or false, got \"yes\"");
  nlohmann::json t = trajectory();
  t["q"][1] = 3;
  EXPECT_EQ(error_of<GaitTrajectoryRecord>(t), "trajectory.q[1]: must be an array of numbers");
  nlohmann::json s = solver();
  s["iterations"] = 1.5;
  EXPECT_EQ(error_of<SolverRecord>(s), "solver.iterations: must be an integer, got 1.5");
  nlohmann::json p = {{"gait", gait()}, {"curve_id", 1}};
  EXPECT_EQ(error_of<WalkerPointRecord>(p), "values.on_grid: is missing");
  EXPECT_EQ(error_of<ComparedFootRecord>({{"foot_spec", {{"model", "point"}}}}), "values.foot: is missing");
}

}  // namespace
}  // namespace cyclopt::records
