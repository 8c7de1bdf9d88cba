// The foot-design study (studies/foot_design.hpp): each bad option is refused before anything is
// solved, naming the option; the drawn start feet; the answer rule; and, on a small study, that
// its two threads call the caller one call at a time and never after the study returned.
#include "cyclopt/studies/foot_design.hpp"
#include "cyclopt/foot/convexity_constraints.hpp"
#include "cyclopt/foot/foot_presets.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <mutex>
#include <string>
#include <thread>

using namespace cyclopt;
using namespace cyclopt::studies;

namespace {

std::string refusal(const foot::FootSpec& start, const FootDesignOptions& o) {
  try {
    FootDesignObserver none;
    design_feet(start, {}, o, none);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

FootDesignOptions small() {
  FootDesignOptions o;
  o.densities = {10};
  o.sweep.speeds = {2.2, 2.3};
  o.design_speed = 2.3;
  return o;
}

const foot::FootSpec& p2() { return foot::foot_preset("P2-shoes-left-HMT").spec; }

}  // namespace

TEST(FootDesign, RefusesBadOptionsNamingThem) {
  FootDesignOptions o = small();
  o.densities = {10, -5};
  EXPECT_EQ(refusal(p2(), o).rfind("densities:", 0), 0u) << refusal(p2(), o);
  o = small();
  o.design_speed = 1.0;
  EXPECT_EQ(refusal(p2(), o).rfind("design_speed:", 0), 0u) << refusal(p2(), o);
  o = small();
  o.free_parameters = {"l_HM", "k_X"};
  EXPECT_NE(refusal(p2(), o).find("free_parameters: 'k_X'"), std::string::npos) << refusal(p2(), o);
  o = small();
  o.starts = 0;
  EXPECT_EQ(refusal(p2(), o).rfind("starts:", 0), 0u);
  o = small();
  o.foot_scale = -1;
  EXPECT_EQ(refusal(p2(), o).rfind("foot_scale:", 0), 0u) << refusal(p2(), o);
  o = small();
  o.resolution_tolerance = 0.0;
  EXPECT_EQ(refusal(p2(), o).rfind("resolution_tolerance:", 0), 0u) << refusal(p2(), o);
  EXPECT_EQ(refusal(foot::foot_preset("point").spec, small()).rfind("foot:", 0), 0u);
}

TEST(FootDesign, RefusesBoundsThatExcludeTheStartFootInAFixedParameter) {
  // P2's h_F is 106.5 mm, above h_F,max = 100 mm: with h_F free it is moved onto the bound, with
  // h_F fixed the bounds exclude the start foot.
  FootDesignOptions o = small();
  o.free_parameters = {"l_HM", "k_HM"};
  EXPECT_EQ(refusal(p2(), o).rfind("design_bounds:", 0), 0u) << refusal(p2(), o);
}

TEST(FootDesign, DrawnStartFeetVaryTheFreeParametersWithinBoundsAndConvexity) {
  foot::FootSpec start = p2();
  const foot::DesignBounds bounds;
  const std::vector<std::string> all{"h_F", "l_HA", "l_HM", "l_MT", "gamma_F", "k_H", "k_HM", "k_MT", "k_T"};
  start.parameters = foot::project_into_design_bounds(start.model, start.parameters, bounds, all);
  const auto layout = foot::parameter_layout(start.model);
  const foot::LinearInequalities convex = foot::convexity_constraints(start.model);
  std::mt19937_64 rng(7);
  double k_HM_min = 1e9, k_HM_max = 0;
  for (int draw = 0; draw < 200; ++draw) {
    const foot::FootParameters<double> p = draw_design_foot(start, all, bounds, 1.0, rng);
    EXPECT_TRUE(foot::violated_design_bounds(start.model, p, bounds, 1e-12).empty()) << p.transpose();
    EXPECT_TRUE(((convex.A * p + convex.b).array() >= 0.0).all()) << p.transpose();
    EXPECT_GT(foot::toe_convexity_margin(p), 0.0) << p.transpose();
    for (std::size_t k = 0; k < layout.size(); ++k) {
      EXPECT_GE(p[static_cast<Eigen::Index>(k)], layout[k].min) << layout[k].name;
      EXPECT_LE(p[static_cast<Eigen::Index>(k)], layout[k].max) << layout[k].name;
    }
    k_HM_min = std::min(k_HM_min, p[foot::hmt::k_HM]);
    k_HM_max = std::max(k_HM_max, p[foot::hmt::k_HM]);
  }
  // exp(N(0,1)) spreads k_HM = 0.054 over more than a factor 5 (the seed's rho 10 design has 0.32).
  EXPECT_GT(k_HM_max / k_HM_min, 5.0);
  // Only the free parameters move; scale 0 keeps the start foot.
  const foot::FootParameters<double> some = draw_design_foot(start, {"k_HM"}, bounds, 1.0, rng);
  for (Eigen::Index i = 0; i < some.size(); ++i) {
    if (i != foot::hmt::k_HM) {
      EXPECT_EQ(some[i], start.parameters[i]) << layout[static_cast<std::size_t>(i)].name;
    }
  }
  EXPECT_EQ(draw_design_foot(start, all, bounds, 0.0, rng), start.parameters);
}

TEST(FootDesign, DefaultDesignHoldsTheCornerCurvaturesAsTheSeedDoes) {
  // Tables 10.1 and 10.2: every design of the seed has k_H = k_T = 1e-8, the fits' fixed value
  // (4.13, 4.18); the other parameters are designed.
  EXPECT_EQ(default_design_parameters(foot::FootModel::hmt),
            (std::vector<std::string>{"h_F", "l_HA", "l_HM", "l_MT", "gamma_F", "k_HM", "k_MT"}));
  EXPECT_EQ(default_design_parameters(foot::FootModel::hm), (std::vector<std::string>{"h_F", "l_HA", "l_HM", "k_HM"}));
}

TEST(FootDesign, TheAnswerIsTheDesignThatReachesMoreSpeedsThenTheCheaperOne) {
  const double nan = std::nan("");
  const auto sweep = [](std::vector<double> f) {
    FootSweepSummary s;
    s.f_mech = std::move(f);
    s.speeds_found = static_cast<int>(std::count_if(s.f_mech.begin(), s.f_mech.end(), [](double x) { return std::isfinite(x); }));
    return s;
  };
  // Equal reach: the lower mean wins; a tie keeps the design (the seed's choice).
  EXPECT_EQ(better_design(sweep({0.005, 0.010, 0.020}), sweep({0.001, 0.010, 0.021})), DesignAnswer::low_speed_design);
  EXPECT_EQ(better_design(sweep({0.005, 0.010, 0.020}), sweep({0.007, 0.010, 0.020})), DesignAnswer::design);
  EXPECT_EQ(better_design(sweep({0.005, 0.010, 0.020}), sweep({0.005, 0.010, 0.020})), DesignAnswer::design);
  // More speeds win whatever the mean (run D's low-speed design: cheaper, but 0.4 m/s missing).
  EXPECT_EQ(better_design(sweep({0.005, 0.010, 0.020}), sweep({0.001, nan, 0.010})), DesignAnswer::design);
  EXPECT_EQ(better_design(sweep({0.001, nan, 0.010}), sweep({0.005, 0.010, 0.020})), DesignAnswer::low_speed_design);
  // Equal reach on different speeds: compared over the speeds both reached.
  EXPECT_EQ(better_design(sweep({nan, 0.010, 0.020}), sweep({0.001, nan, 0.021})), DesignAnswer::design);
  // add_savings sets the answer, and the answer's savings are its sweep's.
  DensityDesign d;
  d.high = sweep({0.005, 0.010, 0.020});
  d.low = sweep({0.001, 0.010, 0.020});
  const std::vector<double> speeds{0.3, 0.4, 0.5};
  add_savings(d, speeds, sweep({0.010, 0.020, 0.030}), sweep({0.020, 0.040, 0.060}));
  EXPECT_EQ(d.answer, DesignAnswer::low_speed_design);
  EXPECT_EQ(&d.answer_sweep(), &d.low);
  EXPECT_NEAR(d.answer_saving_vs_start(), 1 - 0.031 / 0.060, 1e-12);
  EXPECT_NEAR(d.answer_saving_vs_point(), 1 - 0.031 / 0.120, 1e-12);
  EXPECT_NEAR(d.saving_vs_start, 1 - 0.035 / 0.060, 1e-12);
  EXPECT_STREQ(to_string(d.answer), "low-speed design");
}

namespace {

// The small study of tests/service/slurm_integration.sh's foot_design job: P = 50, two design
// starts from the start foot itself, 2.2 and 2.3 m/s, one multistart run per sweep seed speed.
FootDesignOptions runnable() {
  FootDesignOptions o = small();
  o.references = false;
  o.starts = 2;
  o.seed = 2;
  o.scale = 0.02;
  o.foot_scale = 0.0;
  o.constants.points = 50;
  // P = 50 keeps these tests fast but resolves no optimum to 10 %: the design at 2.2 m/s has f_mech
  // 0.0375 on it and 0.0545 on 4P. These tests are about the study's flow, not its resolution.
  o.resolution_tolerance = 1.0;
  o.sweep.starts = 1;
  o.sweep.seeds = {2};
  o.sweep.scale = 0.02;
  o.sweep.seed_speeds = {2.3};
  o.sweep.continuation.min_trust_region = 0.05;
  o.sweep.continuation.corrector.max_iterations = 500;
  o.sweep.corrector_max_iterations = 60;
  // A design found before (a KKT point): whether a drawn start reaches one within MaxIter follows
  // the build's rounding; this start converges locally on every host.
  std::ifstream in(std::string(CYCLOPT_SOURCE_DIR) + "/tests/service/data/small_design.json");
  const nlohmann::json known = nlohmann::json::parse(in).at("known_designs").at(0);
  const std::vector<double> z = known.at("z").get<std::vector<double>>();
  o.known_designs = {{known.at("density").get<double>(), Eigen::Map<const Eigen::VectorXd>(z.data(), static_cast<Eigen::Index>(z.size()))}};
  return o;
}

// Watches the caller's side of the study: calls that overlap, and calls after `closed`.
struct CallbackWatch {
  std::atomic<int> inside{0}, overlaps{0}, calls{0}, late{0};
  std::atomic<bool> closed{false};
  struct Call {
    CallbackWatch& w;
    explicit Call(CallbackWatch& watch) : w(watch) {
      if (w.inside.fetch_add(1) > 0) ++w.overlaps;
      if (w.closed) ++w.late;
      ++w.calls;
      std::this_thread::sleep_for(std::chrono::microseconds(50));  // widen the window for an overlap
    }
    ~Call() { --w.inside; }
  };
};

// Sweep journals in memory, keyed by part; each journal reads a snapshot taken when it is made
// (as the service's sweep_journal does), its records go to the shared maps.
struct MemoryJournals {
  std::mutex m;
  std::map<std::string, std::map<std::pair<int, int>, nlp::SolverSummary>> solves;
  std::map<std::string, std::map<int, continuation::ContinuationResult>> runs;
  std::vector<std::string> parts;

  SweepJournal make(const std::string& part, CallbackWatch& watch) {
    const std::lock_guard lock(m);
    parts.push_back(part);
    const auto solved = std::make_shared<const std::map<std::pair<int, int>, nlp::SolverSummary>>(solves[part]);
    const auto ran = std::make_shared<const std::map<int, continuation::ContinuationResult>>(runs[part]);
    SweepJournal j;
    j.find_solve = [solved](int batch, int start) -> std::optional<nlp::SolverSummary> {
      const auto it = solved->find({batch, start});
      return it == solved->end() ? std::nullopt : std::optional(it->second);
    };
    j.find_run = [ran](int run) -> std::optional<continuation::ContinuationResult> {
      const auto it = ran->find(run);
      return it == ran->end() ? std::nullopt : std::optional(it->second);
    };
    j.record_solve = [this, part, &watch](int batch, int start, const nlp::SolverSummary& r) {
      const CallbackWatch::Call call(watch);
      const std::lock_guard lock(m);
      solves[part][{batch, start}] = r;
    };
    j.record_run = [this, part, &watch](int run, const continuation::ContinuationResult& r) {
      const CallbackWatch::Call call(watch);
      const std::lock_guard lock(m);
      runs[part][run] = r;
    };
    return j;
  }
};

// Every call of the study's observer through `watch`; on_density also records the phases.
class WatchingObserver final : public FootDesignObserver {
 public:
  WatchingObserver(CallbackWatch& watch, MemoryJournals& journals, std::vector<DesignPhase>& phases,
                   std::function<bool(DesignPhase)> go_on = [](DesignPhase) { return true; })
      : watch_(watch), journals_(journals), phases_(phases), go_on_(std::move(go_on)) {}
  bool on_step(const std::string&) override {
    const CallbackWatch::Call call(watch_);
    return true;
  }
  bool on_density(const DensityDesign&, DesignPhase phase) override {
    const CallbackWatch::Call call(watch_);
    phases_.push_back(phase);
    return go_on_(phase);
  }
  void on_multistart_progress(double, int, double) override { const CallbackWatch::Call call(watch_); }
  void on_sweep_progress(const SweepProgress&) override { const CallbackWatch::Call call(watch_); }
  SweepJournal journal(const std::string& part) override { return journals_.make(part, watch_); }

 private:
  CallbackWatch& watch_;
  MemoryJournals& journals_;
  std::vector<DesignPhase>& phases_;
  const std::function<bool(DesignPhase)> go_on_;
};

// The corrector's on_iteration of `o` through `watch` too.
void watch_corrector(FootDesignOptions& o, CallbackWatch& watch) {
  o.sweep.continuation.corrector.on_iteration = [&watch](const nlp::IterationReport&) {
    const CallbackWatch::Call call(watch);
    return true;
  };
}

}  // namespace

TEST(FootDesign, ItsTwoThreadsCallTheCallerOneAtATimeAndNeverAfterItReturned) {
  // The design's fixed-foot sweep runs on a thread of its own beside the free-foot continuation
  // and the low-speed sweep (DesignStudy::at); the caller (the service: one job context) must
  // still see one call at a time, and none once design_density has returned.
  FootDesignOptions o = runnable();
  CallbackWatch watch;
  MemoryJournals journals;
  std::vector<DesignPhase> phases;
  watch_corrector(o, watch);
  WatchingObserver observer(watch, journals, phases);
  const DensityDesign d = design_density(10, p2(), {}, o, observer);
  watch.closed = true;
  ASSERT_GE(d.best, 0) << "the small study found no admissible design";
  for (const DesignOptimum& m : d.optima)  // designs are KKT points, not "acceptable" potential ones
    EXPECT_EQ(m.summary.termination, nlp::Termination::converged) << m.summary.message;
  EXPECT_EQ(d.kkt_starts, static_cast<int>(std::count_if(d.runs.begin(), d.runs.end(), [](const DesignRun& r) {
              return r.termination == nlp::Termination::converged;
            })));
  EXPECT_FALSE(d.stopped);
  EXPECT_GT(d.high.speeds_found, 0);
  EXPECT_GT(d.low.speeds_found, 0);
  EXPECT_EQ(phases, (std::vector<DesignPhase>{DesignPhase::multistart, DesignPhase::free_foot, DesignPhase::high_sweep,
                                              DesignPhase::low_sweep}));
  EXPECT_TRUE(std::count(journals.parts.begin(), journals.parts.end(), "rho 10/high"));
  EXPECT_GT(watch.calls.load(), 100);
  EXPECT_EQ(watch.overlaps.load(), 0) << "callbacks overlapped";
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  EXPECT_EQ(watch.late.load(), 0);

  // Stopped by the caller after step 2 (design multistart and free-foot runs replayed from the
  // journal), the design's sweep, still solving beside it, is abandoned before the study returns.
  journals.solves.erase("rho 10/high");
  journals.runs.erase("rho 10/high");
  CallbackWatch stopped_watch;
  phases.clear();
  FootDesignOptions stop = runnable();
  stop.sweep.starts = 80;  // a design sweep of ~20 s (2 cores), unless abandoned
  watch_corrector(stop, stopped_watch);
  WatchingObserver stopping(stopped_watch, journals, phases, [](DesignPhase p) { return p != DesignPhase::free_foot; });
  const auto t0 = std::chrono::steady_clock::now();
  const DensityDesign s = design_density(10, p2(), {}, stop, stopping);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  stopped_watch.closed = true;
  EXPECT_TRUE(s.stopped);
  EXPECT_EQ(phases, (std::vector<DesignPhase>{DesignPhase::multistart, DesignPhase::free_foot}));
  EXPECT_LT(seconds, 5.0) << "the design's sweep was not abandoned";
  EXPECT_EQ(stopped_watch.overlaps.load(), 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  EXPECT_EQ(stopped_watch.late.load(), 0) << "the design's sweep called back after the study returned";
  std::printf("first study %d callbacks; the stopped one returned after %.2f s\n", watch.calls.load(), seconds);
}

TEST(FootDesign, SweepsTheDesignOnceWhereTheFreeFootCurveReachesNoLowerSpeed) {
  // Design speed at the bottom of the grid: step 2 has no lower speed, so the low-speed design is
  // the design, and its sweep is the design's, not a second identical one.
  FootDesignOptions o = runnable();
  o.design_speed = 2.2;
  o.sweep.seed_speeds = {2.2};
  CallbackWatch watch;
  MemoryJournals journals;
  std::vector<DesignPhase> phases;
  watch_corrector(o, watch);
  WatchingObserver observer(watch, journals, phases);
  const DensityDesign d = design_density(10, p2(), {}, o, observer);
  ASSERT_GE(d.best, 0) << "the small study found no admissible design";
  EXPECT_DOUBLE_EQ(d.low_speed, 2.2);
  EXPECT_GT(d.high.speeds_found, 0);
  EXPECT_EQ(d.low.speeds_found, d.high.speeds_found);
  for (std::size_t i = 0; i < d.high.f_mech.size(); ++i) {
    if (std::isfinite(d.high.f_mech[i])) {
      EXPECT_EQ(d.low.f_mech[i], d.high.f_mech[i]) << "speed " << i;
    }
  }
  EXPECT_EQ(d.low.name, "rho 10 low-speed design");
  EXPECT_EQ(d.low.seconds, 0.0);
  EXPECT_TRUE(std::count(journals.parts.begin(), journals.parts.end(), "rho 10/high"));
  EXPECT_FALSE(std::count(journals.parts.begin(), journals.parts.end(), "rho 10/low")) << "the same foot was swept twice";
  EXPECT_EQ(phases, (std::vector<DesignPhase>{DesignPhase::multistart, DesignPhase::free_foot, DesignPhase::high_sweep,
                                              DesignPhase::low_sweep}));
  EXPECT_EQ(better_design(d.high, d.low), DesignAnswer::design);
}
