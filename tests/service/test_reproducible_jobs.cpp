// Issue 17 item 7, reproducible results: every job the server accepts is stored with the git
// revision of the server, the random seeds it uses and its spec with every default filled in
// (service/resolved_spec.hpp), and that resolved spec, submitted again, is the same job, for
// every kind. A walker
// job can start from a point an earlier job stored (service/stored_start.hpp); a bad reference is
// rejected naming its field.
#include "cyclopt/cli/version.hpp"
#include "cyclopt/foot/fitted_feet.hpp"
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/foot_fit/synthetic_trials.hpp"
#include "cyclopt/io/foot_fit_json.hpp"
#include "cyclopt/io/foot_spec_json.hpp"
#include "cyclopt/jobs/giant_swing/giant_swing_job_spec.hpp"
#include "cyclopt/records/sweep_records.hpp"
#include "cyclopt/records/walker_point_record.hpp"
#include "cyclopt/service/job_spec.hpp"
#include "cyclopt/service/resolved_spec.hpp"
#include "cyclopt/jobs/walker/stored_start.hpp"
#include "cyclopt/service/stored_references.hpp"
#include "cyclopt_channels.hpp"
#include "memq_server_fixture.hpp"

#include <gtest/gtest.h>

#include <set>

namespace cyclopt {
namespace {

using ReproducibleJobs = testing::MemqServerTest;

nlohmann::json job_row(client::ServiceClient& client, std::int64_t id) {
  const auto page = client.query(storage::query_for("job", id), 5.0);
  EXPECT_TRUE(page);
  return page ? page->rows.at(0) : nlohmann::json();
}

TEST_F(ReproducibleJobs, AStoredJobRecordsTheVersionTheSeedsAndTheResolvedSpec) {
  server::Server srv(config_, kinds_, lcm_);
  const nlohmann::json spec = {{"scene", "walker"}, {"task", "multistart"}, {"foot", "P1-barefoot-left-HM"},
                               {"speed", 1.0}, {"points", 50}, {"solver", {{"max_iterations", 30}}},
                               {"multistart", {{"starts", 2}, {"seed", 42}}}};
  const auto ack = client_.submit("repro-multistart", spec.dump(), 5.0);
  ASSERT_TRUE(ack && ack->accepted) << (ack ? ack->problem : "no ack");
  const nlohmann::json job = job_row(client_, ack->job_id);
  EXPECT_EQ(job["program_version"], cli::git_revision());
  EXPECT_NE(job["program_version"], "");
  EXPECT_EQ(job["isa_level"], cli::build_arch());  // results are reproducible by builds of this level
  EXPECT_EQ(job["build_flags"], cli::build_flags());
  EXPECT_NE(std::string(cli::build_flags()).find("-march="), std::string::npos) << cli::build_flags();
  EXPECT_EQ(job["seeds"], (nlohmann::json{{"multistart.seed", 42}}));
  const nlohmann::json& r = job["resolved_spec"];
  std::printf("resolved sweep spec: %s\n", r.dump().c_str());
  EXPECT_EQ(r["speed"], 1.0);
  EXPECT_EQ(r["foot"]["model"], "HM");                   // the preset as its full parameters
  EXPECT_TRUE(r["foot"].contains("l_HM"));
  EXPECT_EQ(r["solver"]["solver"], "sqp");               // the seed's Table 6.2 defaults
  EXPECT_EQ(r["solver"]["max_iterations"], 30);
  EXPECT_EQ(r["solver"]["optimality_tolerance"], 1e-5);
  EXPECT_EQ(r["points"], 50);
  EXPECT_EQ(r["bezier_degree"], 6);
  EXPECT_EQ(r["objective"], "f_mech");
  EXPECT_EQ(r["multistart"], (nlohmann::json{{"starts", 2}, {"seed", 42}, {"scale", 0.05}}));
  const auto done = client_.watch(ack->job_id, [](const cyclopt_lcm::job_progress_t&) {}, 120.0);
  ASSERT_TRUE(done);
}

// The resolved spec of `spec`, checked to be a fixed point: validated and resolved again, it is
// itself (the defaults it spells out are the ones the job ran with).
nlohmann::json resolved_fixed_point(const nlohmann::json& spec) {
  static const service::JobKindRegistry kinds = jobs::builtin_job_kinds();
  const nlohmann::json first = service::resolved_spec(service::validate_job_spec(spec, kinds));
  nlohmann::json again;
  EXPECT_NO_THROW(again = service::resolved_spec(service::validate_job_spec(first, kinds))) << first.dump();
  EXPECT_EQ(again, first) << "submitted " << spec.dump();
  EXPECT_LE(first.dump().size(), channels::kMaxSpecBytes) << "the resolved spec is too large to submit again";
  return first;
}

// The keys of a JSON object.
std::set<std::string> keys(const nlohmann::json& j) {
  std::set<std::string> k;
  for (const auto& [key, value] : j.items()) k.insert(key);
  return k;
}

// The resolved spec of each walker kind is itself a valid spec that resolves to itself.
TEST(ResolvedSpec, TheResolvedSpecOfAWalkerJobIsTheSameJob) {
  const std::vector<nlohmann::json> specs = {
      {{"scene", "walker"}, {"task", "evaluate"}, {"foot", "point"}, {"speed", 1.0}},
      {{"scene", "walker"}, {"task", "optimise"}, {"foot", "P1-barefoot-left-HM"}, {"speed", 1.3},
       {"objective", "f_usq"}, {"solver", {{"solver", "ipopt"}}}, {"free_parameters", {"l_HM", "h_F"}}, {"positive_power_band", 1e-3},
       {"design_bounds", {{"l_HM_max", 0.3}}}},
      {{"scene", "walker"}, {"task", "multistart"}, {"foot", "P1-barefoot-left-HM"}, {"speed", 1.3},
       {"multistart", {{"starts", 4}}}, {"name", "four starts"}, {"limits", {{"max_wall_seconds", 60}}}},
      {{"scene", "walker"}, {"task", "continuation"}, {"foot", "point"}, {"speeds", "0.5:0.5:1.5"},
       {"continuation", {{"predictor", "trivial"}, {"fixed_step", 0.2}}}},
      {{"scene", "walker"}, {"task", "continuation"}, {"foot", "P1-barefoot-left-HM"}, {"speeds", 1.0},
       {"continuation", {{"parameter", "l_HM"}, {"values", "0.1:0.05:0.2"}}}},
      {{"scene", "walker"}, {"task", "sweep"}, {"foot", "point"}, {"speeds", {0.5, 1.0}},
       {"multistart", {{"seed", 9}}}, {"continuation", {{"seed_speeds", 1.0}}}},
      {{"scene", "walker"}, {"task", "sensitivity"}, {"foot", "point"}, {"speed", 1.0}, {"steps", 2}},
  };
  for (const nlohmann::json& spec : specs) {
    const nlohmann::json first = resolved_fixed_point(spec);
    if (spec.contains("design_bounds")) {
      EXPECT_EQ(first["design_bounds"]["l_HM_max"], 0.3) << first.dump();
    }
    const std::string task = spec["task"];
    const nlohmann::json seeds = service::random_seeds(first);
    if (task == "multistart" || task == "sweep") {  // the kinds that draw random starts
      EXPECT_EQ(seeds, (nlohmann::json{{"multistart.seed", spec["multistart"].value("seed", 1)}})) << first.dump();
    } else {
      EXPECT_EQ(seeds, nlohmann::json::object()) << first.dump();
    }
  }
}

TEST(ResolvedSpec, AFootSweepSpellsOutItsFootGridAndSamples) {
  const nlohmann::json spec = {{"scene", "walker"}, {"task", "foot_sweep"}, {"foot", "P2-shoes-left-HMT"},
                               {"sweep", {{"parameter", "density"}, {"values", "20:20:60"}}}};
  const nlohmann::json r = resolved_fixed_point(spec);
  std::printf("resolved foot_sweep spec: %s\n", r.dump().c_str());
  EXPECT_EQ(keys(r), (std::set<std::string>{"scene", "task", "foot", "sweep", "samples", "point_delay_ms"}));
  EXPECT_EQ(r["foot"], io::to_json(foot::foot_preset("P2-shoes-left-HMT").spec));  // the preset's parameters
  EXPECT_EQ(r["sweep"], (nlohmann::json{{"parameter", "density"}, {"values", {20.0, 40.0, 60.0}}}));
  EXPECT_EQ(r["samples"], 13);
  EXPECT_EQ(r["point_delay_ms"], 0);
  EXPECT_EQ(service::random_seeds(r), nlohmann::json::object());
}

// The feet as full parameters under the names the results use (preset name, spec name or field
// path); by default the 16 feet of seed 001 section 9.2 against the point foot.
TEST(ResolvedSpec, AFootComparisonSpellsOutEveryFootAndTheSweepDefaults) {
  const nlohmann::json r = resolved_fixed_point(
      {{"scene", "walker"}, {"task", "foot_comparison"}, {"speeds", "0.5:0.5:1.0"}});
  std::printf("resolved foot_comparison spec: %zu bytes\n", r.dump().size());
  EXPECT_EQ(keys(r), (std::set<std::string>{"scene", "task", "speeds", "objective", "points", "bezier_degree",
                                            "quadrature", "positive_power_band", "solver", "multistart", "reference", "feet",
                                            "continuation"}));
  EXPECT_EQ(r["reference"], (nlohmann::json{{"model", "point"}, {"name", "point"}}));
  const auto section_9_2 = foot::select_fitted_feet({.section_9_2_only = true});
  ASSERT_EQ(r["feet"].size(), section_9_2.size());
  for (std::size_t k = 0; k < section_9_2.size(); ++k) {
    nlohmann::json expected = io::to_json(section_9_2[k]->spec);
    expected["name"] = section_9_2[k]->name();
    EXPECT_EQ(r["feet"][k], expected);
  }
  EXPECT_EQ(r["speeds"], (nlohmann::json{0.5, 1.0}));
  EXPECT_EQ(r["points"], 200);
  EXPECT_EQ(r["bezier_degree"], 6);
  EXPECT_EQ(r["objective"], "f_mech");
  EXPECT_EQ(r["quadrature"], "trapezoid");
  EXPECT_EQ(r["positive_power_band"], 0.0);  // the seed's positive part (5.100)
  EXPECT_EQ(r["solver"], (nlohmann::json{{"solver", "sqp"}, {"max_iterations", 2000}, {"optimality_tolerance", 1e-5},
                                         {"constraint_tolerance", 1e-10}, {"print_level", 0}}));
  EXPECT_EQ(r["multistart"], (nlohmann::json{{"starts", 20}, {"seed", 1}, {"scale", 0.05}}));
  EXPECT_EQ(r["continuation"]["seed_speeds"], (nlohmann::json{0.3, 1.3, 2.3}));
  EXPECT_TRUE(r["continuation"].contains("min_trust_region"));
  EXPECT_EQ(service::random_seeds(r), (nlohmann::json{{"multistart.seed", 1}}));

  nlohmann::json unnamed = io::to_json(foot::foot_preset("P1-barefoot-left-HM").spec);
  unnamed.erase("name");
  const nlohmann::json given = resolved_fixed_point(
      {{"scene", "walker"}, {"task", "foot_comparison"}, {"speeds", {0.8, 1.2}}, {"reference", "P1-shoes-left-HMT-SG"},
       {"feet", {"P1-shoes-left-HM-SG", unnamed}}, {"multistart", {{"seed", 5}}}});
  EXPECT_EQ(given["reference"]["name"], "P1-shoes-left-HMT-SG");
  EXPECT_EQ(given["reference"]["model"], "HMT");
  ASSERT_EQ(given["feet"].size(), 2u);
  EXPECT_EQ(given["feet"][0]["name"], "P1-shoes-left-HM-SG");
  EXPECT_EQ(given["feet"][1]["name"], "feet[1]");
  EXPECT_EQ(service::random_seeds(given), (nlohmann::json{{"multistart.seed", 5}}));
}

// Every option of the method: the bezier ones and the solver, or the seed method's weights,
// tolerance and Nelder-Mead settings.
TEST(ResolvedSpec, AGiantSwingSpellsOutEveryOptionOfItsMethod) {
  const nlohmann::json bezier = resolved_fixed_point({{"scene", "giant_swing"}, {"task", "giant_swing"}, {"motion", "periodic"}});
  std::printf("resolved giant_swing spec: %s\n", bezier.dump().c_str());
  EXPECT_EQ(keys(bezier), (std::set<std::string>{"scene", "task", "motion", "method", "options", "solver"}));
  EXPECT_EQ(bezier["method"], "bezier");
  EXPECT_EQ(keys(bezier["options"]),
            (std::set<std::string>{"name", "omega_deg_s", "initial_rate_deg_s", "rounds", "alpha_min_deg", "alpha_max_deg",
                                   "free_coefficients", "steps", "min_rate_fraction"}));
  EXPECT_EQ(bezier["options"]["name"], "periodic_sequence");  // the task's default name
  EXPECT_EQ(bezier["options"]["rounds"], 10);
  EXPECT_EQ(bezier["options"]["free_coefficients"], 8);
  EXPECT_EQ(bezier["options"]["steps"], 200);
  EXPECT_EQ(bezier["options"]["min_rate_fraction"], 0.05);
  EXPECT_EQ(bezier["solver"]["solver"], "ipopt");
  EXPECT_EQ(bezier["solver"]["max_iterations"], 200);
  EXPECT_EQ(bezier["solver"]["optimality_tolerance"], 1e-8);
  EXPECT_EQ(service::random_seeds(bezier), nlohmann::json::object());

  const nlohmann::json spec = {{"scene", "giant_swing"}, {"task", "giant_swing"}, {"motion", "accelerating"},
                               {"method", "seed"}, {"options", {{"omega_deg_s", 40}, {"weights", {{"jerk", 0.01}}}}}};
  const nlohmann::json seed = resolved_fixed_point(spec);
  EXPECT_EQ(keys(seed), (std::set<std::string>{"scene", "task", "motion", "method", "options"}));  // no NLP solver
  EXPECT_EQ(keys(seed["options"]), (std::set<std::string>{"name", "omega_deg_s", "initial_rate_deg_s", "rounds", "alpha_min_deg",
                                                          "alpha_max_deg", "weights", "relative_tolerance", "optimiser"}));
  EXPECT_EQ(seed["options"]["weights"]["jerk"], 0.01);
  EXPECT_EQ(seed["options"]["optimiser"]["support_points"], 4);
  // The same task, to the last bit.
  const jobs::GiantSwingJob submitted = jobs::parse_giant_swing_job(spec, {});
  const jobs::GiantSwingJob resolved = jobs::parse_giant_swing_job(seed, {});
  EXPECT_EQ(resolved.task.omega, submitted.task.omega);
  EXPECT_EQ(resolved.task.initial_rate, submitted.task.initial_rate);
  EXPECT_EQ(resolved.task.ranges.alpha_min, submitted.task.ranges.alpha_min);
  EXPECT_EQ(resolved.task.ranges.alpha_max, submitted.task.ranges.alpha_max);
  EXPECT_EQ(service::random_seeds(seed), nlohmann::json::object());
}

TEST(ResolvedSpec, AFootFitSpellsOutItsTrialsAndTheToeBound) {
  const foot::FootSpec foot = foot::foot_preset("P1-shoes-left-HMT").spec;
  foot_fit::SyntheticTrialOptions o;
  o.foot_angle = foot_fit::default_foot_angle_history(foot);
  const std::vector<foot_fit::AnkleTrack> tracks = {foot_fit::ankle_track(foot_fit::synthetic_trial(foot, o))};
  nlohmann::json spec = io::foot_fit_job_spec(tracks);
  spec.erase("toe_bound");
  const nlohmann::json r = resolved_fixed_point(spec);
  EXPECT_EQ(keys(r), (std::set<std::string>{"scene", "task", "trials", "toe_bound"}));
  EXPECT_EQ(r["toe_bound"], true);
  EXPECT_EQ(r["trials"], spec["trials"]);  // as submitted (at the 10 um of foot_fit_job_spec)
  EXPECT_EQ(service::random_seeds(r), nlohmann::json::object());
}

// The start foot as given (full parameters), the free foot parameters and bounds (10.1), every
// design and sweep field.
TEST(ResolvedSpec, AFootDesignSpellsOutItsStartFootDesignAndSweepFields) {
  const nlohmann::json r = resolved_fixed_point({{"scene", "walker"}, {"task", "foot_design"}});
  EXPECT_EQ(r["foot"], io::to_json(foot::foot_preset("P2-shoes-left-HMT").spec));
  for (const char* key : {"speeds", "free_parameters", "design_bounds", "densities", "design_speed", "references",
                          "sweep_starts", "foot_scale", "continuation", "solver", "multistart", "points", "bezier_degree"})
    EXPECT_TRUE(r.contains(key)) << key << " missing in " << r.dump();
  EXPECT_EQ(r["design_speed"], 2.3);
  EXPECT_EQ(r["continuation"]["seed_speeds"], (nlohmann::json{0.3, 1.3, 2.3}));
  EXPECT_EQ(service::random_seeds(r), (nlohmann::json{{"multistart.seed", 1}}));
}

TEST(ResolvedSpec, SeedsAreTheFieldsNamedSeed) {
  EXPECT_EQ(service::random_seeds({{"multistart", {{"seed", 7}, {"starts", 3}}}, {"seed_speeds", {1}}}),
            (nlohmann::json{{"multistart.seed", 7}}));
  EXPECT_EQ(service::random_seeds({{"speed", 1.0}}), nlohmann::json::object());
}

// Every kind resolves its spec: a kind without resolve is not registered.
TEST(ResolvedSpec, AKindWithoutAResolverIsRefused) {
  service::JobKind kind = *jobs::builtin_job_kinds().find("foot_sweep");
  kind.resolve = {};
  service::JobKindRegistry registry;
  EXPECT_THROW(registry.add(kind), std::logic_error);
}

// Re-running what a job found: an optimise job at the same speed, started from the optimum an
// optimise job stored, converges where it started (a KKT point is one from its first iterate; how
// many iterations the SQP takes to estimate the multipliers there is its path, not asserted).
TEST_F(ReproducibleJobs, AnOptimiseStartedFromAStoredOptimumConvergesWhereItStarted) {
  const nlohmann::json first = {{"scene", "walker"}, {"task", "optimise"}, {"foot", "point"}, {"speed", 1.0},
                                {"solver", {{"max_iterations", 600}}}};
  const auto rows = run_job("repro-first", first, 1);
  ASSERT_EQ(rows.size(), 1u);
  const int first_iterations = rows[0]["iterations"].get<int>();
  ASSERT_EQ(rows[0]["status"], "converged");
  const std::vector<double> x = rows[0]["values"]["x"].get<std::vector<double>>();
  ASSERT_EQ(x.size(), 20u);  // point feet: (M - 1) n_b = 5 x 4, no free parameters
  nlohmann::json again = first;
  again["start"] = {{"job", 1}, {"point", 0}};
  const auto rerun = run_job("repro-again", again, 1);
  ASSERT_EQ(rerun.size(), 1u);
  const int iterations = rerun[0]["iterations"].get<int>();
  std::printf("optimise from the starting gait: %d iterations; from job 1's optimum: %d\n", first_iterations, iterations);
  EXPECT_EQ(rerun[0]["status"], "converged");
  EXPECT_NEAR(rerun[0]["objective"].get<double>(), rows[0]["objective"].get<double>(), 1e-8);
  const std::vector<double> x_again = rerun[0]["values"]["x"].get<std::vector<double>>();
  ASSERT_EQ(x_again.size(), x.size());
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(x_again[i], x[i], 1e-6) << "x[" << i << "]";
  server::Server srv(config_, kinds_, lcm_);
  const storage::JobRecord job = *srv.store().job(2);
  EXPECT_EQ(nlohmann::json::parse(job.spec_json)["start"], again["start"]);  // as submitted
  EXPECT_EQ(nlohmann::json::parse(job.resolved_spec_json)["start"], x);       // what it ran from
  EXPECT_EQ(service::runnable_spec_text(job), job.resolved_spec_json);  // a resumed job needs no lookup
}

class StoredStartReferences : public testing::MemqServerTest {
 protected:
  void SetUp() override {
    MemqServerTest::SetUp();
    store_ = std::make_unique<storage::ResultStore>(config_.database);
    // job 1: an optimised point-foot gait (curve 0, point 0) and a point without x (curve 1, point 0)
    store_->submit("walker", "walker", "optimise", R"({"scene": "walker", "task": "optimise", "foot": "point", "speed": 1.0})");
    storage::SolutionPoint p;
    records::WalkerPointRecord walker_point;
    walker_point.x = std::vector<double>(20, 0.1);
    p.set_values(walker_point);
    store_->store_point(1, p);
    p.key = {1, 0};
    records::SweepBestRecord not_found;
    not_found.reason = "no gait found";
    p.set_values(not_found);
    store_->store_point(1, p);
    store_->submit("swing", "giant_swing", "giant_swing", R"({"scene": "giant_swing", "task": "giant_swing"})");  // job 2
  }

