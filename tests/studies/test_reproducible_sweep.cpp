// The same spec gives the same answer on every host of the build's instruction-set level (issue 21
// item 1): a short rolling-foot sweep (P2-shoes HMT, P = 100, 1.1-1.5 m/s, a multistart of 2 at
// 1.3 m/s, recovery and closure as by default) against tests/studies/data/reproducible_sweep.json, which the
// default build (CYCLOPT_ARCH x86-64-v3) wrote. Its f_mech per speed must agree to 1e-12
// (relative; bitwise in practice). Another level (x86-64-v2, native) takes other solver paths and
// may reach other optima: the test says it is skipped there.
//
// The same instructions give the same arithmetic only if no choice follows the host at run time:
// Eigen blocks its matrix products by the cache sizes it reads from CPUID unless EIGEN_NO_CPUID
// (CMakeLists.txt), and the block size over the inner dimension orders the sums of J'J.
//
// A change that moves the optima on purpose (a solver, the model, a default) rewrites the file:
//   CYCLOPT_WRITE_SWEEP_REFERENCE=1 build/tests/studies/test_reproducible_sweep
// in the default build, and the commit says why the answer moved.
#include "cyclopt/cli/version.hpp"
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/studies/speed_sweep.hpp"

#include <Eigen/Core>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

using namespace cyclopt;
using namespace cyclopt::studies;

namespace {

constexpr const char* kReferenceArch = "x86-64-v3";
const std::string kReferenceFile = std::string(CYCLOPT_SOURCE_DIR) + "/tests/studies/data/reproducible_sweep.json";

SpeedSweepResult short_rolling_foot_sweep() {
  walker::WalkingConstants constants;
  constants.points = 100;
  const walker::WalkerModel<double> model = walker::make_walker_model(foot::foot_preset("P2-shoes-left-HMT").spec, constants);
  const walker::GaitProblemOptions problem{walker::Objective::mechanical, 1.3, walker::Quadrature::trapezoid, {}};
  SpeedSweepOptions o;
  o.speeds = {1.1, 1.2, 1.3, 1.4, 1.5};
  o.seed_speeds = {1.3};
  o.starts = 2;
  return speed_sweep(model, problem, o);
}

}  // namespace

TEST(ReproducibleSweep, EigenBlocksItsProductsBySizesThatDoNotFollowTheHost) {
  std::ptrdiff_t l1 = 0, l2 = 0, l3 = 0;
  Eigen::internal::manage_caching_sizes(Eigen::GetAction, &l1, &l2, &l3);
  EXPECT_EQ(l1, Eigen::internal::defaultL1CacheSize) << "Eigen read this host's L1 size: build with EIGEN_NO_CPUID";
  EXPECT_EQ(l2, Eigen::internal::defaultL2CacheSize) << "Eigen read this host's L2 size: build with EIGEN_NO_CPUID";
  EXPECT_EQ(l3, Eigen::internal::defaultL3CacheSize) << "Eigen read this host's L3 size: build with EIGEN_NO_CPUID";
}

TEST(ReproducibleSweep, TheDefaultBuildReachesTheCommittedOptimaOnEveryHostOfItsLevel) {
  if (std::string(cli::build_arch()) != kReferenceArch)
    GTEST_SKIP() << "the reference optima were computed by the default " << kReferenceArch << " build; this build targets "
                 << cli::build_arch() << ", whose solver paths may reach other optima";
  const SpeedSweepResult r = short_rolling_foot_sweep();
  if (std::getenv("CYCLOPT_WRITE_SWEEP_REFERENCE")) {
    nlohmann::json doc = {{"arch", cli::build_arch()}, {"flags", cli::build_flags()}, {"revision", cli::git_revision()},
                          {"speeds", nlohmann::json::array()}, {"f_mech", nlohmann::json::array()}};
    for (const BestPoint& b : r.best) {
      doc["speeds"].push_back(b.speed);
      doc["f_mech"].push_back(b.found ? nlohmann::json(b.point.objective) : nlohmann::json(nullptr));
    }
    std::ofstream(kReferenceFile) << doc.dump(1) << "\n";
    GTEST_SKIP() << "wrote " << kReferenceFile;
  }
  std::ifstream in(kReferenceFile);
  ASSERT_TRUE(in.good()) << kReferenceFile;
  const nlohmann::json reference = nlohmann::json::parse(in);
  ASSERT_EQ(reference["f_mech"].size(), r.best.size());
  for (std::size_t i = 0; i < r.best.size(); ++i) {
    const nlohmann::json& expected = reference["f_mech"][i];
    ASSERT_EQ(r.best[i].found, !expected.is_null()) << r.best[i].speed << " m/s";
    if (expected.is_null()) continue;
    const double f = r.best[i].point.objective, f_ref = expected.get<double>();
    std::printf("%.1f m/s: f_mech %.17g, reference %.17g\n", r.best[i].speed, f, f_ref);
    EXPECT_LE(std::abs(f - f_ref), 1e-12 * f_ref) << r.best[i].speed << " m/s: another answer than the reference build's ("
                                                  << reference["revision"] << ")";
  }
}
