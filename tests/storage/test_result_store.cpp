// Results store: idempotent submission, queue transitions, crash recovery, unique points,
// read-only access, queries.
#include "cyclopt/storage/result_queries.hpp"
#include "cyclopt/storage/result_store.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace cyclopt::storage {
namespace {

class ResultStoreTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("cyclopt_store_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    path_ = (dir_ / "results.db").string();
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
  std::string path_;
};

SolutionPoint point(int i) {
  SolutionPoint p;
  p.key = {0, i};
  p.parameter = 0.1 * i;
  p.objective = i * i;
  p.values = {{"i", i}};
  p.trajectory = nlohmann::json::array({1, 2, 3});
  return p;
}

TEST_F(ResultStoreTest, SubmissionIsIdempotentPerRequestId) {
  ResultStore s(path_);
  const SubmitOutcome a = s.submit("r1", "walker", "foot_sweep", "{}");
  const SubmitOutcome b = s.submit("r1", "walker", "foot_sweep", "{}");
  const SubmitOutcome c = s.submit("r1", "walker", "foot_sweep", "{\"x\":1}");
  EXPECT_FALSE(a.duplicate);
  EXPECT_TRUE(b.duplicate);
  EXPECT_FALSE(b.spec_differs);
  EXPECT_TRUE(c.spec_differs);
  EXPECT_EQ(a.job_id, b.job_id);
  EXPECT_EQ(s.count_jobs(std::nullopt), 1);
}

TEST_F(ResultStoreTest, QueueRunsOldestFirstAndRecoversInterruptedJobs) {
  std::int64_t first = 0;
  {
    ResultStore s(path_);
    first = s.submit("a", "walker", "foot_sweep", "{}").job_id;
    s.submit("b", "walker", "foot_sweep", "{}");
    const auto job = s.claim_next();
    ASSERT_TRUE(job);
    EXPECT_EQ(job->id, first);
    EXPECT_EQ(job->state, JobState::running);
    EXPECT_EQ(job->attempts, 1);
    EXPECT_TRUE(s.store_point(first, point(0)));
  }  // "crash": the job is left running
  ResultStore s(path_);
  const RecoverySummary r = s.recover_interrupted();
  EXPECT_EQ(r.requeued, 1);
  const auto again = s.claim_next();
  ASSERT_TRUE(again);
  EXPECT_EQ(again->id, first);
  EXPECT_EQ(again->attempts, 2);
  EXPECT_EQ(again->points_stored, 1);
  EXPECT_EQ(s.stored_points(first), (std::set<PointKey>{{0, 0}}));
}

TEST_F(ResultStoreTest, PointsAreStoredOnce) {
  ResultStore s(path_);
  const auto id = s.submit("a", "walker", "foot_sweep", "{}").job_id;
  EXPECT_TRUE(s.store_point(id, point(3)));
  EXPECT_FALSE(s.store_point(id, point(3)));
  const QueryPage page = run_query(s, query_for("solutions", id));
  ASSERT_EQ(page.total, 1);
  EXPECT_EQ(page.rows[0]["values"]["i"], 3);
  const QueryPage t = run_query(s, query_for("trajectories", id));
  ASSERT_EQ(t.total, 1);
  EXPECT_EQ(t.rows[0]["point"], 3);
  EXPECT_EQ(t.rows[0]["data"], nlohmann::json::array({1, 2, 3}));
}

TEST_F(ResultStoreTest, CancelQueuedAndRunningJobs) {
  ResultStore s(path_);
  const auto a = s.submit("a", "walker", "foot_sweep", "{}").job_id;
  const auto b = s.submit("b", "walker", "foot_sweep", "{}").job_id;
  ASSERT_EQ(s.claim_next()->id, a);
  EXPECT_EQ(s.cancel(a), CancelOutcome::cancel_requested);
  EXPECT_EQ(s.cancel(b), CancelOutcome::cancelled);
  EXPECT_EQ(s.cancel(b), CancelOutcome::already_final);
  EXPECT_EQ(s.cancel(99), CancelOutcome::not_found);
  EXPECT_FALSE(s.claim_next());
  // A restart honours the cancellation of the running job.
  EXPECT_EQ(s.recover_interrupted().cancelled, 1);
  EXPECT_EQ(s.job(a)->state, JobState::cancelled);
}

TEST_F(ResultStoreTest, ReadOnlyOpenSeesCommittedRowsAndCannotWrite) {
  ResultStore w(path_);
  const auto id = w.submit("a", "walker", "foot_sweep", "{}").job_id;
  w.store_point(id, point(1));
  ResultStore r(path_, OpenMode::read_only);
  EXPECT_EQ(run_query(r, query_for("solutions", id)).total, 1);
  EXPECT_THROW(r.submit("b", "walker", "foot_sweep", "{}"), StorageError);
}

TEST_F(ResultStoreTest, QueriesNameTheBadField) {
  ResultStore s(path_);
  QueryRequest q = query_for("jobs", 0, "sleeping");
  try {
    run_query(s, q);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("state"), std::string::npos);
  }
  EXPECT_THROW(run_query(s, query_for("planets")), std::invalid_argument);
  EXPECT_THROW(run_query(s, query_for("solutions", 42)), std::invalid_argument);
  q = query_for("jobs");
  q.limit = 5000;
  EXPECT_THROW(run_query(s, q), std::invalid_argument);
}

}  // namespace
}  // namespace cyclopt::storage
