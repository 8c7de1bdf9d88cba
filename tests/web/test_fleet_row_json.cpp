// One job as the dashboard receives it (web/fleet_row_json.hpp) and the live fleet that keeps the
// rows (web/live_fleet.hpp): the jobs query row with the newest progress message applied, queue
// positions, and only changed rows sent again.
#include "live_fleet.hpp"

#include <gtest/gtest.h>

using namespace cyclopt;

namespace {

constexpr double kT = 1.8e9;

nlohmann::json job_row(std::int64_t id, const std::string& state) {
  return {{"id", id},
          {"name", "<script>alert(1)</script>"},
          {"task", "sweep"},
          {"foot", "point"},
          {"state", state},
          {"progress_percent", state == "queued" ? nlohmann::json(nullptr) : nlohmann::json(12.5)},
          {"eta_seconds", nullptr},
          {"best_objective", nullptr},
          {"run_seconds", 3.0},
          {"submitted_at", kT},
          {"started_at", state == "queued" ? nlohmann::json(nullptr) : nlohmann::json(kT + 1)},
          {"finished_at", nullptr},
          {"phase", ""},
          {"error", ""},
          {"cancel_requested", false},
          {"points_stored", 2},
          {"points_total", nullptr}};
}

cyclopt_lcm::job_progress_t progress(std::int64_t id, double percent) {
  cyclopt_lcm::job_progress_t p{};
  p.job_id = id;
  p.timestamp_us = static_cast<std::int64_t>(kT * 1e6) + 5'000'000;
  p.percent = percent;
  p.percent_is_lower_bound = false;
  p.eta_seconds = 40.0;
  p.best_objective = 0.0226;
  p.elapsed_seconds = 7.0;
  p.phase = "multistart at 1.3 m/s";
  return p;
}

}  // namespace

TEST(FleetRowJson, CarriesTheFleetLineAndWhatABrowserShowsMore) {
  std::vector<web::FleetRow> rows{web::fleet_row(job_row(3, "queued")), web::fleet_row(job_row(1, "running")),
                                  web::fleet_row(job_row(2, "queued"))};
  web::number_queue(rows);
  EXPECT_EQ(rows[0].queue_position, 2);
  EXPECT_EQ(rows[1].queue_position, 0);
  EXPECT_EQ(rows[2].queue_position, 1);
  const nlohmann::json j = web::to_json(rows[1]);
  EXPECT_EQ(j["name"], "<script>alert(1)</script>");  // verbatim: the page sets it as text
  EXPECT_EQ(j["kind"], "sweep");
  EXPECT_EQ(j["state"], "running");
  EXPECT_DOUBLE_EQ(j["percent"].get<double>(), 12.5);
  EXPECT_TRUE(j["percent_lower_bound"].get<bool>());  // running without an ETA: a lower bound
  EXPECT_TRUE(j["eta_seconds"].is_null());
  EXPECT_TRUE(j["best_objective"].is_null());
  EXPECT_TRUE(j["finished"].is_null());
  EXPECT_EQ(j["submitted"].get<std::string>().size(), 16u);  // 2027-01-15T08:00, local time
  EXPECT_EQ(j["points_total"], -1);
  EXPECT_EQ(j["progress_us"], 0);
}

TEST(LiveFleet, AppliesProgressAndSendsOnlyWhatChanged) {
  web::LiveFleet fleet;
  fleet.refresh(nlohmann::json::array({job_row(1, "running"), job_row(2, "queued")}));
  web::LiveFleet::Changes all = fleet.rows_since(0);
  ASSERT_EQ(all.rows.size(), 2u);
  EXPECT_TRUE(fleet.rows_since(all.seq).rows.empty());

  fleet.apply(progress(1, 30.0));
  web::LiveFleet::Changes changed = fleet.rows_since(all.seq);
  ASSERT_EQ(changed.rows.size(), 1u);
  EXPECT_DOUBLE_EQ(changed.rows[0].job.percent, 30.0);
  EXPECT_EQ(changed.rows[0].job.phase, "multistart at 1.3 m/s");
  EXPECT_EQ(changed.rows[0].progress_us, progress(1, 30.0).timestamp_us);

  // The database's older progress does not take the live one back; an unchanged refresh sends nothing.
  fleet.refresh(nlohmann::json::array({job_row(1, "running"), job_row(2, "queued")}));
  EXPECT_TRUE(fleet.rows_since(changed.seq).rows.empty());
  EXPECT_DOUBLE_EQ(fleet.job(1).row->job.percent, 30.0);

  // A job that ended shows its stored state.
  nlohmann::json done = job_row(1, "done");
  done["progress_percent"] = 100.0;
  fleet.refresh(nlohmann::json::array({done, job_row(2, "queued")}));
  const web::LiveFleet::Changes ended = fleet.rows_since(changed.seq);
  ASSERT_EQ(ended.rows.size(), 1u);
  EXPECT_EQ(ended.rows[0].job.state, "done");
  EXPECT_DOUBLE_EQ(ended.rows[0].job.percent, 100.0);
  EXPECT_EQ(fleet.wait(ended.seq, std::chrono::milliseconds(1)), ended.seq);  // nothing new: times out
}

// A job's last message (100 %) wakes the reader of the job list at once; other messages do not.
TEST(LiveFleet, AJobsLastMessageAsksForTheJobListAtOnce) {
  web::LiveFleet fleet;
  fleet.refresh(nlohmann::json::array({job_row(1, "running")}));
  const auto waited = [&](std::chrono::milliseconds timeout) {
    const auto start = std::chrono::steady_clock::now();
    fleet.wait_for_refresh(timeout);
    return std::chrono::steady_clock::now() - start;
  };
  fleet.apply(progress(1, 99.0));
  EXPECT_GE(waited(std::chrono::milliseconds(50)), std::chrono::milliseconds(50));
  fleet.apply(progress(1, 100.0));
  EXPECT_LT(waited(std::chrono::seconds(30)), std::chrono::seconds(10));
  EXPECT_GE(waited(std::chrono::milliseconds(50)), std::chrono::milliseconds(50));  // asked once
}
