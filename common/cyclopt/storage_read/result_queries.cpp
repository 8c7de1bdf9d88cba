#include "cyclopt/storage_read/result_queries.hpp"

#include "cyclopt/records/json_fields.hpp"

#include <stdexcept>

namespace cyclopt::storage {

namespace {

using records::finite_or_null;

// A text cell as valid UTF-8: a damaged or foreign byte sequence becomes U+FFFD, so one bad cell
// cannot make a whole page unprintable (nlohmann::json refuses to dump invalid UTF-8).
std::string utf8(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char c = byte(i);
    // Sequence length and the admissible range of its second byte (RFC 3629, table 3-7).
    std::size_t n = 0;
    unsigned char lo = 0x80, hi = 0xBF;
    if (c < 0x80) n = 1;
    else if (c >= 0xC2 && c <= 0xDF) n = 2;
    else if (c == 0xE0) n = 3, lo = 0xA0;
    else if (c >= 0xE1 && c <= 0xEC) n = 3;
    else if (c == 0xED) n = 3, hi = 0x9F;
    else if (c >= 0xEE && c <= 0xEF) n = 3;
    else if (c == 0xF0) n = 4, lo = 0x90;
    else if (c >= 0xF1 && c <= 0xF3) n = 4;
    else if (c == 0xF4) n = 4, hi = 0x8F;
    bool ok = n > 0 && i + n <= text.size();
    for (std::size_t k = 1; ok && k < n; ++k)
      ok = k == 1 ? byte(i + 1) >= lo && byte(i + 1) <= hi : byte(i + k) >= 0x80 && byte(i + k) <= 0xBF;
    if (ok) {
      out.append(text, i, n);
      i += n;
    } else {
      out += "\xEF\xBF\xBD";
      ++i;
    }
  }
  return out;
}

// A stored JSON document, or a note that the cell is unreadable.
nlohmann::json json_cell(const std::string& text, const char* column) {
  nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded())
    return {{"unreadable", std::string(column) + " is not valid JSON (" + std::to_string(text.size()) + " bytes)"}};
  return j;
}

// Rows of `what` (solutions, events, curves, trajectories) belonging to a job.
int count(ResultReader& store, const std::string& what, std::int64_t job_id) {
  std::lock_guard lock(store.mutex());
  Statement q(store.connection(),
              what == "trajectories"
                  ? "SELECT count(*) FROM trajectories t JOIN solutions s ON s.id = t.solution_id WHERE s.job_id = ?"
                  : "SELECT count(*) FROM " + what + " WHERE job_id = ?");
  q.bind(1, job_id).step();
  return static_cast<int>(q.int64(0));
}

// Runs `sql` (parameters: job id, limit, offset) under the store's lock; one JSON row per result
// row, built by `row`.
template <class RowFn>
nlohmann::json paged_rows(ResultReader& store, const char* sql, std::int64_t job_id, int offset, int limit, RowFn row) {
  std::lock_guard lock(store.mutex());
  Statement q(store.connection(), sql);
  q.bind(1, job_id).bind(2, std::int64_t{limit}).bind(3, std::int64_t{offset});
  nlohmann::json rows = nlohmann::json::array();
  while (q.step()) rows.push_back(row(q));
  return rows;
}

nlohmann::json solution_rows(ResultReader& store, std::int64_t job_id, int offset, int limit) {
  return paged_rows(store,
                    "SELECT curve_index, point_index, parameter, objective, constraint_violation, iterations, status, "
                    "values_json, solved_at FROM solutions WHERE job_id = ? ORDER BY curve_index, point_index "
                    "LIMIT ? OFFSET ?",
                    job_id, offset, limit, [](const Statement& q) {
                      return nlohmann::json{{"curve", q.int64(0)},
                                            {"point", q.int64(1)},
                                            {"parameter", finite_or_null(q.real(2))},
                                            {"objective", finite_or_null(q.real(3))},
                                            {"constraint_violation", finite_or_null(q.real(4))},
                                            {"iterations", q.int64(5)},
                                            {"status", utf8(q.text(6))},
                                            {"values", json_cell(q.text(7), "values_json")},
                                            {"solved_at", q.real(8)}};
                    });
}

