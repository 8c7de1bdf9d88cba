#include "dashboard_server.hpp"

#include "job_rows_cache.hpp"
#include "message_page.hpp"
#include "script_hash.hpp"
#include "service_client.hpp"
#include "store_rows.hpp"
#include "web_assets.hpp"
#include "web_request.hpp"
#include "web_token.hpp"

#include "cyclopt/plot/html_report.hpp"
#include "cyclopt/plot/job_report.hpp"
#include "cyclopt/records/json_fields.hpp"
#include "cyclopt/storage_read/result_queries.hpp"
#include "cyclopt/storage_read/solution_point.hpp"

#include <httplib.h>

#include <cstdio>
#include <limits>
#include <map>
#include <mutex>
#include <set>

namespace cyclopt::web {

namespace {

constexpr const char* kTokenCookie = "cyclopt_token";
// The page's own files only; a report's figures are inline SVG and its style inline.
constexpr const char* kPagePolicy =
    "default-src 'self'; script-src 'self'; style-src 'self' 'unsafe-inline'; img-src 'self' data:; "
    "object-src 'none'; base-uri 'none'; frame-ancestors 'self'; form-action 'self'";
constexpr auto kKeepAlive = std::chrono::seconds(15);  // an SSE comment line this often keeps proxies open

// Who asks: under authentication the key of the token; all_jobs when it may read every job.
struct Viewer {
  const wire::AuthKey* key = nullptr;
  bool all_jobs = true;
};

using records::finite_or_null;

nlohmann::json progress_json(const cyclopt_lcm::job_progress_t& p) {
  return {{"timestamp_us", p.timestamp_us},       {"iteration", p.iteration},
          {"objective", finite_or_null(p.objective)},     {"constraint_violation", finite_or_null(p.constraint_violation)},
          {"parameter", finite_or_null(p.parameter)},     {"curve", p.curve_id},
          {"points_done", p.points_done},         {"points_total", p.points_total},
          {"percent", finite_or_null(p.percent)},         {"percent_lower_bound", p.percent_is_lower_bound},
          {"eta_seconds", finite_or_null(p.eta_seconds)}, {"phase", p.phase},
          {"phase_done", p.phase_done},           {"phase_total", p.phase_total},
          {"best_objective", finite_or_null(p.best_objective)}, {"elapsed_seconds", finite_or_null(p.elapsed_seconds)},
          {"message", p.message}};
}

// What the chart needs of a stored point (its values stay in the database; export has them). Only
// converged points are drawn: a failed solve is never shown as a result.
nlohmann::json point_json(const nlohmann::json& solution) {
  return {{"curve", solution["curve"]},         {"point", solution["point"]},
          {"parameter", solution["parameter"]}, {"objective", solution["objective"]},
          {"status", solution["status"]},
          {"converged", storage::is_converged_status(solution.value("status", std::string()))}};
}

nlohmann::json event_json(const nlohmann::json& event) {
  const double at = event.value("at", std::numeric_limits<double>::quiet_NaN());
  return {{"at", client::local_iso_time(at)}, {"kind", event["kind"]}, {"message", event["message"]}};
}

std::string sse(const char* event, const nlohmann::json& data) {
  // JSON text holds no raw newline: one data line per event.
  return std::string("event: ") + event + "\ndata: " + data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n\n";
}

// An event stream's provider runs on httplib's thread after the route returned, outside the
// route's try: whatever it throws closes that stream (the page reconnects), never the program.
template <class Provider>
auto guarded(Provider provider) {
  return [provider = std::move(provider)](std::size_t offset, httplib::DataSink& sink) {
    try {
      return provider(offset, sink);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "cyclopt-web: an event stream closed: %s\n", e.what());
      return false;
    }
  };
}

void error_page(httplib::Response& res, int status, const std::string& message) {
  res.status = status;
  res.set_header("Content-Security-Policy", kPagePolicy);
  res.set_content(message_page(message), "text/html; charset=utf-8");
}

}  // namespace

struct DashboardServer::Impl {
  Impl(const DashboardConfig& c, storage::ResultReader& s, LiveFleet& f, std::optional<wire::KeyRing> k)
      : config(c), store(s), fleet(f), keys(std::move(k)) {}
  DashboardConfig config;
  storage::ResultReader& store;
  LiveFleet& fleet;
  std::optional<wire::KeyRing> keys;
  httplib::Server http;
  std::mutex reports_mutex;
  std::map<std::int64_t, std::string> final_reports;
  JobRowsCache job_rows{store, {{"curves", [](const nlohmann::json& r) { return r; }}, {"solutions", point_json}, {"events", event_json}}};

