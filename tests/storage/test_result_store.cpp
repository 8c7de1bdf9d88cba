// Results store: idempotent submission, queue transitions, crash recovery, unique points,
// read-only access, queries.
#include "cyclopt/storage_read/result_queries.hpp"
#include "cyclopt/storage/result_store.hpp"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

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
  p.carry({{"i", i}}, nlohmann::json::array({1, 2, 3}));  // the store keeps any JSON the records wrote
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
  ResultReader r(path_);
  EXPECT_EQ(run_query(r, query_for("solutions", id)).total, 1);
  EXPECT_THROW(r.connection().exec("DELETE FROM solutions"), StorageError);
  EXPECT_EQ(run_query(w, query_for("solutions", id)).total, 1);
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

// The StorageError message of opening `path` read-write ("" if it opens).
std::string open_error(const std::string& path) {
  try {
    ResultStore s(path);
  } catch (const StorageError& e) {
    return e.what();
  }
  return "";
}

TEST_F(ResultStoreTest, ReadOnlyDirectoryIsAClearErrorAtStart) {
  if (::geteuid() == 0) GTEST_SKIP() << "root ignores directory permissions";
  const std::filesystem::path ro = dir_ / "ro";
  std::filesystem::create_directories(ro);
  ::chmod(ro.c_str(), 0555);
  const std::string e = open_error((ro / "results.db").string());
  ::chmod(ro.c_str(), 0755);
  EXPECT_NE(e.find("is not writable"), std::string::npos) << e;
}

TEST_F(ResultStoreTest, ReadOnlyFileIsAClearErrorAtStart) {
  { ResultStore s(path_); }
  const std::filesystem::path file(path_);
  // Also as root: a file the server cannot open for writing (here: a directory of that name)
  // must give an error naming the database, not a crash later.
  const std::string missing_dir = (dir_ / "no_such_dir" / "results.db").string();
  const std::string e = open_error(missing_dir);
  EXPECT_NE(e.find("does not exist"), std::string::npos) << e;
  if (::geteuid() != 0) {
    ::chmod(path_.c_str(), 0444);
    const std::string r = open_error(path_);
    ::chmod(path_.c_str(), 0644);
    EXPECT_NE(r.find("read-only"), std::string::npos) << r;
  }
}

