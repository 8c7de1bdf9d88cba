#include "fleet_table.hpp"

#include "progress_line.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <functional>

namespace cyclopt::client {

namespace {

double number_or_nan(const nlohmann::json& row, const char* key) {
  const auto it = row.find(key);
  return it != row.end() && it->is_number() ? it->get<double>() : FleetJob::kNaN;
}

std::string text_or_empty(const nlohmann::json& row, const char* key) {
  const auto it = row.find(key);
  return it != row.end() && it->is_string() ? it->get<std::string>() : "";
}

std::string shortened(const std::string& text, std::size_t max) {
  return text.size() <= max ? text : text.substr(0, max - 1) + "~";
}

struct Column {
  const char* header;
  bool kept;                                          // never dropped
  std::size_t max;                                    // cells are cut to this many characters
  std::function<std::string(const FleetJob&)> cell;
};

std::string progress_cell(const FleetJob& j) {
  if (j.state == "queued") return "-";
  return percent_text(j.percent, j.percent_lower_bound);
}

std::string best_cell(const FleetJob& j) {
  if (!std::isfinite(j.best_objective)) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.5g", j.best_objective);
  return buf;
}

std::string eta_cell(const FleetJob& j) { return j.state == "running" ? duration_text(j.eta_seconds) : "-"; }
std::string run_cell(const FleetJob& j) { return std::isfinite(j.run_seconds) && j.state != "queued" ? duration_text(j.run_seconds) : "-"; }
std::string or_dash(const std::string& s) { return s.empty() ? "-" : s; }

// "17:03" if `t` is on the local day of `day`, else the full local_iso_minutes.
std::string same_day_minutes(double t, double day) {
  const std::string full = local_iso_minutes(t), other = local_iso_minutes(day);
  return full.size() == 16 && other.substr(0, 10) == full.substr(0, 10) ? full.substr(11) : full;
}

std::vector<Column> columns(FleetView view) {
  const Column id{"ID", true, 10, [](const FleetJob& j) { return std::to_string(j.id); }};
  const Column name{"NAME", false, 12, [](const FleetJob& j) { return or_dash(j.name); }};
  const Column kind{"KIND", false, 16, [](const FleetJob& j) { return j.kind; }};
  const Column foot{"FOOT", false, 17, [](const FleetJob& j) { return or_dash(j.foot); }};
  const Column state{"STATE", true, 10, [](const FleetJob& j) { return j.state; }};
  const Column progress{"PROG", true, 8, progress_cell};
  const Column best{"BEST", true, 11, best_cell};
  const Column run{"RUN", false, 8, run_cell};
  const Column started{"STARTED", false, 16, [](const FleetJob& j) { return local_iso_minutes(j.started_at); }};
  if (view == FleetView::list)  // started and finished as the time of day when on the day submitted
    return {id, name, kind, foot, state, progress, best, run,
            {"SUBMITTED", false, 16, [](const FleetJob& j) { return local_iso_minutes(j.submitted_at); }},
            {"STARTED", false, 16, [](const FleetJob& j) { return same_day_minutes(j.started_at, j.submitted_at); }},
            {"ENDED", false, 16, [](const FleetJob& j) { return same_day_minutes(j.finished_at, j.submitted_at); }}};
  return {id, state, progress, best, {"ETA", false, 8, eta_cell}, run, name, kind, foot, started,
          {"PHASE", false, 200, [](const FleetJob& j) { return or_dash(j.phase); }}};
}

}  // namespace

FleetJob fleet_job(const nlohmann::json& row) {
  FleetJob j;
  j.id = row.value("id", std::int64_t{0});
  j.name = text_or_empty(row, "name");
  j.kind = text_or_empty(row, "task");
  j.foot = text_or_empty(row, "foot");
  j.state = text_or_empty(row, "state");
  j.phase = text_or_empty(row, "phase");
  j.percent = number_or_nan(row, "progress_percent");
  j.eta_seconds = number_or_nan(row, "eta_seconds");
  j.best_objective = number_or_nan(row, "best_objective");
  j.run_seconds = number_or_nan(row, "run_seconds");
  j.submitted_at = number_or_nan(row, "submitted_at");
  j.started_at = number_or_nan(row, "started_at");
  j.finished_at = number_or_nan(row, "finished_at");
  if (j.state == "running" && !std::isfinite(j.eta_seconds)) j.percent_lower_bound = std::isfinite(j.percent);
  return j;
}

void apply_progress(FleetJob& j, const cyclopt_lcm::job_progress_t& p) {
  j.percent = p.percent;
  j.percent_lower_bound = p.percent_is_lower_bound;
  j.eta_seconds = p.eta_seconds;
  if (std::isfinite(p.best_objective)) j.best_objective = p.best_objective;
  j.run_seconds = p.elapsed_seconds;
  j.phase = p.phase;
  if (j.state == "queued") j.state = "running";
}

std::vector<std::string> fleet_table(const std::vector<FleetJob>& jobs, FleetView view, std::size_t width) {
  std::vector<Column> cols = columns(view);
  std::vector<std::vector<std::string>> cells(jobs.size() + 1);
  std::vector<std::size_t> widths;
  for (const Column& c : cols) {
    std::size_t w = std::string(c.header).size();
    cells[0].push_back(c.header);
    for (std::size_t r = 0; r < jobs.size(); ++r) {
      cells[r + 1].push_back(shortened(c.cell(jobs[r]), c.max));
      w = std::max(w, cells[r + 1].back().size());
    }
    widths.push_back(w);
  }
  constexpr std::size_t kGap = 2;
  const auto total = [&](const std::vector<bool>& shown) {
    std::size_t t = 0, n = 0;
    for (std::size_t c = 0; c < cols.size(); ++c)
      if (shown[c]) t += widths[c], ++n;
    return n > 0 ? t + kGap * (n - 1) : 0;
  };
  std::vector<bool> shown(cols.size(), true);
  // The last column of top (PHASE) is cut to the room left before any column is dropped.
  if (view == FleetView::top && total(shown) > width) {
    shown.back() = false;
    const std::size_t room = total(shown) + kGap < width ? width - total(shown) - kGap : 0;
    if (room >= 8) {
      widths.back() = std::min(widths.back(), room);
      shown.back() = true;
    }
  }
  for (std::size_t c = cols.size(); c-- > 0 && total(shown) > width;)
    if (!cols[c].kept) shown[c] = false;
  std::vector<std::string> lines;
  for (const std::vector<std::string>& row : cells) {
    std::string line;
    for (std::size_t c = 0; c < cols.size(); ++c) {
      if (!shown[c]) continue;
      if (!line.empty()) line.append(kGap, ' ');
      std::string cell = row[c];
      if (cell.size() > widths[c]) cell = cell.substr(0, widths[c] - 1) + "~";
      line += cell + std::string(widths[c] - cell.size(), ' ');
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    if (line.size() > width) line.resize(width);
    lines.push_back(line);
  }
  return lines;
}

std::string local_iso_minutes(double unix_seconds) {
  const std::string t = local_iso_time(unix_seconds);
  return t.size() > 16 ? t.substr(0, 16) : t;
}

std::string local_iso_time(double unix_seconds) {
  if (!std::isfinite(unix_seconds)) return "-";
  const std::time_t t = static_cast<std::time_t>(unix_seconds);
  std::tm tm{};
  localtime_r(&t, &tm);
  char buf[40];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S", &tm);
  const long minutes = tm.tm_gmtoff / 60;  // the offset as ISO 8601 extended: +01:00
  char zone[48];
  std::snprintf(zone, sizeof zone, "%c%02ld:%02ld", minutes < 0 ? '-' : '+', std::labs(minutes) / 60, std::labs(minutes) % 60);
  return std::string(buf) + zone;
}

}  // namespace cyclopt::client