  std::optional<Viewer> viewer(const httplib::Request& req) const {
    if (!keys) return Viewer{};
    std::string problem;
    const wire::AuthKey* key = check_token(*keys, cookie_value(req.get_header_value("Cookie"), kTokenCookie),
                                           wire::unix_now_us() / 1000000, problem);
    if (!key) return std::nullopt;
    return Viewer{key, key->admin || config.auth_reads_any};
  }

  // The ids of the jobs the viewer submitted (the queue's sender is the submitting key).
  std::set<std::int64_t> own_jobs(const Viewer& v) {
    storage::QueryRequest request = storage::query_for("jobs");
    request.sender = v.key->id;
    std::set<std::int64_t> ids;
    for (const nlohmann::json& row : all_rows(store, request)) ids.insert(row["id"].get<std::int64_t>());
    return ids;
  }

  bool may_read(const Viewer& v, std::int64_t id) { return v.all_jobs || own_jobs(v).count(id) > 0; }

  // The viewer and the job of a /…/ID/… route; answers the request itself (401, 404) when not.
  std::optional<std::pair<Viewer, std::int64_t>> job_request(const httplib::Request& req, httplib::Response& res) {
    const std::optional<Viewer> v = viewer(req);
    if (!v) {
      error_page(res, 401, "Log in first: open /login?token=TOKEN (cyclopt-web token --key-file YOUR_KEY_FILE).");
      return std::nullopt;
    }
    const std::optional<std::int64_t> id = job_id_of(req.matches[1]);
    if (!id || !store.job(*id) || !may_read(*v, *id)) {
      error_page(res, 404, "No job " + std::string(req.matches[1]) + " that this key may read.");
      return std::nullopt;
    }
    return std::pair{*v, *id};
  }

  nlohmann::json rows_of(const std::string& what, std::int64_t id, int offset) {
    storage::QueryRequest request = storage::query_for(what, id);
    request.offset = offset;
    return all_rows(store, request);
  }

  // The job as `cyclopt export` writes it: the job row with its spec and every part (kJobParts).
  nlohmann::json job_document(std::int64_t id) {
    nlohmann::json doc = rows_of("job", id, 0).at(0);
    for (const char* what : storage::kJobParts) doc[what] = rows_of(what, id, 0);
    return doc;
  }

  void serve_page(const httplib::Request& req, httplib::Response& res) {
    if (!viewer(req)) return error_page(res, 401, "Log in first: open /login?token=TOKEN (cyclopt-web token --key-file YOUR_KEY_FILE).");
    const Asset& page = assets().front();  // "/"
    res.set_header("Content-Security-Policy", kPagePolicy);
    res.set_header("Cache-Control", "no-store");
    res.set_content(page.bytes.data(), page.bytes.size(), page.content_type);
  }

  void login(const httplib::Request& req, httplib::Response& res) {
    if (!keys) return res.set_redirect("/", 303);
    const std::string token = req.get_param_value("token");
    std::string problem;
    if (!check_token(*keys, token, wire::unix_now_us() / 1000000, problem))
      return error_page(res, 401, "Login refused: " + problem + ".");
    res.set_header("Set-Cookie", std::string(kTokenCookie) + "=" + token + "; Path=/; HttpOnly; SameSite=Strict");
    res.set_redirect("/", 303);
  }

  void fleet_events(const httplib::Request& req, httplib::Response& res) {
    const std::optional<Viewer> v = viewer(req);
    if (!v) return error_page(res, 401, "Log in first.");
    res.set_header("Cache-Control", "no-store");
    res.set_chunked_content_provider("text/event-stream", guarded([this, v = *v](std::size_t, httplib::DataSink& sink) {
      std::uint64_t seq = 0;
      auto last_write = std::chrono::steady_clock::now();
      while (!fleet.stopped()) {
        LiveFleet::Changes changes = fleet.rows_since(seq);
        const bool first = seq == 0;
        seq = changes.seq;
        nlohmann::json rows = nlohmann::json::array();
        const std::set<std::int64_t> own = v.all_jobs ? std::set<std::int64_t>{} : own_jobs(v);
        for (const FleetRow& r : changes.rows)
          if (v.all_jobs || own.count(r.job.id)) rows.push_back(to_json(r));
        std::string text;
        if (first || !rows.empty()) text = sse("rows", rows);
        else if (std::chrono::steady_clock::now() - last_write > kKeepAlive) text = ": keep-alive\n\n";
        if (!text.empty()) {
          if (!sink.write(text.data(), text.size())) return false;
          last_write = std::chrono::steady_clock::now();
        }
        fleet.wait(seq, kKeepAlive);
      }
      sink.done();
      return true;
    }));
  }

