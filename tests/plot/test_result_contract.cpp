// Acceptance of issue 14 (result contract): a walker point written by the job kinds' writer
// (service/walker_points.hpp), stored and read back through the results store as `cyclopt export`
// does, reaches plot's loader with every field it draws equal to what the writer had, and a foot
// comparison's stored records reach the comparison figures the same way. Plot reads values only
// through records/ (a renamed field fails to compile there); this test fails when the writer
// and the records part.
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/io/foot_spec_json.hpp"
#include "cyclopt/plot/foot_comparison_figures.hpp"
#include "cyclopt/plot/walker_job_results.hpp"
#include "cyclopt/records/foot_comparison_records.hpp"
#include "cyclopt/jobs/walker/walker_points.hpp"
#include "cyclopt/jobs/walker/walker_records.hpp"
#include "cyclopt/storage_read/result_queries.hpp"
#include "cyclopt/storage/result_store.hpp"
#include "cyclopt/walker/gait_evaluation.hpp"
#include "cyclopt/walker/starting_gait.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include <unistd.h>

namespace cyclopt {
namespace {

namespace fs = std::filesystem;

class ResultContract : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = (fs::temp_directory_path() / ("contract-result-" + std::to_string(::getpid()) + ".db")).string();
    fs::remove(path_);
  }
  void TearDown() override {
    for (const char* suffix : {"", "-wal", "-shm"}) fs::remove(path_ + suffix);
  }
  // Stores the points as job `task` and reads the job back as the client's export does.
  nlohmann::json stored_document(const nlohmann::json& spec, const std::vector<storage::SolutionPoint>& points) {
    storage::ResultStore store(path_);
    const std::int64_t id = store.submit("contract-" + spec.at("task").get<std::string>(), "walker", spec["task"], spec.dump()).job_id;
    for (const storage::SolutionPoint& p : points) store.store_point(id, p);
    nlohmann::json doc = storage::run_query(store, storage::query_for("job", id)).rows.at(0);
    for (const char* part : storage::kJobParts) doc[part] = storage::run_query(store, storage::query_for(part, id)).rows;
    return doc;
  }
  std::string path_;
};

TEST_F(ResultContract, PlotReadsEveryGaitFieldTheWriterStored) {
  const double speed = 1.1;
  const walker::GaitEvaluator ev(walker::make_walker_model(foot::foot_preset("P2-shoes-left-HMT").spec));
  walker::StartingGaitOptions so;
  so.speed = speed;
  const walker::StartingGait sg = walker::starting_gait(ev, so);
  ASSERT_TRUE(sg.real) << sg.message;
  const storage::SolutionPoint written = jobs::point_of(sg.gait, {sg.x, "starting gait"}, {0, 0}, speed);
  const nlohmann::json spec = {{"scene", "walker"}, {"task", "evaluate"}, {"foot", "P2-shoes-left-HMT"}, {"speed", speed}};
  const plot::WalkerJobResults r = plot::walker_job_results(stored_document(spec, {written}));
  ASSERT_EQ(r.points.size(), 1u);
  const plot::GaitPoint& p = r.points[0];
  EXPECT_EQ(p.speed, speed);
  EXPECT_EQ(p.status, "ok");
  EXPECT_TRUE(p.converged);
  // Every member, one by one, so a failure names the field (the records compare whole below).
  const records::GaitRecord g = jobs::gait_record(sg.gait);
  EXPECT_TRUE(p.gait.real);
  EXPECT_EQ(p.gait.objective, g.objective);
  EXPECT_EQ(p.gait.f_mech, g.f_mech);
  EXPECT_EQ(p.gait.f_usq, g.f_usq);
  EXPECT_EQ(p.gait.mean_speed, g.mean_speed);
  EXPECT_EQ(p.gait.step_length, g.step_length);
  EXPECT_EQ(p.gait.step_period, g.step_period);
  EXPECT_EQ(p.gait.floquet_multiplier, g.floquet_multiplier);
  EXPECT_EQ(p.gait.stable, g.stable);
  EXPECT_EQ(p.gait.impact_energy_loss, g.impact_energy_loss);
  EXPECT_EQ(p.gait.max_inequality, g.max_inequality);
  EXPECT_EQ(p.gait.speed_equality, g.speed_equality);
  EXPECT_EQ(p.gait.theta_plus, g.theta_plus);
  EXPECT_EQ(p.gait.theta_minus, g.theta_minus);
  EXPECT_EQ(p.gait.bezier_coefficients, g.bezier_coefficients);
  EXPECT_EQ(p.gait, g);
  EXPECT_EQ(p.gait.f_mech, sg.gait.f_mech);  // and the record holds the walker's own numbers
  EXPECT_EQ(p.gait.floquet_multiplier, sg.gait.floquet);
  ASSERT_TRUE(p.trajectory.has_value());
  const records::GaitTrajectoryRecord t = *jobs::trajectory_record(sg.gait.trajectory);
  EXPECT_EQ(p.trajectory->time, t.time);
  EXPECT_EQ(p.trajectory->theta, t.theta);
  EXPECT_EQ(p.trajectory->q, t.q);
  EXPECT_EQ(p.trajectory->q_dot, t.q_dot);
  EXPECT_EQ(p.trajectory->torque, t.torque);
  EXPECT_EQ(p.trajectory->contact_force, t.contact_force);
  EXPECT_EQ(p.trajectory->hip, t.hip);
  EXPECT_EQ(p.trajectory->swing_contact, t.swing_contact);
  EXPECT_EQ(p.trajectory->stance_foot_angle, t.stance_foot_angle);
  EXPECT_FALSE(t.stance_foot_angle.empty());  // a rolling foot
  EXPECT_EQ(*p.trajectory, t);
  EXPECT_EQ(p.trajectory->time.size(), static_cast<std::size_t>(sg.gait.trajectory.time.size()));
}

