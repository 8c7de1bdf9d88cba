// Golden check of the stored results (issue 55, acceptance 1): one small job of every kind runs
// through an in-process server over memq://, and what it stored - every row of `solutions`
// (parameter, objective, constraint violation, iterations, status, required, values), `curves`
// and `trajectories`, and the job's state and point counts - must equal, as parsed JSON,
// tests/service/data/golden_jobs.json, which the default build (CYCLOPT_ARCH x86-64-v3) wrote.
// A redesign of the layers between the spec and the store must not move a single stored value.
//
// Left out of the comparison, as they differ from run to run: row ids, solved_at and every value
// whose key ends in "seconds" (wall times). A trajectory is compared by a digest of its parsed
// JSON (the blobs would make the file large), its rows in full.
//
// Solver paths follow the last bits of the arithmetic: another instruction-set level (x86-64-v2,
// native) may reach other optima, and the test says it is skipped there. A change that moves
// stored results on purpose rewrites the file:
//   CYCLOPT_WRITE_GOLDEN_JOBS=1 build/tests/service/test_golden_jobs
// in the default build, and the commit says why the results moved.
#include "cyclopt/cli/version.hpp"
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/foot_fit/ankle_track.hpp"
#include "cyclopt/foot_fit/synthetic_trials.hpp"
#include "cyclopt/io/foot_fit_json.hpp"
#include "cyclopt/storage_read/sqlite_handle.hpp"
#include "memq_server_fixture.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace cyclopt {
namespace {

constexpr const char* kGoldenArch = "x86-64-v3";
const std::string kGoldenFile = std::string(CYCLOPT_SOURCE_DIR) + "/tests/service/data/golden_jobs.json";

nlohmann::json walker(const std::string& task) {
  return {{"scene", "walker"}, {"task", task}, {"foot", "point"}, {"points", 25}, {"solver", {{"max_iterations", 600}}}};
}

// Two trials of a known foot (cyclopt-foot synth), as the client submits their ankle tracks.
nlohmann::json foot_fit_spec() {
  const foot::FootSpec spec = foot::foot_preset("P1-shoes-left-HMT").spec;
  std::vector<foot_fit::AnkleTrack> tracks;
  for (int k = 0; k < 2; ++k) {
    foot_fit::SyntheticTrialOptions o;
    o.noise = 0.0005;
    o.offset = 0.4 + 0.11 * k;
    o.seed = 1 + k;
    o.foot_angle = foot_fit::default_foot_angle_history(spec);
    o.source = "trial" + std::to_string(k + 1);
    tracks.push_back(foot_fit::ankle_track(foot_fit::synthetic_trial(spec, o)));
  }
  return io::foot_fit_job_spec(tracks);
}

// One job of every kind, small: point feet at P = 25 where a kind takes one walker; the rolling
// feet of the comparison at P = 40, where their solves converge in a few seconds, and the design at
// P = 50, where its two-start design multistart finds an admissible foot: on other grids its best
// optimum may exploit the quadrature (design_class.hpp, "under-resolved") or none converge in 500
// iterations (P = 60 and 80 with this build's paths), and the job would end with no admissible
// foot, storing none of the design's later phases - a golden record that covers less.
std::vector<std::pair<std::string, nlohmann::json>> golden_specs() {
  std::vector<std::pair<std::string, nlohmann::json>> specs;
  specs.emplace_back("foot_sweep", nlohmann::json{{"scene", "walker"}, {"task", "foot_sweep"}, {"foot", "P2-shoes-left-HMT"},
                                                  {"sweep", {{"parameter", "density"}, {"values", "20:20:60"}}}, {"samples", 5}});
  nlohmann::json evaluate = walker("evaluate");
  evaluate["speed"] = 1.0;
  specs.emplace_back("evaluate", evaluate);
  nlohmann::json optimise = walker("optimise");
  optimise["speed"] = 1.0;
  specs.emplace_back("optimise", optimise);
  nlohmann::json multistart = walker("multistart");
  multistart["speed"] = 1.0;
  multistart["multistart"] = {{"starts", 3}, {"seed", 2}, {"scale", 0.05}};
  specs.emplace_back("multistart", multistart);
  nlohmann::json continuation = walker("continuation");
  continuation["speeds"] = "1.0:0.1:1.2";
  specs.emplace_back("continuation", continuation);
  nlohmann::json sweep = walker("sweep");
  sweep["speeds"] = "0.9:0.1:1.1";
  sweep["multistart"] = {{"starts", 2}, {"seed", 3}, {"scale", 0.02}};
  sweep["continuation"] = {{"seed_speeds", 1.0}};
  specs.emplace_back("sweep", sweep);
  nlohmann::json sensitivity = walker("sensitivity");
  sensitivity["speed"] = 1.0;
  sensitivity["parameters"] = {"m_T"};
  sensitivity["steps"] = 1;
  specs.emplace_back("sensitivity", sensitivity);
  nlohmann::json comparison = walker("foot_comparison");
  comparison.erase("foot");
  comparison["speeds"] = "1.0:0.1:1.1";
  comparison["points"] = 40;
  comparison["feet"] = {"P1-barefoot-left-HM"};
  comparison["multistart"] = {{"starts", 2}, {"seeds", {3, 4}}, {"scale", 0.02}};
  comparison["continuation"] = {{"seed_speeds", 1.0}};
  specs.emplace_back("foot_comparison", comparison);
  specs.emplace_back("foot_design", nlohmann::json{{"scene", "walker"},
                                                   {"task", "foot_design"},
                                                   {"foot", "P2-shoes-left-HMT"},
                                                   {"speeds", "2.2:0.1:2.3"},
                                                   {"densities", {10}},
                                                   {"design_speed", 2.3},
                                                   {"points", 50},
                                                   {"solver", {{"max_iterations", 500}}},
                                                   {"multistart", {{"starts", 2}, {"seed", 2}, {"scale", 0.02}}},
                                                   {"sweep_starts", 1},
                                                   {"foot_scale", 0},
                                                   {"continuation",
                                                    {{"seed_speeds", 2.3}, {"min_trust_region", 0.05}, {"corrector_max_iterations", 60}}}});
  specs.emplace_back("foot_fit", foot_fit_spec());
  specs.emplace_back("giant_swing", nlohmann::json{{"scene", "giant_swing"}, {"task", "giant_swing"}, {"motion", "single"},
                                                   {"method", "bezier"}, {"options", {{"free_coefficients", 4}, {"steps", 50}}}});
  return specs;
}

// `j` without the members whose key ends in "seconds", at any depth.
nlohmann::json without_timings(nlohmann::json j) {
  if (j.is_object()) {
    nlohmann::json out = nlohmann::json::object();
    for (auto& [key, value] : j.items())
      if (key.size() < 7 || key.compare(key.size() - 7, 7, "seconds") != 0) out[key] = without_timings(value);
    return out;
  }
  if (j.is_array())
    for (nlohmann::json& e : j) e = without_timings(e);
  return j;
}

// FNV-1a (64 bit) of the canonical text of parsed JSON: equal exactly when the documents are.
std::string digest(const nlohmann::json& j) {
  std::uint64_t h = 14695981039346656037ull;
  for (const char c : j.dump()) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

nlohmann::json real_or_null(const storage::Statement& q, int col) {
  return q.is_null(col) ? nlohmann::json(nullptr) : nlohmann::json(q.real(col));
}

// What job `id` stored, in the form of the golden file.
nlohmann::json stored_job(const std::string& database, std::int64_t id) {
  const storage::Connection db(database, true);
  nlohmann::json job;
  storage::Statement row(db, "SELECT state, points_total, points_converged, error FROM jobs WHERE id = ?");
  row.bind(1, id);
  if (!row.step()) return job;
  job["state"] = row.text(0);
  job["points_total"] = row.is_null(1) ? nlohmann::json(nullptr) : nlohmann::json(row.int64(1));
  job["points_converged"] = row.is_null(2) ? nlohmann::json(nullptr) : nlohmann::json(row.int64(2));
  job["error"] = row.text(3);
  job["curves"] = nlohmann::json::array();
  storage::Statement curves(db, "SELECT curve_index, name, parameter_name FROM curves WHERE job_id = ? ORDER BY curve_index");
  curves.bind(1, id);
  while (curves.step()) job["curves"].push_back({{"curve", curves.int64(0)}, {"name", curves.text(1)}, {"parameter_name", curves.text(2)}});
  job["solutions"] = nlohmann::json::array();
  storage::Statement solutions(db,
                               "SELECT curve_index, point_index, parameter, objective, constraint_violation, iterations, "
                               "status, required, values_json FROM solutions WHERE job_id = ? ORDER BY curve_index, point_index");
  solutions.bind(1, id);
  while (solutions.step())
    job["solutions"].push_back({{"curve", solutions.int64(0)},
                                {"point", solutions.int64(1)},
                                {"parameter", real_or_null(solutions, 2)},
                                {"objective", real_or_null(solutions, 3)},
                                {"constraint_violation", real_or_null(solutions, 4)},
                                {"iterations", solutions.int64(5)},
                                {"status", solutions.text(6)},
                                {"required", solutions.int64(7)},
                                {"values", without_timings(nlohmann::json::parse(solutions.text(8)))}});
  job["trajectories"] = nlohmann::json::array();
  storage::Statement trajectories(db,
                                  "SELECT s.curve_index, s.point_index, t.format, t.data FROM trajectories t JOIN solutions s "
                                  "ON s.id = t.solution_id WHERE s.job_id = ? ORDER BY s.curve_index, s.point_index");
  trajectories.bind(1, id);
  while (trajectories.step())
    job["trajectories"].push_back({{"curve", trajectories.int64(0)},
                                   {"point", trajectories.int64(1)},
                                   {"format", trajectories.text(2)},
                                   {"digest", digest(without_timings(nlohmann::json::parse(trajectories.text(3))))}});
  return job;
}

using GoldenJobs = testing::MemqServerTest;

TEST_F(GoldenJobs, EveryKindStoresTheGoldenRows) {
  if (std::string(cli::build_arch()) != kGoldenArch)
    GTEST_SKIP() << "the golden rows were stored by the default " << kGoldenArch << " build; this build targets "
                 << cli::build_arch() << ", whose solver paths may reach other optima";
  std::vector<std::pair<std::string, std::int64_t>> jobs;
  {
    server::Server srv(config_, kinds_, lcm_);
    for (const auto& [task, spec] : golden_specs()) {
      const auto ack = client_.submit("golden-" + task, spec.dump(), 5.0);
      ASSERT_TRUE(ack && ack->accepted) << task << ": " << (ack ? ack->problem : "no ack");
      jobs.emplace_back(task, ack->job_id);
    }
    for (const auto& [task, id] : jobs) {
      const auto t0 = std::chrono::steady_clock::now();
      const auto done = client_.watch(id, [](const cyclopt_lcm::job_progress_t&) {}, 400.0);
      ASSERT_TRUE(done) << task;
      std::printf("%-16s %-10s %3d points (waited %.1f s)\n", task.c_str(), done->state.c_str(), done->points_stored,
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
  }
  nlohmann::json stored = nlohmann::json::object();
  for (const auto& [task, id] : jobs) stored[task] = stored_job(config_.database, id);
  if (std::getenv("CYCLOPT_WRITE_GOLDEN_JOBS")) {
    const nlohmann::json doc = {{"arch", cli::build_arch()}, {"revision", cli::git_revision()}, {"jobs", stored}};
    std::ofstream(kGoldenFile) << doc.dump(1) << "\n";
    GTEST_SKIP() << "wrote " << kGoldenFile;
  }
  std::ifstream in(kGoldenFile);
  ASSERT_TRUE(in.good()) << kGoldenFile;
  const nlohmann::json golden = nlohmann::json::parse(in)["jobs"];
  ASSERT_EQ(golden.size(), stored.size());
  for (const auto& [task, expected] : golden.items()) {
    ASSERT_TRUE(stored.contains(task)) << task;
    const nlohmann::json& got = stored[task];
    for (const char* key : {"state", "points_total", "points_converged", "error"}) EXPECT_EQ(got[key], expected[key]) << task << " " << key;
    for (const char* table : {"curves", "solutions", "trajectories"}) {
      ASSERT_EQ(got[table].size(), expected[table].size()) << task << " " << table;
      for (std::size_t i = 0; i < expected[table].size(); ++i)
        EXPECT_EQ(got[table][i], expected[table][i]) << task << " " << table << " row " << i << ":\n  stored " << got[table][i].dump().substr(0, 600)
                                                     << "\n  golden " << expected[table][i].dump().substr(0, 600);
    }
  }
}

}  // namespace
}  // namespace cyclopt
