// Progress that does not lie (issue 53 item 3): the meter (service/progress_meter.hpp) and the
// sequence of progress messages of small jobs through the server over memq://: the percentage
// never decreases, reads 100 only in the message of the finished job, every phase change is an
// event, and progress, query and the stored curves number curves alike.
#include "cyclopt/service/progress_meter.hpp"
#include "memq_server_fixture.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace cyclopt {
namespace {

using service::ProgressMeter;
using service::ProgressReport;

TEST(ProgressMeter, PercentIsTheShareOfTheEstimatedRunTimeAndNeverDecreases) {
  ProgressMeter m;
  ProgressReport r{.points_done = 0, .points_total = 4};
  r.eta_seconds = 30.0;
  EXPECT_NEAR(m.read(r, 10.0, 10.0).percent, 25.0, 1e-12);  // 10 s of 40
  r.eta_seconds = 90.0;                                      // a phase found more work
  const service::ProgressReading grown = m.read(r, 20.0, 20.0);
  EXPECT_NEAR(grown.percent, 25.0, 1e-12) << "held, not 18 %";
  EXPECT_NEAR(grown.eta_seconds, 90.0, 1e-12);
  r.eta_seconds = 10.0;
  EXPECT_NEAR(m.read(r, 90.0, 90.0).percent, 90.0, 1e-12);
}

TEST(ProgressMeter, AllPointsDoneIsNotOneHundredPercentWhileTheJobRuns) {
  ProgressMeter m;
  const ProgressReport r{.points_done = 4, .points_total = 4};  // e.g. a sweep's speeds all reached
  const service::ProgressReading reading = m.read(r, 50.0, 50.0);
  EXPECT_LT(reading.percent, 100.0);
  EXPECT_LE(reading.percent, ProgressMeter::kRunningCap);
  EXPECT_EQ(m.finish(true).percent, 100.0);
}

TEST(ProgressMeter, ARepeatedEstimateCountsDownAndThenIsUnknown) {
  ProgressMeter m;
  ProgressReport r;
  r.eta_seconds = 1.0;
  EXPECT_NEAR(m.read(r, 10.0, 10.0).eta_seconds, 1.0, 1e-12);
  EXPECT_NEAR(m.read(r, 10.5, 10.5).eta_seconds, 0.5, 1e-12);
  const service::ProgressReading late = m.read(r, 30.0, 30.0);  // "ETA 1 s" 20 s later
  EXPECT_TRUE(std::isnan(late.eta_seconds));
  EXPECT_TRUE(late.lower_bound);
  EXPECT_NEAR(late.percent, 100.0 * 10.5 / 11.0, 1e-9) << "held where the estimate left it";
}

TEST(ProgressMeter, WithoutAnEstimateThePointsGiveTheRate) {
  ProgressMeter m(2);  // two points from an earlier attempt
  const ProgressReport r{.points_done = 4, .points_total = 10};
  const service::ProgressReading reading = m.read(r, 100.0, 20.0);  // 2 points in this attempt's 20 s
  EXPECT_NEAR(reading.eta_seconds, 60.0, 1e-12);
  EXPECT_NEAR(reading.percent, 62.5, 1e-12);
  EXPECT_FALSE(reading.lower_bound);
  EXPECT_NEAR(m.finish(false).percent, 62.5, 1e-12) << "a failed job keeps what it reached";
}

// Units at once: the longest running unit's ETA plus the units not begun, in rounds of as many as
// run at once, at the mean duration of the units ended.
TEST(ProgressMeter, UnitsRunningAtOnceGiveTheLongestRestPlusTheUnitsNotBegun) {
  ProgressMeter m;
  m.units(4);
  ProgressReport a, b;
  a.unit = "foot-0";
  b.unit = "foot-1";
  a.eta_seconds = 30.0;
  b.eta_seconds = ProgressReport::kNaN;
  m.read(a, 10.0, 10.0);
  EXPECT_TRUE(std::isnan(m.read(b, 10.0, 10.0).eta_seconds)) << "foot-1 runs without an estimate yet";
  b.eta_seconds = 50.0;
  // foot-0: began at 10 s, 30 s left; foot-1: began at 10 s, 50 s left; two not begun, one round
  // of two at the running units' mean estimated duration (30 + 50) / 2 + 0 = 40 s.
  EXPECT_NEAR(m.read(b, 10.0, 10.0).eta_seconds, 50.0 + 40.0, 1e-9);
  m.unit_ended("foot-0", 40.0);  // took 30 s
  b.eta_seconds = 20.0;
  // foot-1 alone: 20 s left, then two units one at a time at 30 s each.
  EXPECT_NEAR(m.read(b, 40.0, 40.0).eta_seconds, 20.0 + 2 * 30.0, 1e-9);
}

using JobProgress = testing::MemqServerTest;

struct Watched {
  std::vector<cyclopt_lcm::job_progress_t> messages;
  std::string state;
  std::int64_t job_id = 0;
};

Watched watch_job(JobProgress& t, client::ServiceClient& client, const std::string& id, const nlohmann::json& spec) {
  Watched w;
  const auto ack = client.submit(id, spec.dump(), 5.0);
  EXPECT_TRUE(ack && ack->accepted) << (ack ? ack->problem : "no ack");
  if (!ack || !ack->accepted) return w;
  w.job_id = ack->job_id;
  const auto done = client.watch(ack->job_id, [&](const cyclopt_lcm::job_progress_t& p) { w.messages.push_back(p); }, 300.0);
  EXPECT_TRUE(done);
  if (done) w.state = done->state;
  (void)t;
  return w;
}

// The findings as assertions on the message sequence.
void expect_honest(const Watched& w) {
  ASSERT_GE(w.messages.size(), 3u);
  double last = 0.0;
  std::string phases;
  for (std::size_t i = 0; i < w.messages.size(); ++i) {
    const cyclopt_lcm::job_progress_t& p = w.messages[i];
    EXPECT_GE(p.percent, last) << "message " << i << " (" << p.phase << ") goes back from " << last;
    last = p.percent;
    if (i + 1 < w.messages.size()) {
      EXPECT_LT(p.percent, 100.0) << "message " << i << " (" << p.phase << ") says 100 % before the job ended";
      if (std::isfinite(p.eta_seconds)) {
        EXPECT_GT(p.eta_seconds, 0.0) << "an expired ETA is unknown, not 0";
      }
    }
  }
  const cyclopt_lcm::job_progress_t& end = w.messages.back();
  EXPECT_EQ(end.phase, w.state);
  EXPECT_EQ(end.percent, 100.0);
  EXPECT_EQ(w.state, "done");
  EXPECT_EQ(end.points_done, end.points_total) << "a done job's last message counts every point it announced";
}

// Every phase the messages show is a "phase" event (units running at once interleave their
// messages, so the events are compared as a set).
void expect_phase_events(client::ServiceClient& client, const Watched& w) {
  std::set<std::string> changes;
  for (const cyclopt_lcm::job_progress_t& p : w.messages)
    if (!p.phase.empty() && p.phase != w.state) changes.insert(p.phase);
  const auto events = client.query(storage::query_for("events", w.job_id), 5.0);
  ASSERT_TRUE(events);
  std::set<std::string> stored;
  for (const nlohmann::json& e : events->rows)
    if (e["kind"] == "phase") stored.insert(e["message"].get<std::string>().substr(0, e["message"].get<std::string>().find(" | ")));
  for (const std::string& phase : changes) EXPECT_TRUE(stored.count(phase)) << "no event for phase " << phase;
  const auto job = client.query(storage::query_for("job", w.job_id), 5.0);
  ASSERT_TRUE(job);
  EXPECT_EQ(job->rows.at(0)["progress_percent"], 100.0);
  EXPECT_EQ(job->rows.at(0)["phase"], "done");
}

TEST_F(JobProgress, PointFootSweepIsMonotoneAndReachesOneHundredOnlyAtTheEnd) {
  config_.progress_hz = 50;
  server::Server srv(config_, kinds_, lcm_);
  const nlohmann::json spec = {{"scene", "walker"}, {"task", "sweep"}, {"foot", "point"}, {"speeds", "0.9:0.1:1.1"},
                               {"solver", {{"max_iterations", 600}}}, {"multistart", {{"starts", 2}, {"seed", 3}, {"scale", 0.02}}},
                               {"continuation", {{"seed_speeds", 1.0}}}};
  const Watched w = watch_job(*this, client_, "progress-sweep", spec);
  std::printf("%zu progress messages\n", w.messages.size());
  expect_honest(w);
  expect_phase_events(client_, w);
  // One curve numbering: a curve the progress names is a stored curve, named by its number.
  const auto curves = client_.query(storage::query_for("curves", w.job_id), 5.0);
  ASSERT_TRUE(curves);
  std::set<int> stored;
  for (const nlohmann::json& c : curves->rows) {
    const int index = c["curve"].get<int>();
    stored.insert(index);
    if (index > 0) {
      EXPECT_EQ(c["name"], "solution curve " + std::to_string(index));
    }
  }
  const std::regex named("curve ([0-9]+)");
  int seen = 0;
  for (const cyclopt_lcm::job_progress_t& p : w.messages)
    for (std::sregex_iterator it(p.phase.begin(), p.phase.end(), named), end; it != end; ++it, ++seen)
      EXPECT_TRUE(stored.count(std::stoi((*it)[1]))) << p.phase;
  EXPECT_GT(seen, 0) << "the sweep's continuation runs name their curve";
}

// Its last report comes from the solve, before the point is stored: the end still says 1/1.
TEST_F(JobProgress, AnOptimiseJobEndsWithItsPointCounted) {
  config_.progress_hz = 50;
  server::Server srv(config_, kinds_, lcm_);
  const nlohmann::json spec = {{"scene", "walker"}, {"task", "optimise"}, {"foot", "point"}, {"speed", 1.0}};
  const Watched w = watch_job(*this, client_, "progress-optimise", spec);
  expect_honest(w);
  EXPECT_EQ(w.messages.back().points_total, 1);
}

TEST_F(JobProgress, TwoFootComparisonIsMonotoneAcrossItsFeet) {
  config_.progress_hz = 50;
  server::Server srv(config_, kinds_, lcm_);
  const nlohmann::json spec = {{"scene", "walker"},
                               {"task", "foot_comparison"},
                               {"speeds", "1.0:0.1:1.1"},
                               {"points", 40},
                               {"feet", {"P1-barefoot-left-HM"}},
                               {"multistart", {{"starts", 2}, {"seed", 3}, {"scale", 0.02}}},
                               {"continuation", {{"seed_speeds", 1.0}}}};
  const Watched w = watch_job(*this, client_, "progress-comparison", spec);
  std::set<std::string> feet;
  for (const cyclopt_lcm::job_progress_t& p : w.messages)
    if (p.phase.rfind("foot ", 0) == 0) feet.insert(p.phase.substr(0, 8));  // "foot 1/2"
  std::printf("%zu progress messages, feet seen: %zu\n", w.messages.size(), feet.size());
  EXPECT_EQ(feet.size(), 2u) << "progress went through both feet";
  expect_honest(w);
  expect_phase_events(client_, w);
}

}  // namespace
}  // namespace cyclopt
