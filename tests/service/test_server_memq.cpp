// The server and a client in one process over memq:// (no network): submission, idempotency,
// progress rate, paged queries, cancellation, limits, rejection of bad messages, and resume
// after a shutdown in the middle of a sweep.
#include "cyclopt_channels.hpp"
#include "memq_server_fixture.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace cyclopt {
namespace {

std::string sweep(int points, int delay_ms, int samples = 13) {
  nlohmann::json s = {{"scene", "walker"},
                      {"task", "foot_sweep"},
                      {"foot", "P2-shoes-left-HMT"},
                      {"samples", samples},
                      {"point_delay_ms", delay_ms},
                      {"sweep", {{"parameter", "density"}, {"values", "1:1:" + std::to_string(points)}}}};
  return s.dump();
}

class ServerMemq : public testing::MemqServerTest {
 protected:
  cyclopt_lcm::job_ack_t submit(const std::string& id, const std::string& spec) {
    const auto ack = client_.submit(id, spec, 5.0);
    EXPECT_TRUE(ack);
    return ack.value_or(cyclopt_lcm::job_ack_t{});
  }
};

TEST_F(ServerMemq, SubmitWatchAndQuery) {
  server::Server srv(config_, kinds_, lcm_);
  const auto ack = submit("req-1", sweep(50, 20));
  ASSERT_TRUE(ack.accepted) << ack.problem;
  EXPECT_FALSE(ack.duplicate);
  int progress = 0;
  double last_percent = 0.0;
  const auto done = client_.watch(ack.job_id, [&](const cyclopt_lcm::job_progress_t& p) {
    ++progress;
    EXPECT_GE(p.percent, last_percent);
    last_percent = p.percent;
  }, 20.0);
  ASSERT_TRUE(done);
  EXPECT_EQ(done->state, "done");
  EXPECT_EQ(done->points_stored, 50);
  // 50 points x 20 ms = 1 s at 5 Hz: a handful of messages, not one per point.
  EXPECT_GE(progress, 2);
  EXPECT_LE(progress, 10);
  EXPECT_DOUBLE_EQ(last_percent, 100.0);
  const auto dup = submit("req-1", sweep(50, 20));
  EXPECT_TRUE(dup.accepted);
  EXPECT_TRUE(dup.duplicate);
  EXPECT_EQ(dup.job_id, ack.job_id);
  const auto page = client_.query(storage::query_for("solutions", ack.job_id), 5.0);
  ASSERT_TRUE(page);
  EXPECT_EQ(page->rows.size(), 50u);
  EXPECT_EQ(client_.query(storage::query_for("jobs"), 5.0)->total, 1);
  const auto trajectories = client_.query(storage::query_for("trajectories", ack.job_id), 5.0);
  ASSERT_TRUE(trajectories);
  ASSERT_EQ(trajectories->rows.size(), 50u);
  EXPECT_EQ(trajectories->rows[0]["data"].size(), 13u);  // the rolling samples of the point
}

TEST_F(ServerMemq, LargeResultsArriveInSeveralPages) {
  server::Server srv(config_, kinds_, lcm_);
  const auto ack = submit("big", sweep(400, 0));
  ASSERT_TRUE(client_.watch(ack.job_id, [](const auto&) {}, 20.0));
  storage::QueryRequest r = storage::query_for("solutions", ack.job_id);
  r.limit = 1000;
  const auto page = client_.query(r, 10.0);
  ASSERT_TRUE(page);
  EXPECT_EQ(page->rows.size(), 400u);
  EXPECT_EQ(page->rows.back()["point"], 399);
}

TEST_F(ServerMemq, EveryBadMessageIsRejectedByName) {
  server::Server srv(config_, kinds_, lcm_);
  const std::string garbage = "\x01\x02not an lcm message at all";
  const auto g = client_.send_raw(channels::kSubmit, garbage, "", 5.0);
  ASSERT_TRUE(g);
  EXPECT_FALSE(g->accepted);
  EXPECT_EQ(g->field, channels::kSubmit);
  const auto c = client_.send_raw(channels::kCancel, garbage, "", 5.0);
  ASSERT_TRUE(c);
  EXPECT_EQ(c->field, channels::kCancel);
  struct Case {
    std::string id, spec, field;
  };
  const std::vector<Case> cases = {
      {"m1", "{\"scene\": \"walker\", ", "spec_json"},
      {"m2", "42", "spec_json"},
      {"m3", R"({"scene": 7, "task": "foot_sweep"})", "scene"},
      {"m4", R"({"scene": "walker", "task": "foot_sweep", "foot": "P2-shoes-left-HMT", "sweep": {"parameter": "k_HM", "values": "0:0.5:5"}})", "sweep.values"},
      {"m5", std::string(channels::kMaxSpecBytes + 1, ' '), "spec_json"},
      {std::string(100, 'x'), sweep(2, 0), "request_id"},
      {"has space", sweep(2, 0), "request_id"},
  };
  for (const Case& k : cases) {
    const auto ack = submit(k.id, k.spec);
    EXPECT_FALSE(ack.accepted) << k.id;
    EXPECT_EQ(ack.field, k.field) << ack.problem;
    EXPECT_NE(ack.problem.find(k.field), std::string::npos) << ack.problem;
  }
  EXPECT_EQ(srv.counters().rejected, 2 + static_cast<long>(cases.size()));
  EXPECT_EQ(srv.store().count_jobs(std::nullopt), 0);
  // Same request id, different spec: refused rather than silently ignored.
  ASSERT_TRUE(submit("same", sweep(2, 0)).accepted);
  const auto clash = submit("same", sweep(3, 0));
  EXPECT_FALSE(clash.accepted);
  EXPECT_EQ(clash.field, "request_id");
}

TEST_F(ServerMemq, CancelStopsARunningJob) {
  server::Server srv(config_, kinds_, lcm_);
  const auto ack = submit("slow", sweep(200, 20));
  while (srv.store().job(ack.job_id)->points_stored < 3) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  const auto c = client_.cancel(ack.job_id, 5.0);
  ASSERT_TRUE(c);
  EXPECT_TRUE(c->accepted) << c->problem;
  const auto done = client_.watch(ack.job_id, [](const auto&) {}, 20.0);
  ASSERT_TRUE(done);
  EXPECT_EQ(done->state, "cancelled");
  EXPECT_LT(done->points_stored, 200);
  const auto again = client_.cancel(ack.job_id, 5.0);
  ASSERT_TRUE(again);
  EXPECT_FALSE(again->accepted);
}

TEST_F(ServerMemq, TimeLimitFailsTheJobNamingTheLimit) {
  config_.caps.max_wall_seconds = 0.3;
  server::Server srv(config_, kinds_, lcm_);
  const auto ack = submit("long", sweep(100, 20));
  const auto done = client_.watch(ack.job_id, [](const auto&) {}, 20.0);
  ASSERT_TRUE(done);
  EXPECT_EQ(done->state, "failed");
  EXPECT_NE(done->error.find("limits.max_wall_seconds"), std::string::npos) << done->error;
}

TEST_F(ServerMemq, ShutdownMidSweepResumesWithoutDuplicates) {
  constexpr int kPoints = 60;
  std::int64_t job = 0;
  {
    server::Server srv(config_, kinds_, lcm_);
    job = submit("resume", sweep(kPoints, 20)).job_id;
    while (srv.store().job(job)->points_stored < 10) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }  // graceful stop: the job goes back to the queue
  {
    storage::ResultStore s(config_.database);
    const auto j = s.job(job);
    EXPECT_EQ(j->state, storage::JobState::queued);
    EXPECT_GE(j->points_stored, 10);
    EXPECT_LT(j->points_stored, kPoints);
  }
  server::Server srv(config_, kinds_, lcm_);
  const auto done = client_.watch(job, [](const auto&) {}, 20.0);
  ASSERT_TRUE(done);
  EXPECT_EQ(done->state, "done");
  const auto j = srv.store().job(job);
  EXPECT_EQ(j->points_stored, kPoints);
  EXPECT_EQ(j->attempts, 2);
}

TEST_F(ServerMemq, CostlyJobsAreRejectedAtSubmissionWithTheEstimate) {
  const nlohmann::json huge = {{"scene", "walker"},     {"task", "multistart"}, {"foot", "point"},
                               {"speed", 1.3},          {"points", 20000},
                               {"multistart", {{"starts", 1000}}}};
  nlohmann::json big = huge;
  big["multistart"]["starts"] = 2;
  big["points"] = 5000;
  {
    server::Server srv(config_, kinds_, lcm_);
    const auto ack = submit("huge", huge.dump());
    EXPECT_FALSE(ack.accepted);
    EXPECT_EQ(ack.field, "points") << ack.problem;
    EXPECT_NE(ack.problem.find("estimated to run"), std::string::npos) << ack.problem;
    EXPECT_NE(ack.problem.find("limit of 60 min"), std::string::npos) << ack.problem;
    std::printf("rejected: %s\n", ack.problem.c_str());
    EXPECT_EQ(srv.store().count_jobs(std::nullopt), 0);
  }
  config_.max_job_memory_mb = 64;  // a server with little memory per job
  server::Server small(config_, kinds_, lcm_);
  const auto mem = submit("memory", big.dump());
  EXPECT_FALSE(mem.accepted);
  EXPECT_NE(mem.problem.find("of memory"), std::string::npos) << mem.problem;
  EXPECT_EQ(small.store().count_jobs(std::nullopt), 0);
}

TEST_F(ServerMemq, OddInputsGetFieldErrors) {
  server::Server srv(config_, kinds_, lcm_);
  const auto overflow = submit("overflow", R"({"scene": "walker", "task": "optimise", "foot": "point", "speed": 1e400})");
  EXPECT_FALSE(overflow.accepted);
  EXPECT_EQ(overflow.field, "speed") << overflow.problem;
  const auto grid = submit("grid", R"({"scene": "walker", "task": "sweep", "foot": "point", "speeds": "-1e308:1e-300:1e308"})");
  EXPECT_EQ(grid.field, "speeds");
  EXPECT_EQ(grid.problem.find("-9223372036854775808"), std::string::npos) << grid.problem;
}

TEST_F(ServerMemq, QueueQuotaStopsOneSenderFromFloodingTheQueue) {
  config_.quota.max_queued_jobs = 5;
  config_.workers = 1;
  server::Server srv(config_, kinds_, lcm_);
  int accepted = 0, over_quota = 0;
  for (int i = 0; i < 20; ++i) {
    const auto ack = submit("flood" + std::to_string(i), sweep(100, 20));
    if (ack.accepted) ++accepted;
    if (!ack.accepted && ack.field == "queue") ++over_quota;
  }
  EXPECT_LE(accepted, 6);  // 5 queued + at most one already running
  EXPECT_EQ(accepted + over_quota, 20);
}

TEST_F(ServerMemq, FullDiskRequeuesTheJobTellsItsWatchersAndKeepsItsPoints) {
  server::Server srv(config_, kinds_, lcm_);
  const auto ack = submit("disk", sweep(400, 5));
  while (srv.store().job(ack.job_id)->points_stored < 5) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  auto set_max_pages = [&](const std::string& n) {
    std::lock_guard lock(srv.store().mutex());
    srv.store().connection().exec("PRAGMA max_page_count = " + n);
  };
  {
    std::lock_guard lock(srv.store().mutex());
    storage::Statement q(srv.store().connection(), "PRAGMA page_count");
    q.step();
    srv.store().connection().exec("PRAGMA max_page_count = " + std::to_string(q.int64(0)));
  }
  const auto told = client_.watch(ack.job_id, [](const auto&) {}, 30.0);
  ASSERT_TRUE(told);
  EXPECT_EQ(told->state, "queued");
  EXPECT_NE(told->error.find("could not store a point"), std::string::npos) << told->error;
  EXPECT_NE(told->error.find("re-queued"), std::string::npos) << told->error;
  const auto j = srv.store().job(ack.job_id);
  EXPECT_TRUE(j->state == storage::JobState::queued || j->state == storage::JobState::running);
  EXPECT_GE(j->points_stored, 5);
  set_max_pages("1073741823");  // space again: the job resumes and finishes after the pause
  const auto done = client_.watch(ack.job_id, [](const auto&) {}, 60.0);
  ASSERT_TRUE(done);
  EXPECT_EQ(done->state, "done") << done->error;
  EXPECT_EQ(srv.store().job(ack.job_id)->points_stored, 400);
}

// Every store access of a job counts as a point's does: a job whose curve cannot be added (a full
// disk, injected as PRAGMA query_only, before its first point) is re-queued and resumes, not
// failed - a foot comparison of the soak test once failed so ("step: database or disk is full").
TEST_F(ServerMemq, AFullDiskAtAJobsCurveRequeuesTheJobInsteadOfFailingIt) {
  struct NoFields {};
  std::atomic<int> attempts{0};
  std::atomic<bool> disk_full{false}, curve_failed{false};
  kinds_ = service::JobKindRegistry();  // "foot_sweep" as this test's own kind: one curve, one point
  kinds_.add(service::typed_job_kind<NoFields>(
      "foot_sweep", {"walker"}, {}, [](const nlohmann::json&, const service::CommonJobFields&) { return NoFields{}; },
      [&](const NoFields&, service::JobContext& ctx) {
        ctx.announce(1);
        if (attempts++ == 0)
          while (!disk_full) std::this_thread::sleep_for(std::chrono::milliseconds(2));
        try {
          ctx.add_curve(0, "the curve", "speed");
        } catch (...) {  // seen by the test, passed on to the worker as it came
          curve_failed = true;
          throw;
        }
        storage::SolutionPoint p;
        p.key = {0, 0};
        p.parameter = 1.0;
        p.objective = 1.0;
        p.status = "converged";
        ctx.store_point(p);
      },
      [](const NoFields&) { return nlohmann::json::object(); }));
  server::Server srv(config_, kinds_, lcm_);
  auto set_query_only = [&](bool on) {
    std::lock_guard lock(srv.store().mutex());
    srv.store().connection().exec(std::string("PRAGMA query_only = ") + (on ? "1" : "0"));
  };
  const auto ack = submit("curve-on-full-disk", R"({"scene": "walker", "task": "foot_sweep"})");
  ASSERT_TRUE(ack.accepted) << ack.problem;
  while (attempts == 0) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  set_query_only(true);
  disk_full = true;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (!curve_failed && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  ASSERT_TRUE(curve_failed) << "the curve was added to a read-only database";
  set_query_only(false);  // the worker, retrying the job's state meanwhile, re-queues it
  auto done = client_.watch(ack.job_id, [](const auto&) {}, 60.0);
  if (done && done->state == "queued") done = client_.watch(ack.job_id, [](const auto&) {}, 60.0);  // re-queued; then
  ASSERT_TRUE(done);
  EXPECT_EQ(done->state, "done") << done->error;
  EXPECT_EQ(attempts, 2);
  const auto j = srv.store().job(ack.job_id);
  EXPECT_EQ(j->state, storage::JobState::done);
  EXPECT_EQ(j->points_stored, 1);
  std::lock_guard lock(srv.store().mutex());
  storage::Statement why(srv.store().connection(), "SELECT message FROM events WHERE job_id = ? AND kind = 'interrupted'");
  why.bind(1, ack.job_id);
  ASSERT_TRUE(why.step()) << "no 'interrupted' event";
  EXPECT_NE(why.text(0).find("could not store"), std::string::npos) << why.text(0);
}

// A submission the store cannot take (a full disk, injected as PRAGMA query_only) is refused as the
// server's failure, not the spec's: field "server", saying nothing was queued and that the same
// request id may be sent again - which is accepted once the store takes writes again.
TEST_F(ServerMemq, ASubmissionTheStoreCannotTakeIsRefusedAsTheServersFailure) {
  server::Server srv(config_, kinds_, lcm_);
  auto set_query_only = [&](bool on) {
    std::lock_guard lock(srv.store().mutex());
    srv.store().connection().exec(std::string("PRAGMA query_only = ") + (on ? "1" : "0"));
  };
  set_query_only(true);
  const auto refused = submit("full-disk", sweep(3, 5));
  EXPECT_FALSE(refused.accepted);
  EXPECT_EQ(refused.field, "server");
  EXPECT_NE(refused.problem.find("nothing was queued"), std::string::npos) << refused.problem;
  EXPECT_EQ(refused.problem.find("internal error"), std::string::npos) << refused.problem;
  set_query_only(false);
  const auto again = submit("full-disk", sweep(3, 5));
  EXPECT_TRUE(again.accepted) << again.problem;
  EXPECT_FALSE(again.duplicate);
}

// A store that refuses every write (PRAGMA query_only: the injected form of a full disk that also
// has no room for the state change): the point fails, re-queueing fails too. The job must not stay
// `running` without a worker: its worker retries the state change, says so on LCM, and once writes
// succeed again the job resumes by itself within 10 s (issue 57, acceptance 1).
TEST_F(ServerMemq, JobWhoseStateCannotBeWrittenIsRetriedAndResumesWithinTenSeconds) {
  config_.workers = 1;
  server::Server srv(config_, kinds_, lcm_);
  const auto ack = submit("no-writes", sweep(200, 5));
  while (srv.store().job(ack.job_id)->points_stored < 5) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  auto set_query_only = [&](bool on) {
    std::lock_guard lock(srv.store().mutex());
    srv.store().connection().exec(std::string("PRAGMA query_only = ") + (on ? "1" : "0"));
  };
  set_query_only(true);
  std::string notice;
  const auto early = client_.watch(ack.job_id, [&](const cyclopt_lcm::job_progress_t& p) {
    if (p.message.find("cannot record") != std::string::npos) notice = p.message;
  }, 3.0);
  EXPECT_FALSE(early) << "the job ended while nothing could be written: " << early->state << " " << early->error;
  EXPECT_NE(notice.find("retrying"), std::string::npos) << "progress said '" << notice << "'";
  EXPECT_EQ(srv.store().job(ack.job_id)->attempts, 1);
  const auto t0 = std::chrono::steady_clock::now();
  set_query_only(false);  // space again
  double resumed_after = -1.0;
  while (std::chrono::steady_clock::now() - t0 < std::chrono::seconds(15)) {
    const auto j = srv.store().job(ack.job_id);
    if (j->attempts >= 2 || storage::is_final(j->state)) {
      resumed_after = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  std::printf("resumed %.2f s after writes were possible again\n", resumed_after);
  ASSERT_GE(resumed_after, 0.0) << "the job did not resume within 15 s";
  EXPECT_LE(resumed_after, 10.0);
  auto done = client_.watch(ack.job_id, [](const auto&) {}, 60.0);
  ASSERT_TRUE(done);
  if (done->state == "queued") {  // the done message of the re-queueing, once it could be recorded
    EXPECT_NE(done->error.find("re-queued"), std::string::npos) << done->error;
    done = client_.watch(ack.job_id, [](const auto&) {}, 60.0);
    ASSERT_TRUE(done);
  }
  EXPECT_EQ(done->state, "done") << done->error;
  EXPECT_EQ(srv.store().job(ack.job_id)->points_stored, 200);
}

// A row left `running` with no worker behind it (however it came about) is re-queued by the
// server's periodic check, and runs.
TEST_F(ServerMemq, RunningJobWithoutAWorkerIsRequeued) {
  config_.workers = 1;
  server::Server srv(config_, kinds_, lcm_);
  const auto ack = submit("orphan-source", sweep(3, 0));
  ASSERT_TRUE(client_.watch(ack.job_id, [](const auto&) {}, 30.0));
  {
    std::lock_guard lock(srv.store().mutex());
    srv.store().connection().exec("UPDATE jobs SET state = 'running' WHERE id = " + std::to_string(ack.job_id));
  }
  const auto t0 = std::chrono::steady_clock::now();
  while (srv.store().job(ack.job_id)->state == storage::JobState::running &&
         std::chrono::steady_clock::now() - t0 < std::chrono::seconds(15))
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  const auto j = srv.store().job(ack.job_id);
  EXPECT_NE(j->state, storage::JobState::running) << "still running without a worker after 15 s";
  EXPECT_EQ(j->points_stored, 3);
}

// Cancel and the wall-time limit inside long solver work (a walker sweep's multistart): both
// take effect within 1 s on an idle machine (measured 0.004 s and 0.003 s overshoot, 2026-12-02).
// 5 s allowed here: at load 4-13 on 2 cores (other builds beside the suite) the starved worker
// threads took 2.4-8 s, and this test is about the stop being honoured, not about the load.
TEST_F(ServerMemq, CancelAndWallLimitStopARunningSweepWithinASecond) {
  const nlohmann::json spec = {{"scene", "walker"}, {"task", "sweep"}, {"foot", "point"}, {"speeds", "0.6:0.1:1.4"},
                               {"multistart", {{"starts", 6}}}};
  server::Server srv(config_, kinds_, lcm_);
  const auto ack = submit("cancel-sweep", spec.dump());
  ASSERT_TRUE(ack.accepted) << ack.problem;
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // inside the multistart at 0.6 m/s
  const auto t0 = std::chrono::steady_clock::now();
  ASSERT_TRUE(client_.cancel(ack.job_id, 5.0));
  const auto done = client_.watch(ack.job_id, [](const auto&) {}, 60.0);
  const double latency = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_TRUE(done);
  EXPECT_EQ(done->state, "cancelled");
  EXPECT_LT(latency, 5.0);
  nlohmann::json limited = spec;
  limited["limits"] = {{"max_wall_seconds", 2.0}};
  const auto lim = submit("limited-sweep", limited.dump());
  const auto failed = client_.watch(lim.job_id, [](const auto&) {}, 60.0);
  ASSERT_TRUE(failed);
  EXPECT_EQ(failed->state, "failed");
  EXPECT_LT(failed->run_seconds - 2.0, 5.0);
  std::printf("cancel latency %.3f s; wall limit 2 s: stopped after %.3f s (overshoot %.3f s)\n", latency,
              failed->run_seconds, failed->run_seconds - 2.0);
}

}  // namespace
}  // namespace cyclopt