TEST_F(ResultContract, AStoredPointOffTheContractIsAnErrorNamingTheField) {
  storage::SolutionPoint p;
  p.parameter = 1.0;
  // A row off the contract, as a writer that lost the gait's other members would have stored it.
  p.carry({{"gait", {{"real", true}, {"f_mech", 0.1}}}}, std::nullopt);
  const nlohmann::json spec = {{"scene", "walker"}, {"task", "evaluate"}, {"foot", "point"}, {"speed", 1.0}};
  try {
    plot::walker_job_results(stored_document(spec, {p}));
    ADD_FAILURE() << "read a gait without its members";
  } catch (const records::RecordError& e) {
    EXPECT_EQ(std::string(e.what()), "gait.objective: is missing");
  }
}

TEST_F(ResultContract, TheComparisonFiguresReadTheStoredRecords) {
  const std::vector<std::string> feet = {"point", "P1-shoes-left-HM-SG"};
  const double f_mech[2][2] = {{0.05, 0.051}, {0.03, 0.031}};
  std::vector<storage::SolutionPoint> points;
  for (int k = 0; k < 2; ++k) {
    for (int i = 0; i < 2; ++i) {
      records::ComparedSpeedRecord s;
      s.foot = feet[static_cast<std::size_t>(k)];
      s.found_by = "multistart";
      s.f_mech = f_mech[k][i];
      s.sweep_seconds = 3.0;
      storage::SolutionPoint p;
      p.key = {1 + k, i};
      p.parameter = 1.0 + 0.5 * i;
      p.set_values(s);
      points.push_back(p);
    }
    records::ComparedFootRecord f;
    f.foot = feet[static_cast<std::size_t>(k)];
    f.reference = k == 0;
    f.best_fitted = k == 1;
    f.saving = k == 0 ? 0.0 : 0.39;
    f.mean_f_mech = (f_mech[k][0] + f_mech[k][1]) / 2;
    f.foot_spec = io::to_json(foot::foot_preset(feet[static_cast<std::size_t>(k)]).spec);
    if (k == 0) f.envelope_saving = 0.4;
    storage::SolutionPoint p;
    p.key = {3, k};
    p.parameter = 1 + k;
    p.set_values(f);
    points.push_back(p);
  }
  records::ComparedSpeedRecord best;
  best.foot = feet[1];
  best.f_mech = 0.03;
  best.saving = 0.4;
  best.reference_f_mech = 0.05;
  storage::SolutionPoint b;
  b.parameter = 1.0;
  b.set_values(best);
  points.push_back(b);
  const nlohmann::json spec = {{"scene", "walker"}, {"task", "foot_comparison"}, {"speeds", "1:0.5:1.5"}};
  const plot::FootComparisonCurves c = plot::foot_comparison_curves(stored_document(spec, points));
  ASSERT_EQ(c.feet.size(), 2u);
  EXPECT_EQ(c.feet[0].name, "point");
  EXPECT_TRUE(c.feet[0].reference);
  EXPECT_FALSE(c.feet[0].best_fitted);
  EXPECT_EQ(c.feet[1].name, feet[1]);
  EXPECT_TRUE(c.feet[1].best_fitted);
  EXPECT_EQ(c.feet[1].saving, 0.39);
  EXPECT_EQ(c.feet[1].spec.model, foot::foot_preset(feet[1]).spec.model);
  EXPECT_EQ(c.envelope_saving, 0.4);
  EXPECT_EQ(c.feet[1].speed, (std::vector<double>{1.0, 1.5}));
  EXPECT_EQ(c.feet[1].f_mech, (std::vector<double>{0.03, 0.031}));
  EXPECT_EQ(c.envelope_speed, std::vector<double>{1.0});
  EXPECT_EQ(c.envelope_f_mech, std::vector<double>{0.03});
}

}  // namespace
}  // namespace cyclopt
