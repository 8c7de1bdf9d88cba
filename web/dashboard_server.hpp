#pragma once
// cyclopt-web's HTTP side (docs/dashboard.md). Routes:
//   GET  /, /job/ID             the page (web/page/); which view follows from the path
//   GET  /static/...            its script, style and uPlot (web_assets.hpp)
//   GET  /login?token=T         under authentication: checks T (web_token.hpp), sets it as cookie
//   GET  /api/fleet/events      Server-Sent Events: "rows", the fleet rows changed (all at first)
//   GET  /api/job/ID/events     Server-Sent Events of one job: "job", "progress", "points",
//                               "curves", "events" (what each holds: docs/dashboard.md)
//   GET  /job/ID/report         the job's report (plot/job_report.hpp), as `cyclopt report` writes it
//   GET  /job/ID/export.json    the job as `cyclopt export` writes it
//   POST /api/job/ID/cancel     a cancel request to cycloptd over LCM (signed with the viewer's key)
// Nothing is written through GET. Under authentication every route but /static/ and /login needs
// the token cookie; a key reads what the server's auth_reads lets it read.

#include "dashboard_config.hpp"
#include "live_fleet.hpp"
#include "message_auth.hpp"

#include "cyclopt/storage_read/result_reader.hpp"

#include <memory>
#include <optional>

namespace cyclopt::web {

class DashboardServer {
 public:
  // `keys`: the server's key file when authentication is on.
  DashboardServer(const DashboardConfig& config, storage::ResultReader& store, LiveFleet& fleet,
                  std::optional<wire::KeyRing> keys);
  ~DashboardServer();
  // Serves until stop(); false if it cannot listen on config.host:port.
  bool listen();
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cyclopt::web
