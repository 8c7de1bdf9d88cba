#include "unit_spool.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace cyclopt::server::remote {

namespace fs = std::filesystem;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// JSON has no NaN: nlohmann writes it as null, and null reads back as NaN.
double number_or_nan(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  return it == j.end() || it->is_null() ? kNaN : it->get<double>();
}

std::optional<std::string> read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

nlohmann::json read_json(const fs::path& path) {
  const auto text = read_text(path);
  if (!text) throw std::runtime_error(path.string() + ": cannot read");
  nlohmann::json j = nlohmann::json::parse(*text, nullptr, false);
  if (j.is_discarded()) throw std::runtime_error(path.string() + ": not valid JSON");
  return j;
}

std::string event_name(int sequence) {
  char name[32];
  std::snprintf(name, sizeof name, "%08d.json", sequence);
  return name;
}

}  // namespace

void write_file_atomically(const fs::path& path, const std::string& text) {
  fs::path tmp = path;
  tmp += ".tmp" + std::to_string(::getpid());  // same directory: rename() is atomic
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error(tmp.string() + ": cannot create");
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n <= 0) {
      ::close(fd);
      throw std::runtime_error(tmp.string() + ": write failed");
    }
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0) throw std::runtime_error(tmp.string() + ": fsync failed");
  fs::rename(tmp, path);
}

nlohmann::json point_to_json(const storage::SolutionPoint& p) {
  nlohmann::json j{{"curve", p.key.curve_index},
                   {"point", p.key.point_index},
                   {"parameter", p.parameter},
                   {"objective", p.objective},
                   {"constraint_violation", p.constraint_violation},
                   {"iterations", p.iterations},
                   {"status", p.status},
                   {"required", p.required},
                   {"values", p.values()}};
  if (p.trajectory()) j["trajectory"] = *p.trajectory();
  return j;
}

storage::SolutionPoint point_from_json(const nlohmann::json& j) {
  storage::SolutionPoint p;
  p.key = {j.at("curve").get<int>(), j.at("point").get<int>()};
  p.parameter = number_or_nan(j, "parameter");
  p.objective = number_or_nan(j, "objective");
  p.constraint_violation = number_or_nan(j, "constraint_violation");
  p.iterations = j.at("iterations").get<int>();
  p.status = j.at("status").get<std::string>();
  p.required = j.at("required").get<bool>();
  p.carry(j.at("values"), j.contains("trajectory") ? std::optional<nlohmann::json>(j.at("trajectory")) : std::nullopt);
  return p;
}

service::StopReason stop_reason_from_string(const std::string& s) {
  using service::StopReason;
  for (StopReason r : {StopReason::none, StopReason::cancelled, StopReason::time_limit, StopReason::iteration_limit,
                       StopReason::shutdown})
    if (s == service::to_string(r)) return r;
  throw std::runtime_error("unknown stop reason '" + s + "'");
}

UnitSpool::UnitSpool(fs::path dir) : dir_(std::move(dir)) {}

void UnitSpool::create() const { fs::create_directories(dir_ / "events"); }

void UnitSpool::write_spec(const UnitSpec& s) const {
  const nlohmann::json j{{"job_id", s.job_id},
                         {"task", s.task},
                         {"spec", s.spec_json},
                         {"max_wall_seconds", s.limits.max_wall_seconds},
                         {"max_iterations", s.limits.max_iterations},
                         {"run_seconds_before", s.run_seconds_before},
                         {"submitted_at", s.submitted_at},
                         {"unit", s.unit ? nlohmann::json{{"id", s.unit->id}, {"index", s.unit->index}} : nlohmann::json()}};
  write_file_atomically(dir_ / "unit.json", j.dump());
}

UnitSpec UnitSpool::read_spec() const {
  const fs::path path = dir_ / "unit.json";
  const nlohmann::json j = read_json(path);
  try {
    UnitSpec s;
    s.job_id = j.at("job_id").get<std::int64_t>();
    s.task = j.at("task").get<std::string>();
    s.spec_json = j.at("spec").get<std::string>();
    s.limits.max_wall_seconds = j.at("max_wall_seconds").get<double>();
    s.limits.max_iterations = j.at("max_iterations").get<int>();
    s.run_seconds_before = j.at("run_seconds_before").get<double>();
    s.submitted_at = j.at("submitted_at").get<double>();
    if (const nlohmann::json& u = j.at("unit"); !u.is_null())
      s.unit = service::WorkUnit{u.at("id").get<std::string>(), u.at("index").get<int>()};
    return s;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
}

void UnitSpool::write_stored_keys(const std::set<storage::PointKey>& keys) const {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& k : keys) j.push_back({k.curve_index, k.point_index});
  write_file_atomically(dir_ / "stored_keys.json", j.dump());
}

