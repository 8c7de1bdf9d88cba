// Calibration of the job cost estimate (common/cyclopt/service/job_cost.hpp): seconds per SQP
// iteration and peak memory of one walker solve as functions of the grid size P, for point and
// rolling feet. Each measurement runs in a child process so its peak RSS (getrusage) is its own.
//
// usage: job_cost_bench [iterations = 4] [P ...]   (default P: 200 2000 20000)
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/nlp/solver_options.hpp"
#include "cyclopt/walker/gait_optimisation.hpp"
#include "machine_info.hpp"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace cyclopt;

namespace {

double peak_rss_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;
}

// One solve of `iterations` SQP iterations (the seed's Table 6.2 options) at 1.3 m/s.
void measure(const std::string& foot, int points, int iterations) {
  const double rss0 = peak_rss_mib();
  walker::WalkingConstants c;
  c.points = points;
  const walker::WalkerModel<double> model = walker::make_walker_model(foot::foot_preset(foot).spec, c);
  walker::GaitProblemOptions po;
  po.speed = 1.3;
  nlp::SolverOptions so = nlp::seed_table_6_2_options();
  so.max_iterations = iterations;
  int seen = 0;
  so.on_iteration = [&](const nlp::IterationReport&) { return ++seen < iterations; };
  const auto t0 = std::chrono::steady_clock::now();
  const walker::GaitOptimum opt = walker::optimise_gait(model, po, so);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("%-20s P %6d: %d iterations in %8.3f s = %8.4f s per iteration (incl. start), peak RSS %7.1f MiB "
              "(+%.1f MiB)\n",
              foot.c_str(), points, opt.summary.iterations, s, s / std::max(1, opt.summary.iterations), peak_rss_mib(),
              peak_rss_mib() - rss0);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const int iterations = argc > 1 ? std::atoi(argv[1]) : 4;
  std::vector<int> sizes;
  for (int i = 2; i < argc; ++i) sizes.push_back(std::atoi(argv[i]));
  if (sizes.empty()) sizes = {200, 2000, 20000};
  std::printf("job_cost_bench on %s\n", bench::machine_line().c_str());
  for (const char* foot : {"point", "P2-shoes-left-HMT"})
    for (int p : sizes) {
      std::fflush(stdout);
      const pid_t child = fork();
      if (child == 0) {
        measure(foot, p, iterations);
        std::_Exit(0);
      }
      int status = 0;
      waitpid(child, &status, 0);
    }
}
