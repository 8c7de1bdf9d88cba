// Honest outcomes (issue 17 item 2): a job is done only when every required point is stored and
// converged; incomplete when some are missing or did not converge; failed when none converged.
// The summary names the points. Only required points count (a sweep's continuation runs do not),
// and files made before the state 'incomplete' existed are migrated when a server opens them.
#include "cyclopt/storage/job_outcome.hpp"
#include "cyclopt/storage_read/result_queries.hpp"
#include "cyclopt/storage/result_store.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace cyclopt::storage {
namespace {

RequiredPoint at_speed(double v, const std::string& status) { return {{0, 0}, v, status, "speed"}; }

TEST(JobOutcome, DoneOnlyWhenEveryAnnouncedPointConverged) {
  const JobOutcome o = judge_job_outcome({at_speed(0.8, "converged"), at_speed(1.0, "acceptable"), at_speed(1.2, "ok")}, 3);
  EXPECT_EQ(o.state, JobState::done);
  EXPECT_EQ(o.converged, 3);
  EXPECT_EQ(o.expected, 3);
  EXPECT_EQ(o.summary, "");
}

TEST(JobOutcome, IncompleteNamesThePointsThatDidNotConvergeAndCountsTheMissing) {
  const JobOutcome o = judge_job_outcome(
      {at_speed(0.3, "not found"), at_speed(0.8, "converged"), at_speed(1.3, "max_iterations"), at_speed(1.8, "converged")}, 5);
  EXPECT_EQ(o.state, JobState::incomplete);
  EXPECT_EQ(o.converged, 2);
  EXPECT_EQ(o.expected, 5);
  EXPECT_EQ(o.summary, "2 of 5 points converged; not converged: speed 0.3 (not found), speed 1.3 (max_iterations); 1 not stored");
}

TEST(JobOutcome, FailedWhenNoPointConverged) {
  const JobOutcome one = judge_job_outcome({at_speed(1.3, "max_iterations")}, 1);
  EXPECT_EQ(one.state, JobState::failed);
  EXPECT_EQ(one.summary, "0 of 1 points converged; not converged: speed 1.3 (max_iterations)");
  const JobOutcome none = judge_job_outcome({}, 0);  // e.g. a multistart that found no optimum
  EXPECT_EQ(none.state, JobState::failed);
  EXPECT_EQ(none.summary, "no point was found");
  EXPECT_EQ(judge_job_outcome({}, std::nullopt).state, JobState::failed);
  EXPECT_EQ(judge_job_outcome({}, 4).summary, "0 of 4 points converged; 4 not stored");
}

class JobOutcomeStore : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("cyclopt_outcome_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    path_ = (dir_ / "results.db").string();
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
  std::string path_;
};

SolutionPoint stored(int curve, int index, double v, const std::string& status, bool required) {
  SolutionPoint p;
  p.key = {curve, index};
  p.parameter = v;
  p.status = status;
  p.required = required;
  return p;
}

TEST_F(JobOutcomeStore, OnlyRequiredPointsAreJudgedAndTheOutcomeIsRecorded) {
  ResultStore s(path_);
  const auto id = s.submit("sweep", "walker", "sweep", "{}").job_id;
  s.set_points_total(id, 2);
  s.add_curve(id, 0, "best solution per speed", "speed");
  s.add_curve(id, 1, "solution curve 0", "speed");
  s.store_point(id, stored(1, 0, 1.0, "converged", false));
  s.store_point(id, stored(1, 1, 1.1, "max_iterations", false));  // a run's last step: not asked for
  s.store_point(id, stored(0, 0, 1.0, "converged", true));
  s.store_point(id, stored(0, 1, 1.1, "not found", true));
  const std::vector<RequiredPoint> required = s.required_points(id);
  ASSERT_EQ(required.size(), 2u);
  EXPECT_EQ(required[1].parameter_name, "speed");
  const JobOutcome o = judge_job_outcome(required, s.job(id)->points_total);
  EXPECT_EQ(o.state, JobState::incomplete);
  EXPECT_EQ(o.summary, "1 of 2 points converged; not converged: speed 1.1 (not found)");
  s.finish(id, o.state, o.summary, 1.0, 0.0, o.converged);
  const nlohmann::json row = run_query(s, query_for("job", id)).rows.at(0);
  EXPECT_EQ(row["state"], "incomplete");
  EXPECT_EQ(row["points_converged"], 1);
  EXPECT_EQ(row["points_stored"], 4);
  EXPECT_EQ(row["error"], o.summary);
  EXPECT_TRUE(is_final(JobState::incomplete));
  EXPECT_EQ(job_state_from_string("incomplete"), JobState::incomplete);
}

// A file whose jobs table still has the CHECK without 'incomplete' (as every file made before it
// existed): opening it for writing rebuilds the table, keeping the rows and the references to them.
TEST_F(JobOutcomeStore, OlderFilesAreMigratedToAcceptIncomplete) {
  std::int64_t id = 0;
  {
    ResultStore s(path_);
    id = s.submit("old", "walker", "optimise", "{\"task\": \"optimise\"}").job_id;
    s.store_point(id, stored(0, 0, 1.3, "max_iterations", true));
    Connection& db = s.connection();
    std::string sql;
    {
      Statement q(db, "SELECT sql FROM sqlite_master WHERE name = 'jobs'");
      ASSERT_TRUE(q.step());
      sql = q.text(0);
    }
    const std::string now = "'cancelled', 'incomplete')";
    ASSERT_NE(sql.find(now), std::string::npos);
    sql.replace(sql.find(now), now.size(), "'cancelled')");
    db.exec("PRAGMA foreign_keys = OFF");
    db.exec("CREATE TABLE jobs_old " + sql.substr(sql.find('(')));
    db.exec("INSERT INTO jobs_old SELECT * FROM jobs");
    db.exec("DROP TABLE jobs");
    db.exec("ALTER TABLE jobs_old RENAME TO jobs");
    EXPECT_THROW(db.exec("UPDATE jobs SET state = 'incomplete'"), StorageError);  // the old constraint
  }
  ResultStore s(path_);
  s.finish(id, JobState::incomplete, "0 of 2 points converged", 1.0, 0.0, 0);
  const nlohmann::json row = run_query(s, query_for("job", id)).rows.at(0);
  EXPECT_EQ(row["state"], "incomplete");
  EXPECT_EQ(row["spec"]["task"], "optimise");
  EXPECT_EQ(row["points_stored"], 1);
  Statement fk(s.connection(), "PRAGMA foreign_key_check");
  EXPECT_FALSE(fk.step()) << "a reference to jobs broke";
}

}  // namespace
}  // namespace cyclopt::storage