  // The SpecError of resolving `start` in an optimise spec ("field: message"), or "resolved".
  std::string rejection(const nlohmann::json& start, const std::string& foot = "point") {
    try {
      jobs::with_stored_start({{"scene", "walker"}, {"task", "optimise"}, {"foot", foot}, {"speed", 1.0}, {"start", start}},
                                 *store_);
    } catch (const SpecError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(e.field() + ": ", 0), 0u) << e.what();
      return e.what();  // "field: message"
    }
    return "resolved";
  }

  std::unique_ptr<storage::ResultStore> store_;
};

TEST_F(StoredStartReferences, AReferenceBecomesThePointsGaitParameters) {
  const nlohmann::json spec = {{"scene", "walker"}, {"task", "optimise"}, {"foot", "point"}, {"speed", 1.2},
                               {"start", {{"job", 1}, {"curve", 0}, {"point", 0}}}};
  EXPECT_EQ(jobs::with_stored_start(spec, *store_)["start"], std::vector<double>(20, 0.1));
  const nlohmann::json plain = {{"scene", "walker"}, {"task", "optimise"}, {"start", {1, 2}}};
  EXPECT_EQ(jobs::with_stored_start(plain, *store_), plain);  // an x list is left to the walker fields
}

TEST_F(StoredStartReferences, BadReferencesAreRejectedNamingTheField) {
  const auto starts_with = [](const std::string& text, const std::string& prefix) {
    return text.rfind(prefix, 0) == 0;
  };
  const std::map<std::string, nlohmann::json> cases = {
      {"start.job: there is no job 9", {{"job", 9}, {"point", 0}}},
      {"start.point: job 1 has no stored point (curve 0, point 4); it has 2", {{"job", 1}, {"point", 4}}},
      {"start.curve: job 1 has no stored point (curve 7, point 0)", {{"job", 1}, {"curve", 7}, {"point", 0}}},
      {"start.point: point (curve 1, point 0) of job 1 holds no gait parameters x", {{"job", 1}, {"curve", 1}, {"point", 0}}},
      {"start.job: job 2 is a giant_swing giant_swing job", {{"job", 2}, {"point", 0}}},
      {"start.job: is required", {{"point", 0}}},
      {"start.point: is required", {{"job", 1}}},
      {"start.job: must be in [1,", {{"job", 0}, {"point", 0}}},
      {"start.point: must be in [0,", {{"job", 1}, {"point", -1}}},
      {"start.index: unknown field", {{"job", 1}, {"index", 0}}},
  };
  for (const auto& [expected, start] : cases) {
    const std::string got = rejection(start);
    EXPECT_TRUE(starts_with(got, expected)) << "start " << start.dump() << ": " << got;
  }
  const std::string other_foot = rejection({{"job", 1}, {"point", 0}}, "P1-barefoot-left-HM");
  EXPECT_TRUE(starts_with(other_foot, "start.job: job 1 is for the foot model point, this job's foot is HM")) << other_foot;
  // The client, without the database, checks the reference's form and the rest of the spec.
  EXPECT_THROW(service::without_stored_start({{"start", {{"job", "seven"}, {"point", 0}}}}), SpecError);
  EXPECT_FALSE(service::without_stored_start({{"start", {{"job", 7}, {"point", 0}}}}).contains("start"));
}

}  // namespace
}  // namespace cyclopt
