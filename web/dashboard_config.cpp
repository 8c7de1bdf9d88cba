#include "dashboard_config.hpp"

#include "cyclopt/errors/spec_error.hpp"
#include "cyclopt/service/spec_fields.hpp"

#include <nlohmann/json.hpp>

#include <fstream>

namespace cyclopt::web {

namespace {

void apply_server_config(DashboardConfig& c, const std::string& path) {
  std::ifstream in(path);
  if (!in) throw SpecError("--config", "cannot read '" + path + "'");
  nlohmann::json file;
  try {
    file = nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw SpecError("--config", "'" + path + "' is not JSON: " + e.what());
  }
  if (!file.is_object()) throw SpecError("--config", "'" + path + "' must hold a JSON object");
  if (file.contains("database")) c.database = service::string_value(file["database"], "database", 4096);
  if (file.contains("lcm_url")) c.lcm_url = service::string_value(file["lcm_url"], "lcm_url", 4096);
  if (file.contains("auth_secret_file"))
    c.auth_secret_file = service::string_value(file["auth_secret_file"], "auth_secret_file", 4096);
  if (file.contains("auth_reads")) {
    const std::string reads = service::string_value(file["auth_reads"], "auth_reads", 16);
    if (reads != "owner" && reads != "any") throw SpecError("auth_reads", "one of owner, any; got '" + reads + "'");
    c.auth_reads_any = reads == "any";
  }
}

bool loopback(const std::string& host) { return host == "127.0.0.1" || host == "localhost" || host == "::1"; }

}  // namespace

DashboardConfig dashboard_config_from_args(const std::vector<std::string>& args) {
  DashboardConfig c;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& flag = args[i];
    if (flag == "--allow-remote") {
      c.allow_remote = true;
      continue;
    }
    if (i + 1 >= args.size()) throw SpecError(flag, "unknown flag or missing value (see --help)");
    const std::string& value = args[++i];
    if (flag == "--config") apply_server_config(c, value);
    else if (flag == "--database") c.database = value;
    else if (flag == "--lcm-url") c.lcm_url = value;
    else if (flag == "--refresh-seconds") {
      try {
        c.refresh_seconds = std::stod(value);
      } catch (const std::exception&) {
        c.refresh_seconds = -1.0;
      }
      if (!(c.refresh_seconds >= 0.1 && c.refresh_seconds <= 60.0)) throw SpecError(flag, "a number in [0.1, 60], got '" + value + "'");
    } else if (flag == "--listen") {
      const std::size_t colon = value.rfind(':');
      const std::string port = colon == std::string::npos ? "" : value.substr(colon + 1);
      c.host = colon == std::string::npos ? "" : value.substr(0, colon);
      if (!c.host.empty() && c.host.front() == '[' && c.host.back() == ']') c.host = c.host.substr(1, c.host.size() - 2);
      c.port = port.empty() || port.size() > 5 || port.find_first_not_of("0123456789") != std::string::npos ? 0 : std::stoi(port);
      if (c.host.empty() || c.port < 1 || c.port > 65535)
        throw SpecError(flag, "HOST:PORT with PORT in [1, 65535], e.g. 127.0.0.1:8080; got '" + value + "'");
    } else
      throw SpecError(flag, "unknown flag (--config, --database, --lcm-url, --listen, --allow-remote, --refresh-seconds)");
  }
  if (!loopback(c.host) && !c.allow_remote)
    throw SpecError("--listen", "'" + c.host + "' is not loopback (127.0.0.1, localhost, ::1): add --allow-remote to serve other hosts");
  return c;
}

}  // namespace cyclopt::web
