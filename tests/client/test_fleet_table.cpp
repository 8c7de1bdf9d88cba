// The fleet views `cyclopt list` and `cyclopt top` (client/fleet_table.hpp): every job's state,
// progress and best objective fit the width; other columns are dropped from the right.
#include "fleet_table.hpp"

#include <gtest/gtest.h>

#include <limits>

using namespace cyclopt::client;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Rows as the `jobs` query returns them (storage_read/result_queries.hpp), with long names and feet.
std::vector<FleetJob> fleet() {
  const double t = 1.7e9;
  std::vector<FleetJob> jobs;
  jobs.push_back(fleet_job({{"id", 1}, {"name", "P2 shoes HMT sweep over speed, 21 values"}, {"task", "sweep"},
                            {"foot", "P2-shoes-left-HMT"}, {"state", "done"}, {"progress_percent", 100.0},
                            {"best_objective", 0.0226312}, {"run_seconds", 191.4}, {"submitted_at", t},
                            {"started_at", t + 1}, {"finished_at", t + 193}, {"phase", "done"}, {"request_id", "abc"}}));
  jobs.push_back(fleet_job({{"id", 12}, {"name", "feet compared"}, {"task", "foot_comparison"},
                            {"foot", "point,P2-shoes-left-HMT"}, {"state", "running"}, {"progress_percent", 42.4},
                            {"eta_seconds", 311.0}, {"best_objective", 0.0187}, {"run_seconds", 228.0}, {"submitted_at", t + 5},
                            {"started_at", t + 194}, {"finished_at", nullptr},
                            {"phase", "foot 2/2 P2-shoes-left-HMT continuation run 3 from 1.3 m/s upwards, curve 2"}}));
  jobs.push_back(fleet_job({{"id", 123}, {"name", ""}, {"task", "foot_design"}, {"foot", "P2-shoes-left-HMT"}, {"state", "running"},
                            {"progress_percent", 7.0}, {"eta_seconds", nullptr}, {"best_objective", nullptr},
                            {"run_seconds", 12.0}, {"submitted_at", t + 6}, {"started_at", t + 400}, {"phase", "multistart at 0.3 m/s"}}));
  jobs.push_back(fleet_job({{"id", 1234}, {"name", "queued one"}, {"task", "sweep"}, {"foot", "point"}, {"state", "queued"},
                            {"submitted_at", t + 7}, {"run_seconds", 0.0}}));
  return jobs;
}

// The cells of a line split at runs of two or more spaces.
std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < line.size()) {
    const std::size_t gap = line.find("  ", i);
    out.push_back(line.substr(i, gap - i));
    if (gap == std::string::npos) break;
    i = line.find_first_not_of(' ', gap);
  }
  return out;
}

}  // namespace

TEST(FleetTable, TopAtEightyColumnsShowsStateProgressAndBestOfEveryJob) {
  const std::vector<std::string> lines = fleet_table(fleet(), FleetView::top, 80);
  ASSERT_EQ(lines.size(), 5u);
  for (const std::string& l : lines) {
    std::printf("%s\n", l.c_str());
    EXPECT_LE(l.size(), 80u) << l;
  }
  EXPECT_EQ(cells(lines[0]).at(0), "ID");
  EXPECT_EQ(cells(lines[0]).at(1), "STATE");
  EXPECT_EQ(cells(lines[0]).at(2), "PROG");
  EXPECT_EQ(cells(lines[0]).at(3), "BEST");
  const std::vector<std::vector<std::string>> expected = {
      {"1", "done", "100%", "0.022631"}, {"12", "running", "42%", "0.0187"}, {"123", "running", ">=7%", "-"}, {"1234", "queued", "-", "-"}};
  for (std::size_t r = 0; r < expected.size(); ++r) {
    const std::vector<std::string> c = cells(lines[r + 1]);
    ASSERT_GE(c.size(), 4u) << lines[r + 1];
    for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(c[k], expected[r][k]) << lines[r + 1];
  }
}

