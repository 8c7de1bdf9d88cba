#pragma once
// cyclopt-web's settings (docs/dashboard.md): what it shares with cycloptd comes from the server's
// own config file (database, lcm_url, auth_secret_file, auth_reads; the server's other keys are
// ignored), so the two cannot disagree; the rest from the command line.

#include <string>
#include <vector>

namespace cyclopt::web {

struct DashboardConfig {
  std::string database = "cyclopt.db";  // opened read-only
  std::string lcm_url;                   // empty: LCM's default (LCM_DEFAULT_URL or udpm multicast)
  std::string auth_secret_file;          // the server's key file; empty: no authentication
  bool auth_reads_any = false;           // the server's auth_reads "any": every key reads every job
  std::string host = "127.0.0.1";
  int port = 8080;
  bool allow_remote = false;             // listening on another address than loopback
  double refresh_seconds = 1.0;          // the job list is read from the database this often
};

// --config FILE (cycloptd's), --database FILE, --lcm-url URL, --listen HOST:PORT, --allow-remote,
// --refresh-seconds S. Throws SpecError naming the flag or key and the admissible values; a
// non-loopback HOST without --allow-remote is refused.
DashboardConfig dashboard_config_from_args(const std::vector<std::string>& args);

inline constexpr const char* kDashboardUsage =
    R"(usage: cyclopt-web [--config CYCLOPTD.json] [--database FILE] [--lcm-url URL]
                   [--listen HOST:PORT] [--allow-remote] [--refresh-seconds S]
       cyclopt-web token [--key-file FILE] [--hours H]

The browser dashboard of cycloptd's jobs (docs/dashboard.md): open
http://HOST:PORT/.

  --config FILE      cycloptd's config file: database, lcm_url, auth_secret_file
                     and auth_reads are taken from it (the server's other
                     settings are ignored)
  --listen HOST:PORT default 127.0.0.1:8080; a HOST other than loopback needs
                     --allow-remote
  --refresh-seconds  how often the job list is read from the database (default
                     1, 0.1 .. 60)
  token              prints a login token of the key in FILE (your cyclopt key
                     file, default $CYCLOPT_KEY_FILE) valid for H hours (default
                     12): open http://HOST:PORT/login?token=TOKEN
)";

}  // namespace cyclopt::web