nlohmann::json trajectory_rows(ResultReader& store, std::int64_t job_id, int offset, int limit) {
  return paged_rows(store,
                    "SELECT s.curve_index, s.point_index, t.format, t.data FROM trajectories t JOIN solutions s "
                    "ON s.id = t.solution_id WHERE s.job_id = ? ORDER BY s.curve_index, s.point_index "
                    "LIMIT ? OFFSET ?",
                    job_id, offset, limit, [](const Statement& q) {
                      return nlohmann::json{{"curve", q.int64(0)},
                                            {"point", q.int64(1)},
                                            {"format", utf8(q.text(2))},
                                            {"data", q.text(2) == "json" ? json_cell(q.text(3), "data")
                                                                         : nlohmann::json(utf8(q.text(3)))}};
                    });
}

nlohmann::json event_rows(ResultReader& store, std::int64_t job_id, int offset, int limit) {
  return paged_rows(store, "SELECT at, kind, message FROM events WHERE job_id = ? ORDER BY id LIMIT ? OFFSET ?", job_id,
                    offset, limit, [](const Statement& q) {
                      return nlohmann::json{{"at", q.real(0)}, {"kind", utf8(q.text(1))}, {"message", utf8(q.text(2))}};
                    });
}

nlohmann::json curve_rows(ResultReader& store, std::int64_t job_id, int offset, int limit) {
  return paged_rows(store,
                    "SELECT c.curve_index, c.name, c.parameter_name, "
                    "(SELECT count(*) FROM solutions s WHERE s.job_id = c.job_id AND s.curve_index = c.curve_index) "
                    "FROM curves c WHERE c.job_id = ? ORDER BY c.curve_index LIMIT ? OFFSET ?",
                    job_id, offset, limit, [](const Statement& q) {
                      return nlohmann::json{
                          {"curve", q.int64(0)}, {"name", utf8(q.text(1))}, {"parameter_name", utf8(q.text(2))}, {"points", q.int64(3)}};
                    });
}

// What a fleet view names a job by: the spec's "name", and its feet ("foot", "feet", "start_foot":
// a preset's name, a foot spec's "name", else "custom"), comma-separated.
std::string foot_label(const nlohmann::json& foot) {
  if (foot.is_string()) return foot.get<std::string>();
  if (foot.is_object() && foot.contains("name") && foot["name"].is_string()) return foot["name"].get<std::string>();
  return "custom";
}

std::pair<std::string, std::string> job_labels(const std::string& spec_json) {
  const nlohmann::json spec = nlohmann::json::parse(spec_json, nullptr, false);
  if (!spec.is_object()) return {};
  std::string name = spec.contains("name") && spec["name"].is_string() ? spec["name"].get<std::string>() : "";
  std::string feet;
  for (const char* key : {"foot", "start_foot", "feet"}) {
    if (!spec.contains(key)) continue;
    const nlohmann::json& f = spec[key];
    for (const nlohmann::json& one : f.is_array() ? f : nlohmann::json::array({f})) {
      if (!feet.empty()) feet += ',';
      feet += foot_label(one);
    }
  }
  return {utf8(name), utf8(feet)};
}

JobRecord existing_job(ResultReader& store, std::int64_t job_id) {
  std::optional<JobRecord> j = store.job(job_id);
  if (!j) throw std::invalid_argument("job_id: no job " + std::to_string(job_id));
  return *j;
}

}  // namespace