std::set<storage::PointKey> UnitSpool::read_stored_keys() const {
  const fs::path path = dir_ / "stored_keys.json";
  std::set<storage::PointKey> keys;
  if (!fs::exists(path)) return keys;
  try {
    for (const auto& k : read_json(path)) keys.insert({k.at(0).get<int>(), k.at(1).get<int>()});
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
  return keys;
}

void UnitSpool::write_checkpoints(const std::map<std::string, std::string>& checkpoints) const {
  write_file_atomically(dir_ / "checkpoints.json", nlohmann::json(checkpoints).dump());
}

std::map<std::string, std::string> UnitSpool::read_checkpoints() const {
  const fs::path path = dir_ / "checkpoints.json";
  if (!fs::exists(path)) return {};
  try {
    return read_json(path).get<std::map<std::string, std::string>>();
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
}

void UnitSpool::write_event(int sequence, const UnitEvent& e) const {
  nlohmann::json j;
  switch (e.type) {
    case UnitEvent::Type::announce: j = {{"type", "announce"}, {"points_total", e.points_total}}; break;
    case UnitEvent::Type::curve:
      j = {{"type", "curve"}, {"curve", e.curve_index}, {"name", e.curve_name}, {"parameter_name", e.parameter_name}};
      break;
    case UnitEvent::Type::point: j = {{"type", "point"}, {"point", point_to_json(e.point)}}; break;
    case UnitEvent::Type::checkpoint:
      j = {{"type", "checkpoint"}, {"key", e.checkpoint_key}, {"value", e.checkpoint_value}};
      break;
  }
  write_file_atomically(dir_ / "events" / event_name(sequence), j.dump());
}

int UnitSpool::next_sequence() const {
  int n = 0;
  while (fs::exists(dir_ / "events" / event_name(n))) ++n;
  return n;
}

std::vector<std::pair<int, UnitEvent>> UnitSpool::read_events(int from) const {
  std::vector<std::pair<int, UnitEvent>> events;
  for (int n = from;; ++n) {
    const fs::path path = dir_ / "events" / event_name(n);
    if (!fs::exists(path)) break;
    const nlohmann::json j = read_json(path);
    UnitEvent e;
    try {
      const std::string type = j.at("type").get<std::string>();
      if (type == "announce") {
        e.type = UnitEvent::Type::announce;
        e.points_total = j.at("points_total").get<int>();
      } else if (type == "curve") {
        e.type = UnitEvent::Type::curve;
        e.curve_index = j.at("curve").get<int>();
        e.curve_name = j.at("name").get<std::string>();
        e.parameter_name = j.at("parameter_name").get<std::string>();
      } else if (type == "point") {
        e.type = UnitEvent::Type::point;
        e.point = point_from_json(j.at("point"));
      } else if (type == "checkpoint") {
        e.type = UnitEvent::Type::checkpoint;
        e.checkpoint_key = j.at("key").get<std::string>();
        e.checkpoint_value = j.at("value").get<std::string>();
      } else {
        throw std::runtime_error(path.string() + ": unknown event type '" + type + "'");
      }
    } catch (const nlohmann::json::exception& ex) {
      throw std::runtime_error(path.string() + ": " + ex.what());
    }
    events.emplace_back(n, std::move(e));
  }
  return events;
}

void UnitSpool::write_progress(const service::ProgressReport& r) const {
  const nlohmann::json j{{"iteration", r.iteration},
                         {"objective", r.objective},
                         {"constraint_violation", r.constraint_violation},
                         {"parameter", r.parameter},
                         {"curve_id", r.curve_id},
                         {"points_done", r.points_done},
                         {"points_total", r.points_total},
                         {"message", r.message},
                         {"phase", r.phase},
                         {"phase_done", r.phase_done},
                         {"phase_total", r.phase_total},
                         {"best_objective", r.best_objective},
                         {"eta_seconds", r.eta_seconds}};
  write_file_atomically(dir_ / "progress.json", j.dump());
}

std::optional<service::ProgressReport> UnitSpool::read_progress() const {
  const fs::path path = dir_ / "progress.json";
  if (!fs::exists(path)) return std::nullopt;
  try {
    const nlohmann::json j = read_json(path);
    service::ProgressReport r;
    r.iteration = j.at("iteration").get<int>();
    r.objective = number_or_nan(j, "objective");
    r.constraint_violation = number_or_nan(j, "constraint_violation");
    r.parameter = number_or_nan(j, "parameter");
    r.curve_id = j.at("curve_id").get<int>();
    r.points_done = j.at("points_done").get<int>();
    r.points_total = j.at("points_total").get<int>();
    r.message = j.at("message").get<std::string>();
    r.phase = j.at("phase").get<std::string>();
    r.phase_done = j.at("phase_done").get<int>();
    r.phase_total = j.at("phase_total").get<int>();
    r.best_objective = number_or_nan(j, "best_objective");
    r.eta_seconds = number_or_nan(j, "eta_seconds");
    return r;
  } catch (const std::exception&) {
    return std::nullopt;  // progress is advisory: a malformed report is skipped
  }
}

void UnitSpool::write_started(double unix_seconds) const {
  write_file_atomically(dir_ / "started.json", nlohmann::json{{"started_at", unix_seconds}}.dump());
}

std::optional<double> UnitSpool::read_started() const {
  if (!fs::exists(dir_ / "started.json")) return std::nullopt;
  return read_json(dir_ / "started.json").at("started_at").get<double>();
}

void UnitSpool::request_cancel() const { write_file_atomically(dir_ / "cancel", "cancel\n"); }

bool UnitSpool::cancel_requested() const { return fs::exists(dir_ / "cancel"); }

void UnitSpool::write_outcome(const UnitOutcome& o) const {
  write_file_atomically(dir_ / "done.json",
                        nlohmann::json{{"error", o.error}, {"stop", service::to_string(o.stop)}}.dump());
}

std::optional<UnitOutcome> UnitSpool::read_outcome() const {
  const fs::path path = dir_ / "done.json";
  if (!fs::exists(path)) return std::nullopt;
  const nlohmann::json j = read_json(path);
  try {
    return UnitOutcome{j.at("error").get<std::string>(), stop_reason_from_string(j.at("stop").get<std::string>())};
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
}

void UnitSpool::clear_run_state() const {
  for (const char* name : {"done.json", "cancel", "progress.json", "started.json"}) fs::remove(dir_ / name);
}

}  // namespace cyclopt::server::remote
