// The progress display of `cyclopt watch` (client/progress_line.hpp): what a user reads in a
// terminal and in a log.
#include "progress_line.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <limits>

using namespace cyclopt::client;

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

cyclopt_lcm::job_progress_t sweep_report() {
  cyclopt_lcm::job_progress_t p{};
  p.job_id = 3;
  p.task = "sweep";
  p.iteration = 12;
  p.objective = 0.031;
  p.constraint_violation = 1e-9;
  p.parameter = 1.3;
  p.curve_id = 0;
  p.points_done = 6;
  p.points_total = 21;
  p.percent = 100.0 * 6 / 21;
  p.eta_seconds = 150.0;
  p.message = "speed sweep";
  p.phase = "continuation run 2 from 1.3 m/s upwards, curve 1";
  p.phase_done = 5;
  p.phase_total = 10;
  p.best_objective = 0.02263;
  p.elapsed_seconds = 72.0;
  return p;
}

}  // namespace

TEST(ProgressLine, NamesPhasePointsBestObjectiveAndEta) {
  EXPECT_EQ(progress_line(sweep_report(), 200),
            "job 3  28% 6/21 | 1:12, ETA 2:30 | continuation run 2 from 1.3 m/s upwards, curve 1 5/10 | best 0.02263");
}

// The percentage is the server's (not points done / total), rounded down so a running job never
// reads 100 %, and marked as a lower bound when the server says so.
TEST(ProgressLine, PercentIsTheServersRoundedDownAndMayBeALowerBound) {
  cyclopt_lcm::job_progress_t p = sweep_report();
  p.points_done = 21;
  p.percent = 99.7;
  EXPECT_EQ(progress_line(p, 200).substr(0, 15), "job 3  99% 21/2");
  p.percent_is_lower_bound = true;
  p.eta_seconds = nan;
  EXPECT_EQ(progress_line(p, 200).substr(0, 17), "job 3 >=99% 21/21");
  EXPECT_EQ(percent_text(100.0, false), "100%");
  EXPECT_EQ(percent_text(nan, false), "?");
}

// At 80 columns a long phase is cut, not the best objective (issue 53).
TEST(ProgressLine, EightyColumnsKeepTheBestValue) {
  const std::string line = progress_line(sweep_report(), 80);
  EXPECT_EQ(line.size(), 80u);
  EXPECT_EQ(line.substr(line.size() - 15), " | best 0.02263") << line;
  EXPECT_NE(line.find("..."), std::string::npos) << line;
}

TEST(ProgressLine, UnknownsAreSaidAsSuch) {
  cyclopt_lcm::job_progress_t p = sweep_report();
  p.points_total = -1;
  p.phase = "";
  p.phase_total = -1;
  p.best_objective = nan;
  p.eta_seconds = nan;
  p.percent = nan;
  EXPECT_EQ(progress_line(p, 200), "job 3    ? | 1:12, ETA ? | speed sweep | objective 0.031");
}

TEST(ProgressLine, FitsTheTerminal) {
  const std::string line = progress_line(sweep_report(), 40);
  EXPECT_EQ(line.size(), 40u);
  EXPECT_EQ(line.substr(37), "...");
}

TEST(ProgressLine, Durations) {
  EXPECT_EQ(duration_text(0.4), "0 s");
  EXPECT_EQ(duration_text(59.4), "59 s");
  EXPECT_EQ(duration_text(185), "3:05");
  EXPECT_EQ(duration_text(3725), "1:02:05");
  EXPECT_EQ(duration_text(nan), "?");
  EXPECT_EQ(duration_text(-1), "?");
}

TEST(ProgressLine, LogGetsALineOnEveryPhaseChangeAndOtherwiseEveryInterval) {
  LogThrottle log(std::chrono::seconds(5));
  const auto t0 = std::chrono::steady_clock::time_point{} + std::chrono::hours(1);
  cyclopt_lcm::job_progress_t p = sweep_report();
  EXPECT_TRUE(log.due(p, t0));
  int lines = 0;
  for (int ms = 100; ms < 4900; ms += 100) lines += log.due(p, t0 + std::chrono::milliseconds(ms));
  EXPECT_EQ(lines, 0);  // 48 reports within 5 s of the same phase: no line
  EXPECT_TRUE(log.due(p, t0 + std::chrono::milliseconds(5000)));
  p.phase = "recovery at 0.8 m/s (unreached)";
  EXPECT_TRUE(log.due(p, t0 + std::chrono::milliseconds(5100)));
  EXPECT_FALSE(log.due(p, t0 + std::chrono::milliseconds(5200)));
}