nlohmann::json to_json(const JobRecord& job, bool with_spec) {
  auto opt = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); };
  const auto [name, feet] = job_labels(job.spec_json);
  nlohmann::json j = {{"id", job.id},
                      {"name", name},
                      {"foot", feet},
                      {"request_id", utf8(job.request_id)},
                      {"scene", utf8(job.scene)},
                      {"task", utf8(job.task)},
                      {"state", to_string(job.state)},
                      {"cancel_requested", job.cancel_requested},
                      {"attempts", job.attempts},
                      {"submitted_at", job.submitted_at},
                      {"started_at", opt(job.started_at)},
                      {"finished_at", opt(job.finished_at)},
                      {"points_total", job.points_total ? nlohmann::json(*job.points_total) : nlohmann::json(nullptr)},
                      {"points_stored", job.points_stored},
                      {"points_converged", job.points_converged ? nlohmann::json(*job.points_converged) : nlohmann::json(nullptr)},
                      {"run_seconds", job.run_seconds},
                      {"publish_seconds", job.publish_seconds},
                      {"error", utf8(job.error)},
                      {"program_version", utf8(job.program_version)},
                      {"isa_level", utf8(job.isa_level)},
                      {"build_flags", utf8(job.build_flags)},
                      {"seeds", json_cell(job.seeds_json, "seeds_json")},
                      {"progress_percent", opt(job.progress.percent)},
                      {"phase", utf8(job.progress.phase)},
                      {"eta_seconds", opt(job.progress.eta_seconds)},
                      {"best_objective", opt(job.progress.best_objective)},
                      {"progress_at", opt(job.progress.at)}};
  if (with_spec) {
    j["spec"] = json_cell(job.spec_json, "spec_json");
    j["resolved_spec"] = job.resolved_spec_json.empty() ? nlohmann::json(nullptr)
                                                        : json_cell(job.resolved_spec_json, "resolved_spec_json");
  }
  return j;
}

QueryRequest query_for(std::string what, std::int64_t job_id, std::string state) {
  QueryRequest r;
  r.what = std::move(what);
  r.job_id = job_id;
  r.state = std::move(state);
  return r;
}

QueryPage run_query(ResultReader& store, const QueryRequest& r) {
  if (r.offset < 0) throw std::invalid_argument("offset: must be >= 0, got " + std::to_string(r.offset));
  if (r.limit < 1 || r.limit > 1000)
    throw std::invalid_argument("limit: must be in [1, 1000], got " + std::to_string(r.limit));
  QueryPage page;
  if (r.what == "jobs") {
    std::optional<JobState> state;
    if (!r.state.empty()) {
      state = job_state_from_string(r.state);
      if (!state)
        throw std::invalid_argument("state: '" + r.state + "' is not one of queued, running, done, failed, cancelled");
    }
    page.total = store.count_jobs(state, r.sender);
    for (const JobRecord& j : store.jobs(state, r.offset, r.limit, r.sender)) page.rows.push_back(to_json(j, false));
    return page;
  }
  if (r.what == "job") {
    page.rows.push_back(to_json(existing_job(store, r.job_id), true));
    page.total = 1;
    if (r.offset > 0) page.rows = nlohmann::json::array();
    return page;
  }
  if (r.what != "solutions" && r.what != "events" && r.what != "curves" && r.what != "trajectories")
    throw std::invalid_argument("what: '" + r.what +
                                "' is not one of jobs, job, solutions, events, curves, trajectories");
  existing_job(store, r.job_id);
  page.total = count(store, r.what, r.job_id);
  if (r.what == "solutions")
    page.rows = solution_rows(store, r.job_id, r.offset, r.limit);
  else if (r.what == "events")
    page.rows = event_rows(store, r.job_id, r.offset, r.limit);
  else if (r.what == "curves")
    page.rows = curve_rows(store, r.job_id, r.offset, r.limit);
  else
    page.rows = trajectory_rows(store, r.job_id, r.offset, r.limit);
  return page;
}

}  // namespace cyclopt::storage
