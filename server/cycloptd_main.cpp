// cycloptd: the cyclopt job server (usage: server_config.hpp, kServerUsage).
#include "cyclopt/cli/exit_codes.hpp"
#include "cyclopt/cli/usage_text.hpp"
#include "cyclopt/cli/version.hpp"
#include "cyclopt/jobs/builtin_job_kinds.hpp"
#include "server.hpp"
#include "server_config.hpp"

#include <csignal>
#include <filesystem>
#include <cstdio>
#include <cstring>

namespace {

std::atomic<bool> g_stop{false};
extern "C" void on_signal(int) { g_stop = true; }

}  // namespace

int main(int argc, char** argv) {
  using namespace cyclopt;
  std::vector<std::string> args(argv + 1, argv + argc);
  for (const auto& a : args) {
    if (a == "--help" || a == "-h") {
      std::fputs(server::kServerUsage, stdout);
      std::fputs(cli::kExitCodeTable, stdout);
      return cli::kExitOk;
    }
    if (a == "--version") {
      std::printf("%s\n", cli::version_text("cycloptd").c_str());
      return cli::kExitOk;
    }
  }
  server::ServerConfig config;
  try {
    config = server::server_config_from_args(args);
  } catch (const std::exception& e) {
    std::fputs(cli::short_usage("cycloptd", e.what(), server::kServerUsage).c_str(), stderr);
    return cli::kExitUsage;
  }
  if (config.executor == "slurm" && config.slurm.worker.empty())
    config.slurm.worker = (std::filesystem::read_symlink("/proc/self/exe").parent_path() / "cyclopt-worker").string();
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigaction(SIGTERM, &sa, nullptr);
  sigaction(SIGINT, &sa, nullptr);
  std::signal(SIGPIPE, SIG_IGN);

  config.lcm_url = wire::resolved_lcm_url(config.lcm_url);
  lcm::LCM lcm(config.lcm_url);
  if (!lcm.good()) {
    std::fprintf(stderr, "cycloptd: cannot open LCM at '%s'\n", config.lcm_url.c_str());
    return cli::kExitResource;
  }
  const service::JobKindRegistry kinds = jobs::builtin_job_kinds();
  try {
    server::Server srv(config, kinds, lcm);
    std::fprintf(stderr, "cycloptd: database %s, %d workers (%s executor), tasks:", config.database.c_str(),
                 server::effective_workers(config), config.executor.c_str());
    for (const auto& t : kinds.tasks()) std::fprintf(stderr, " %s", t.c_str());
    std::fprintf(stderr, "; re-queued %d interrupted job(s), cancelled %d\n", srv.recovery().requeued,
                 srv.recovery().cancelled);
    if (!srv.authenticates())
      std::fprintf(stderr, "cycloptd: WARNING: no auth_secret_file in the config: anyone on the LCM network can "
                           "submit, cancel and read jobs and forge this server's messages (docs/service.md, Authentication)\n");
    srv.serve(g_stop);
    const auto& c = srv.counters();
    const long submissions = c.accepted + c.duplicates + c.rejected;
    std::fprintf(stderr,
                 "cycloptd: stopping (accepted %ld, duplicates %ld, rejected %ld (unauthenticated %ld), queries %ld; "
                 "%.3f ms per submission handled)\n",
                 c.accepted.load(), c.duplicates.load(), c.rejected.load(), c.unauthenticated.load(), c.queries.load(),
                 submissions > 0 ? 1e3 * c.submit_seconds / submissions : 0.0);
    if (const auto* d = srv.bus().datagram_counters())
      std::fprintf(stderr, "cycloptd: datagrams %ld: %ld messages, %ld malformed, %ld oversize, %ld incomplete dropped\n",
                   d->datagrams, d->messages, d->malformed, d->oversize, d->dropped_assemblies);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cycloptd: %s\n", e.what());
    return cli::kExitResource;
  }
  std::fprintf(stderr, "cycloptd: stopped cleanly\n");
  return 0;
}
