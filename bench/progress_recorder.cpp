// Records every progress message of one job until it ends (bench/progress_honesty.sh, issue 53
// acceptance 3): one tab-separated line per message - receive time (Unix s), percent, lower bound
// (0/1), ETA (s, nan: unknown), run time (s), phase - then "end <time> <state>".
// usage: progress_recorder JOB_ID [TIMEOUT_S]   (LCM URL: LCM_DEFAULT_URL)
#include "message_bus.hpp"
#include "service_client.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

double unix_now() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: progress_recorder JOB_ID [TIMEOUT_S]\n");
    return 2;
  }
  const std::int64_t job = std::atoll(argv[1]);
  const double timeout = argc > 2 ? std::atof(argv[2]) : 3600.0;
  const char* env = std::getenv("LCM_DEFAULT_URL");
  const std::string url = cyclopt::wire::resolved_lcm_url(env ? env : "");
  lcm::LCM lcm(url);
  if (!lcm.good()) return 1;
  cyclopt::client::ServiceClient client(lcm, url);
  const auto done = client.watch(job, [](const cyclopt_lcm::job_progress_t& p) {
    std::printf("%.3f\t%.4f\t%d\t%.3f\t%.3f\t%s\n", unix_now(), p.percent, p.percent_is_lower_bound ? 1 : 0, p.eta_seconds,
                p.elapsed_seconds, p.phase.c_str());
    std::fflush(stdout);
  }, timeout);
  std::printf("end\t%.3f\t%s\n", unix_now(), done ? done->state.c_str() : "timeout");
  return done ? 0 : 1;
}