  void job_events(const httplib::Request& req, httplib::Response& res) {
    const auto asked = job_request(req, res);
    if (!asked) return;
    const std::int64_t id = asked->second;
    res.set_header("Cache-Control", "no-store");
    res.set_chunked_content_provider("text/event-stream", guarded([this, id](std::size_t, httplib::DataSink& sink) {
      std::uint64_t global = 0, seen = 0;  // the fleet's newest change, the job's last one sent
      std::size_t points = 0, events = 0, curves = 0;
      std::string row_text;
      std::int64_t progress_us = -1;
      auto last_write = std::chrono::steady_clock::now();
      const auto send = [&](const char* event, const nlohmann::json& data) {
        last_write = std::chrono::steady_clock::now();
        const std::string text = sse(event, data);
        return sink.write(text.data(), text.size());
      };
      // Rows of `what` stored after the `count` sent; sent as `event`.
      const auto send_new = [&](const char* what, const char* event, std::size_t& count, const std::string& mark) {
        const nlohmann::json fresh = job_rows.rows_after(id, what, count, mark);
        count += fresh.size();
        return fresh.empty() || send(event, fresh);
      };
      while (!fleet.stopped()) {
        const LiveFleet::JobView view = fleet.job(id);
        if (seen == 0 || view.seq > seen) {
          seen = std::max<std::uint64_t>(view.seq, 1);
          const nlohmann::json row = view.row ? to_json(*view.row) : nlohmann::json(nullptr);
          std::string text = row.dump();
          if (text != row_text && !send("job", row)) return false;
          row_text = std::move(text);
          // The database is read only when the row or the live message says something new is there.
          const std::string state = row.is_null() ? "" : row["state"].dump();
          const std::string points_mark = state + std::to_string(row.is_null() ? 0 : row.value("points_stored", 0)) + "/" +
                                          std::to_string(view.progress ? view.progress->points_done : 0);
          const std::string events_mark = row.is_null() ? "" : state + row["phase"].dump() + row["cancel_requested"].dump();
          if (!send_new("curves", "curves", curves, points_mark) || !send_new("solutions", "points", points, points_mark) ||
              !send_new("events", "events", events, events_mark))
            return false;
          if (view.progress && view.progress->timestamp_us != progress_us) {
            progress_us = view.progress->timestamp_us;
            if (!send("progress", progress_json(*view.progress))) return false;
          }
        } else if (std::chrono::steady_clock::now() - last_write > kKeepAlive) {
          const std::string comment = ": keep-alive\n\n";
          if (!sink.write(comment.data(), comment.size())) return false;
          last_write = std::chrono::steady_clock::now();
        }
        global = fleet.wait(global, kKeepAlive);
      }
      sink.done();
      return true;
    }));
  }

  void report(const httplib::Request& req, httplib::Response& res) {
    const auto asked = job_request(req, res);
    if (!asked) return;
    // No script but the report's own (its animations run only while on screen).
    static const std::string policy = "default-src 'none'; script-src " + script_hash_source(plot::report_script()) +
                                      "; style-src 'unsafe-inline'; img-src data:; frame-ancestors 'self'";
    res.set_header("Content-Security-Policy", policy);
    res.set_content(report_html(asked->second), "text/html; charset=utf-8");
  }

  // A report takes a second or more to draw: one at a time, and a finished job's (which no longer
  // changes) drawn once for every page that shows it.
  std::string report_html(std::int64_t id) {
    std::lock_guard lock(reports_mutex);
    if (const auto it = final_reports.find(id); it != final_reports.end()) return it->second;
    const std::optional<storage::JobRecord> job = store.job(id);
    const bool final = job && storage::is_final(job->state);
    std::string html = plot::to_html(plot::job_report(job_document(id)));
    if (final) final_reports[id] = html;
    return html;
  }

  void export_job(const httplib::Request& req, httplib::Response& res) {
    const auto asked = job_request(req, res);
    if (!asked) return;
    res.set_header("Content-Disposition", "attachment; filename=\"job" + std::to_string(asked->second) + ".json\"");
    res.set_content(job_document(asked->second).dump(2), "application/json");
  }