TEST(FleetTable, TopDropsColumnsFromTheRightButNeverStateProgressOrBest) {
  for (const std::size_t width : {200u, 120u, 80u, 60u, 40u}) {
    const std::vector<std::string> lines = fleet_table(fleet(), FleetView::top, width);
    for (const std::string& l : lines) EXPECT_LE(l.size(), width) << l;
    const std::vector<std::string> head = cells(lines[0]);
    ASSERT_GE(head.size(), 4u) << width;
    EXPECT_EQ(head[3], "BEST") << width;
    // The columns shown are a prefix of the documented order.
    const std::vector<std::string> order = {"ID", "STATE", "PROG", "BEST", "ETA", "RUN", "NAME", "KIND", "FOOT", "STARTED", "PHASE"};
    for (std::size_t k = 0; k < head.size(); ++k) EXPECT_EQ(head[k], order[k]) << width << ": " << lines[0];
  }
  EXPECT_EQ(cells(fleet_table(fleet(), FleetView::top, 200)[0]).size(), 11u);
}

TEST(FleetTable, ListAtOneHundredTwentyColumns) {
  const std::vector<std::string> lines = fleet_table(fleet(), FleetView::list, 120);
  for (const std::string& l : lines) {
    std::printf("%s\n", l.c_str());
    EXPECT_LE(l.size(), 120u) << l;
    EXPECT_EQ(l.find("abc"), std::string::npos) << "request ids only with --wide";
  }
  const std::vector<std::string> head = cells(lines[0]);
  const std::vector<std::string> order = {"ID", "NAME", "KIND", "FOOT", "STATE", "PROG", "BEST", "RUN", "SUBMITTED", "STARTED", "ENDED"};
  ASSERT_GE(head.size(), 9u) << lines[0];
  for (std::size_t k = 0; k < head.size(); ++k) EXPECT_EQ(head[k], order[k]);
  const std::vector<std::string> done = cells(lines[1]);
  EXPECT_EQ(done[2], "sweep");
  EXPECT_EQ(done[4], "done");
  EXPECT_EQ(done[5], "100%");
  EXPECT_EQ(done[6], "0.022631");
  EXPECT_EQ(done[7], "3:11");
  EXPECT_EQ(done[8], local_iso_minutes(1.7e9));
  EXPECT_EQ(done[8].size(), 16u);  // 2023-11-14T22:13
  EXPECT_EQ(done[8][10], 'T');
  EXPECT_EQ(done.size(), 11u) << "every column fits 120 here: " << lines[1];
  EXPECT_EQ(done[10], local_iso_minutes(1.7e9 + 193).substr(11)) << "the time of day on the day submitted";
}

TEST(FleetTable, LiveProgressReplacesTheStoredOne) {
  FleetJob j = fleet()[2];
  cyclopt_lcm::job_progress_t p{};
  p.job_id = 123;
  p.percent = 9.5;
  p.percent_is_lower_bound = false;
  p.eta_seconds = 120.0;
  p.best_objective = 0.031;
  p.elapsed_seconds = 15.0;
  p.phase = "continuation run 1 from 0.3 m/s upwards, curve 1";
  apply_progress(j, p);
  const std::vector<std::string> c = cells(fleet_table({j}, FleetView::top, 200)[1]);
  EXPECT_EQ(c[2], "9%");
  EXPECT_EQ(c[3], "0.031");
  EXPECT_EQ(c[4], "2:00");
  EXPECT_EQ(c[5], "15 s");
}

TEST(FleetTable, IsoTimes) {
  const std::string t = local_iso_time(1.7e9);
  ASSERT_EQ(t.size(), 25u) << t;  // 2023-11-14T22:13:20+00:00
  EXPECT_EQ(t[10], 'T');
  EXPECT_EQ(t[22], ':');
  EXPECT_EQ(local_iso_time(kNaN), "-");
}