TEST_F(ResultStoreTest, CorruptFileIsRefusedAtStartAndNothingIsWritten) {
  std::int64_t job = 0;
  {
    ResultStore s(path_);
    job = s.submit("a", "walker", "foot_sweep", "{}").job_id;
    for (int i = 0; i < 200; ++i) s.store_point(job, point(i));  // a file of many pages
    s.connection().exec("PRAGMA wal_checkpoint(TRUNCATE)");
  }
  const auto size = std::filesystem::file_size(path_);
  ASSERT_GT(size, 8 * 4096u);
  {  // overwrite a page in the middle of the file (as a failing disk or a stray write would)
    std::fstream f(path_, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(static_cast<std::streamoff>(size / 2 / 4096 * 4096));
    const std::string junk(4096, '\x5a');
    f.write(junk.data(), static_cast<std::streamsize>(junk.size()));
  }
  const auto before = std::filesystem::last_write_time(path_);
  const std::string e = open_error(path_);
  EXPECT_NE(e.find("is damaged (PRAGMA quick_check"), std::string::npos) << e;
  EXPECT_NE(e.find("refusing to start"), std::string::npos) << e;
  EXPECT_EQ(std::filesystem::last_write_time(path_), before);
  EXPECT_EQ(std::filesystem::file_size(path_), size);
  // Not a database at all.
  const std::string text = (dir_ / "text.db").string();
  std::ofstream(text) << std::string(5000, 'x');
  EXPECT_NE(open_error(text).find("is damaged"), std::string::npos) << open_error(text);
}

TEST_F(ResultStoreTest, FullDiskFailsTheWriteAndKeepsWhatWasStored) {
  ResultStore s(path_);
  const auto job = s.submit("a", "walker", "foot_sweep", "{}").job_id;
  s.claim_next();
  s.store_point(job, point(0));
  // SQLite's own cap on the file size: the next pages cannot be allocated (SQLITE_FULL).
  {
    Statement q(s.connection(), "PRAGMA page_count");
    q.step();
    s.connection().exec("PRAGMA max_page_count = " + std::to_string(q.int64(0)));
  }
  SolutionPoint big = point(1);
  nlohmann::json long_trajectory = nlohmann::json::array();
  for (int i = 0; i < 20000; ++i) long_trajectory.push_back(i);
  big.carry(big.values(), long_trajectory);
  try {
    s.store_point(job, big);
    FAIL() << "a write beyond max_page_count succeeded";
  } catch (const StorageError& e) {
    EXPECT_NE(std::string(e.what()).find("full"), std::string::npos) << e.what();
  }
  // The job's state can still be recorded (its event is dropped when there is no room).
  s.return_to_queue(job, 1.5, 0.0, std::string(5000, 'w'));
  EXPECT_EQ(s.job(job)->state, JobState::queued);
  EXPECT_EQ(s.stored_points(job), (std::set<PointKey>{{0, 0}}));
  Statement check(s.connection(), "PRAGMA integrity_check");
  ASSERT_TRUE(check.step());
  EXPECT_EQ(check.text(0), "ok");
}

TEST_F(ResultStoreTest, OneCorruptTextCellDoesNotBreakTheJobList) {
  ResultStore s(path_);
  const auto a = s.submit("a", "walker", "foot_sweep", "{}").job_id;
  s.submit("b", "walker", "foot_sweep", "{}");
  s.store_point(a, point(0));
  s.connection().exec("UPDATE jobs SET error = CAST(x'41ff42c3' AS TEXT), spec_json = 'not json' WHERE id = " +
                      std::to_string(a));
  s.connection().exec("UPDATE solutions SET values_json = CAST(x'7b22ff' AS TEXT), status = CAST(x'e282' AS TEXT)");
  const QueryPage jobs = run_query(s, query_for("jobs"));
  ASSERT_EQ(jobs.rows.size(), 2u);
  EXPECT_EQ(jobs.rows[0]["error"], "A\xEF\xBF\xBD" "B\xEF\xBF\xBD");
  EXPECT_NO_THROW(jobs.rows.dump());
  EXPECT_NO_THROW(run_query(s, query_for("job", a)).rows.dump());
  const QueryPage points = run_query(s, query_for("solutions", a));
  ASSERT_EQ(points.rows.size(), 1u);
  EXPECT_TRUE(points.rows[0]["values"].contains("unreadable"));
  EXPECT_NO_THROW(points.rows.dump());
}

TEST_F(ResultStoreTest, SenderQuotaLimitsQueuedJobsAndTheirEstimatedTime) {
  ResultStore s(path_);
  const SenderQuota quota{3, 100.0};
  auto submit = [&](const std::string& id, const std::string& sender, double seconds) {
    return s.submit({id, "walker", "optimise", "{}", sender, seconds, "", "{}", "", "", ""}, quota);
  };
  EXPECT_FALSE(submit("a1", "alice", 10).over_quota);
  EXPECT_FALSE(submit("a2", "alice", 10).over_quota);
  EXPECT_FALSE(submit("a3", "alice", 10).over_quota);
  const SubmitOutcome full = submit("a4", "alice", 10);
  EXPECT_TRUE(full.over_quota);
  EXPECT_EQ(full.queued_jobs, 3);
  EXPECT_DOUBLE_EQ(full.queued_seconds, 30.0);
  EXPECT_TRUE(submit("a1", "alice", 10).duplicate);  // a resend is still answered
  EXPECT_FALSE(submit("b1", "bob", 95).over_quota);  // per sender
  EXPECT_TRUE(submit("b2", "bob", 10).over_quota);   // 105 s > 100 s
  s.claim_next();                                     // a running job no longer counts
  EXPECT_FALSE(submit("a5", "alice", 10).over_quota);
  EXPECT_EQ(s.count_jobs(std::nullopt), 5);
}

TEST_F(ResultStoreTest, RunSecondsAccumulateAcrossCheckpointsAndAttempts) {
  ResultStore s(path_);
  const auto job = s.submit("a", "walker", "foot_sweep", "{}").job_id;
  s.claim_next();
  s.add_run_seconds(job, 2.0);
  s.add_run_seconds(job, 3.0);
  s.recover_interrupted();  // a kill -9: the checkpointed time stays
  EXPECT_DOUBLE_EQ(s.job(job)->run_seconds, 5.0);
  EXPECT_DOUBLE_EQ(s.claim_next()->run_seconds, 5.0);
  s.finish(job, JobState::done, "", 1.0, 0.0);
  EXPECT_DOUBLE_EQ(s.job(job)->run_seconds, 6.0);
  EXPECT_EQ(s.job(job)->attempts, 2);
}

}  // namespace
}  // namespace cyclopt::storage
