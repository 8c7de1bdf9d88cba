#include "server_config.hpp"

#include "cyclopt/service/spec_fields.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <stdexcept>
#include <thread>

namespace cyclopt::server {

namespace {

// One setting, read from a JSON value (file) or converted from a flag's text.
void apply(ServerConfig& c, const std::string& key, const nlohmann::json& v) {
  using namespace service;
  if (key == "database") c.database = string_value(v, key, 4096);
  else if (key == "lcm_url") c.lcm_url = string_value(v, key, 4096);
  else if (key == "workers") c.workers = integer_value(v, key, 1, 256);
  else if (key == "max_job_seconds") c.caps.max_wall_seconds = number_value(v, key, 1e-3, 7 * 86400.0);
  else if (key == "max_job_iterations") c.caps.max_iterations = integer_value(v, key, 1, 1000000000);
  else if (key == "max_job_memory_mb") c.max_job_memory_mb = number_value(v, key, 16.0, 1048576.0);
  else if (key == "max_queued_jobs") c.quota.max_queued_jobs = integer_value(v, key, 1, 1000000);
  else if (key == "max_queued_hours") {
    c.quota.max_queued_seconds = 3600.0 * number_value(v, key, 0.0, 1e6);
    if (c.quota.max_queued_seconds <= 0.0) throw SpecError(key, "must be in (0, 1e6], got 0");
  } else if (key == "progress_hz") c.progress_hz = number_value(v, key, 0.1, 100.0);
  else throw SpecError(key, "unknown setting (database, lcm_url, workers, max_job_seconds, max_job_iterations, "
                            "max_job_memory_mb, max_queued_jobs, max_queued_hours, progress_hz)");
}

}  // namespace

ServerConfig server_config_from_file(const std::string& path, ServerConfig c) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument("--config: cannot read '" + path + "'");
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (!j.is_object()) throw std::invalid_argument(path + ": must hold a JSON object");
  for (const auto& [key, value] : j.items()) apply(c, key, value);
  return c;
}

ServerConfig server_config_from_args(const std::vector<std::string>& args) {
  ServerConfig c;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.rfind("--", 0) != 0 || i + 1 >= args.size()) throw std::invalid_argument(a + ": unknown flag or missing value");
    const std::string value = args[++i];
    if (a == "--config") {
      c = server_config_from_file(value, c);
      continue;
    }
    std::string key = a.substr(2);
    for (char& ch : key)
      if (ch == '-') ch = '_';
    const bool text = key == "database" || key == "lcm_url";
    nlohmann::json v = text ? nlohmann::json(value) : nlohmann::json::parse(value, nullptr, false);
    if (v.is_discarded()) v = value;  // reported as a type error by apply()
    apply(c, key, v);
  }
  return c;
}

int effective_workers(const ServerConfig& c) {
  if (c.workers > 0) return c.workers;
  return std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace cyclopt::server
