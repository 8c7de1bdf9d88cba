#include "fleet_row_json.hpp"

#include "cyclopt/records/json_fields.hpp"

#include <algorithm>
#include <cmath>

namespace cyclopt::web {

namespace {

using records::finite_or_null;
nlohmann::json time_text(double unix_seconds) {
  return std::isfinite(unix_seconds) ? nlohmann::json(client::local_iso_minutes(unix_seconds)) : nlohmann::json(nullptr);
}

}  // namespace

FleetRow fleet_row(const nlohmann::json& job_row) {
  FleetRow r;
  r.job = client::fleet_job(job_row);
  r.error = job_row.value("error", std::string());
  r.cancel_requested = job_row.value("cancel_requested", false);
  r.points_stored = job_row.value("points_stored", 0);
  const auto total = job_row.find("points_total");
  if (total != job_row.end() && total->is_number_integer()) r.points_total = total->get<int>();
  return r;
}

void number_queue(std::vector<FleetRow>& rows) {
  std::vector<FleetRow*> queued;
  for (FleetRow& r : rows) {
    r.queue_position = 0;
    if (r.job.state == "queued") queued.push_back(&r);
  }
  std::sort(queued.begin(), queued.end(), [](const FleetRow* a, const FleetRow* b) { return a->job.id < b->job.id; });
  for (std::size_t i = 0; i < queued.size(); ++i) queued[i]->queue_position = static_cast<int>(i + 1);
}

nlohmann::json to_json(const FleetRow& r) {
  const client::FleetJob& j = r.job;
  return {{"id", j.id},
          {"name", j.name},
          {"kind", j.kind},
          {"foot", j.foot},
          {"state", j.state},
          {"phase", j.phase},
          {"percent", finite_or_null(j.percent)},
          {"percent_lower_bound", j.percent_lower_bound},
          {"eta_seconds", finite_or_null(j.eta_seconds)},
          {"best_objective", finite_or_null(j.best_objective)},
          {"run_seconds", finite_or_null(j.run_seconds)},
          {"submitted", time_text(j.submitted_at)},
          {"started", time_text(j.started_at)},
          {"finished", time_text(j.finished_at)},
          {"error", r.error},
          {"cancel_requested", r.cancel_requested},
          {"queue_position", r.queue_position},
          {"points_stored", r.points_stored},
          {"points_total", r.points_total},
          {"progress_us", r.progress_us}};
}

}  // namespace cyclopt::web
