#include "server_config.hpp"

#include "cyclopt/service/spec_fields.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <stdexcept>
#include <thread>

namespace cyclopt::server {

namespace {

// One key of the "slurm" object.
void apply_slurm(remote::SlurmOptions& o, const std::string& key, const nlohmann::json& v) {
  using namespace service;
  const std::string field = "slurm." + key;
  if (key == "spool") o.spool = string_value(v, field, 4096);
  else if (key == "worker") o.worker = string_value(v, field, 4096);
  else if (key == "partition") o.partition = string_value(v, field, 256);
  else if (key == "account") o.account = string_value(v, field, 256);
  else if (key == "cpus_per_unit") o.cpus_per_unit = integer_value(v, field, 1, 1024);
  else if (key == "time_limit_minutes") o.time_limit_minutes = integer_value(v, field, 0, 525600);
  else if (key == "max_submissions") o.max_submissions = integer_value(v, field, 1, 100);
  else if (key == "poll_seconds") o.poll_seconds = number_value(v, field, 0.05, 60.0);
  else
    throw SpecError(field, "unknown setting (spool, worker, partition, account, cpus_per_unit, time_limit_minutes, "
                           "max_submissions, poll_seconds)");
}

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
  else if (key == "executor") {
    c.executor = string_value(v, key, 16);
    if (c.executor != "local" && c.executor != "slurm") throw SpecError(key, "must be local or slurm");
  } else if (key == "slurm") {
    if (!v.is_object()) throw SpecError(key, "must be an object of Slurm settings");
    for (const auto& [k, value] : v.items()) apply_slurm(c.slurm, k, value);
  } else if (key == "slurm_spool") c.slurm.spool = string_value(v, key, 4096);
  else if (key == "auth_secret_file") c.auth_secret_file = string_value(v, key, 4096);
  else if (key == "auth_reads") {
    const std::string reads = enum_value(v, key, {"owner", "any"});
    c.auth_reads = reads == "any" ? AuthReads::any : AuthReads::owner;
  } else throw SpecError(key, "unknown setting (database, lcm_url, workers, max_job_seconds, max_job_iterations, "
                              "max_job_memory_mb, max_queued_jobs, max_queued_hours, progress_hz, executor, slurm, "
                              "auth_secret_file, auth_reads)");
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
    if (key == "auth_secret_file" || key == "auth_reads")
      throw std::invalid_argument(a + ": set " + key + " in the --config file");
    const bool text = key == "database" || key == "lcm_url" || key == "executor" || key == "slurm_spool";
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
