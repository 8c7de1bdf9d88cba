// cyclopt-web: the browser dashboard of cycloptd's jobs (usage: dashboard_config.hpp,
// kDashboardUsage; docs/dashboard.md). Three threads besides HTTP's: the job list read from the
// database every --refresh-seconds, the progress messages received from LCM, and one waiting for
// SIGINT / SIGTERM.
#include "cyclopt/cli/exit_codes.hpp"
#include "cyclopt/cli/usage_text.hpp"
#include "cyclopt/cli/version.hpp"
#include "dashboard_config.hpp"
#include "dashboard_server.hpp"
#include "service_client.hpp"
#include "store_rows.hpp"
#include "web_token.hpp"

#include <csignal>
#include <cstdlib>
#include <cstdio>
#include <thread>

namespace {

using namespace cyclopt;

// `cyclopt-web token [--key-file FILE] [--hours H]`.
int print_token(const std::vector<std::string>& args) {
  std::string key_file;
  double hours = 12.0;
  for (std::size_t i = 1; i + 1 < args.size(); i += 2) {
    if (args[i] == "--key-file") key_file = args[i + 1];
    else if (args[i] == "--hours") hours = std::atof(args[i + 1].c_str());
    else throw std::invalid_argument(args[i] + ": unknown flag of token (--key-file, --hours)");
  }
  if (const char* env = std::getenv("CYCLOPT_KEY_FILE"); key_file.empty() && env) key_file = env;  // as cyclopt's
  if (key_file.empty() || args.size() % 2 == 0) throw std::invalid_argument("token needs --key-file FILE (or CYCLOPT_KEY_FILE) [--hours H]");
  if (!(hours > 0.0 && hours <= 24.0 * 366)) throw std::invalid_argument("--hours: a number in (0, 8784]");
  const wire::KeyRing ring = wire::read_key_file(key_file);
  const auto expires = wire::unix_now_us() / 1000000 + static_cast<std::int64_t>(hours * 3600.0);
  std::printf("%s\n", web::make_token(ring.keys.at(0), expires).c_str());
  return cli::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  for (const auto& a : args) {
    if (a == "--help" || a == "-h") {
      std::fputs(web::kDashboardUsage, stdout);
      std::fputs(cli::kExitCodeTable, stdout);
      return cli::kExitOk;
    }
    if (a == "--version") {
      std::printf("%s\n", cli::version_text("cyclopt-web").c_str());
      return cli::kExitOk;
    }
  }
  web::DashboardConfig config;
  try {
    if (!args.empty() && args[0] == "token") return print_token(args);
    config = web::dashboard_config_from_args(args);
  } catch (const std::exception& e) {
    std::fputs(cli::short_usage("cyclopt-web", e.what(), web::kDashboardUsage).c_str(), stderr);
    return cli::kExitUsage;
  }
  // Signals go to the thread that waits for them, not to HTTP's or LCM's.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);
  std::signal(SIGPIPE, SIG_IGN);

  const std::string url = wire::resolved_lcm_url(config.lcm_url);
  try {
    std::optional<wire::KeyRing> keys;
    if (!config.auth_secret_file.empty()) keys = wire::read_key_file(config.auth_secret_file);
    storage::ResultReader store(config.database);
    lcm::LCM lcm(url);
    if (!lcm.good()) {
      std::fprintf(stderr, "cyclopt-web: cannot open LCM at '%s'\n", url.c_str());
      return cli::kExitResource;
    }
    web::LiveFleet fleet;
    fleet.refresh(web::all_rows(store, storage::query_for("jobs")));
    web::DashboardServer http(config, store, fleet, keys);
    std::thread refresher([&] {
      while (!fleet.stopped()) {
        try {
          fleet.refresh(web::all_rows(store, storage::query_for("jobs")));
        } catch (const std::exception& e) {  // e.g. the database busy: the next refresh reads it
          std::fprintf(stderr, "cyclopt-web: reading the job list: %s\n", e.what());
        }
        fleet.wait_for_refresh(std::chrono::milliseconds(static_cast<int>(config.refresh_seconds * 1000)));
      }
    });
    std::thread listener([&] {
      client::ServiceClient monitor = keys ? client::ServiceClient(lcm, url, *keys) : client::ServiceClient(lcm, url);
      while (!fleet.stopped()) monitor.listen([&](const cyclopt_lcm::job_progress_t& p) { fleet.apply(p); }, 0.25);
    });
    std::thread stopper([&] {
      int signal = 0;
      sigwait(&stop_signals, &signal);
      fleet.stop();
      http.stop();
    });
    std::fprintf(stderr, "cyclopt-web: http://%s:%d/ (database %s read-only, LCM %s, %s)\n", config.host.c_str(), config.port,
                 config.database.c_str(), url.c_str(), keys ? "login by token" : "no authentication");
    const bool served = http.listen();
    if (!served) {
      std::fprintf(stderr, "cyclopt-web: cannot listen on %s:%d\n", config.host.c_str(), config.port);
      fleet.stop();
      pthread_kill(stopper.native_handle(), SIGTERM);
    }
    stopper.join();
    refresher.join();
    listener.join();
    return served ? cli::kExitOk : cli::kExitResource;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cyclopt-web: %s\n", e.what());
    return cli::kExitResource;
  }
}