  void cancel(const httplib::Request& req, httplib::Response& res) {
    if (!req.has_header(kActionHeader) || !same_origin(req.get_header_value("Origin"), req.get_header_value("Host")))
      return error_page(res, 403, "Cancel only from the dashboard's own page.");
    const auto asked = job_request(req, res);
    if (!asked) return;
    // A connection of its own: the listening one is pumped by the progress thread.
    const std::string url = wire::resolved_lcm_url(config.lcm_url);
    lcm::LCM lcm(url);
    if (!lcm.good()) return error_page(res, 503, "LCM is not available at " + url + ".");
    client::ServiceClient client(lcm, url, asked->first.key ? std::optional(*asked->first.key) : std::nullopt);
    nlohmann::json answer;
    try {
      const auto ack = client.cancel(asked->second, 5.0);
      if (!ack) answer = {{"ok", false}, {"message", "no answer from cycloptd in 5 s"}};
      else if (!ack->accepted) answer = {{"ok", false}, {"message", ack->problem}};
      else answer = {{"ok", true}, {"message", ack->state == "cancelled" ? "cancelled" : "cancel requested"}};
    } catch (const client::SignatureRejected& e) {
      answer = {{"ok", false}, {"message", e.what()}};
    }
    res.set_content(answer.dump(), "application/json");
  }
};

DashboardServer::DashboardServer(const DashboardConfig& config, storage::ResultReader& store, LiveFleet& fleet,
                                 std::optional<wire::KeyRing> keys)
    : impl_(std::make_unique<Impl>(config, store, fleet, std::move(keys))) {
  Impl& s = *impl_;
  // Each open page holds one connection (its event stream): room for many pages.
  s.http.new_task_queue = [] { return new httplib::ThreadPool(64); };
  // cpp-httplib 0.11 watches an idle kept-alive connection by polling it every 10 ms until its
  // keep-alive timeout (default 5 s): ten freshly opened pages cost more CPU that way than their
  // event streams. A page's few requests come at load and at the job's end; 1 s is plenty.
  s.http.set_keep_alive_timeout(1);
  s.http.set_default_headers({{"X-Content-Type-Options", "nosniff"}, {"Referrer-Policy", "no-referrer"}});
  // Debian's cpp-httplib compresses every text response the browser accepts so, brotli at its
  // slowest quality: a report of a few MB cost seconds of CPU per request. Pages come over loopback
  // or a tunnel; they go uncompressed. (The Request is httplib's own, writable, object.)
  s.http.set_pre_routing_handler([](const httplib::Request& req, httplib::Response&) {
    const_cast<httplib::Request&>(req).headers.erase("Accept-Encoding");
    return httplib::Server::HandlerResponse::Unhandled;
  });
  const auto route = [&s](void (Impl::*handler)(const httplib::Request&, httplib::Response&)) {
    return [&s, handler](const httplib::Request& req, httplib::Response& res) {
      try {
        (s.*handler)(req, res);
      } catch (const std::exception& e) {
        error_page(res, 500, std::string("cyclopt-web: ") + e.what());
      }
    };
  };
  s.http.Get("/", route(&Impl::serve_page));
  s.http.Get(R"(/job/(\d+))", route(&Impl::serve_page));
  s.http.Get("/login", route(&Impl::login));
  s.http.Get("/api/fleet/events", route(&Impl::fleet_events));
  s.http.Get(R"(/api/job/(\d+)/events)", route(&Impl::job_events));
  s.http.Get(R"(/job/(\d+)/report)", route(&Impl::report));
  s.http.Get(R"(/job/(\d+)/export\.json)", route(&Impl::export_job));
  s.http.Post(R"(/api/job/(\d+)/cancel)", route(&Impl::cancel));
  for (const Asset& a : assets())
    if (std::string_view(a.url) != "/")
      s.http.Get(a.url, [&a](const httplib::Request&, httplib::Response& res) {
        res.set_header("Cache-Control", "max-age=3600");
        res.set_content(a.bytes.data(), a.bytes.size(), a.content_type);
      });
}

DashboardServer::~DashboardServer() = default;

bool DashboardServer::listen() { return impl_->http.listen(impl_->config.host, impl_->config.port); }

void DashboardServer::stop() { impl_->http.stop(); }

}  // namespace cyclopt::web
