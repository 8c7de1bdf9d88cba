// cyclopt-python-reference: what the C++ libraries compute, for the Python package's tests
// (tests/python/) and its overhead benchmark (bench/python_overhead.py) to hold it against.
//
//   cyclopt-python-reference evaluate SPEC_JSON [REPEATS]
//     SPEC_JSON: the walker fields of a one-speed job spec, as cyclopt.evaluate_gait sends them.
//     Prints JSON: the starting gait's "x" at the speed, the "gait" and "trajectory" records
//     (records/gait_records.hpp) evaluated there (shortest round-trip decimals, so exact), and the
//     mean seconds of one evaluation over REPEATS calls (default 0: not timed): "evaluate_seconds"
//     for GaitEvaluator::evaluate with trajectories, "call_seconds" for that and the records a
//     stored point holds (its scene, the evaluator, built once as the package keeps it).
//   cyclopt-python-reference store DB POINTS SEED
//     Fills DB with a finished walker sweep of POINTS points through the store API: gaits of the
//     point foot evaluated at random gait parameters near the starting gait at 1.0 m/s
//     (walker::perturbed_gait, scale 0.01), stored as the walker job kinds store them
//     (jobs::walker_point; trajectories for the first 3 points only). Prints JSON: "job_id" and,
//     for at most 200 points, their "points" (curve, point, parameter, gait record).
//   cyclopt-python-reference forge-done JOB_ID COUNT
//     Publishes COUNT unsigned job_done_t messages ("done") for JOB_ID on $LCM_DEFAULT_URL, one
//     every 0.1 s: a forgery that a client holding a key must ignore.
#include "cyclopt/jobs/walker/walker_job_spec.hpp"
#include "cyclopt/jobs/walker/walker_points.hpp"
#include "cyclopt/jobs/walker/walker_records.hpp"
#include "cyclopt/service/common_job_fields.hpp"
#include "cyclopt/storage/result_store.hpp"
#include "cyclopt_channels.hpp"
#include "message_bus.hpp"
#include "wire_check.hpp"

#include <cyclopt_lcm/job_done_t.hpp>
#include <lcm/lcm-cpp.hpp>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <random>
#include <string>
#include <thread>

using namespace cyclopt;

namespace {

jobs::WalkerJob walker_job(const nlohmann::json& spec) {
  return jobs::parse_walker_job(spec, service::parse_common_job_fields(spec), false);
}

template <class F>
double mean_seconds(int repeats, F&& call) {
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < repeats; ++i) call();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / repeats;
}

int evaluate(const std::string& spec_text, int repeats) {
  const nlohmann::json spec = nlohmann::json::parse(spec_text);
  const jobs::WalkerJob job = walker_job(spec);
  const walker::GaitEvaluator evaluator(job.model());
  const Eigen::VectorXd x = walker::gait_start(evaluator, job.speeds.at(0), job.start).x;
  const walker::PeriodicGait<double> gait = evaluator.evaluate(x, job.gait_options(job.speeds.at(0)));
  nlohmann::json out = {{"x", std::vector<double>(x.data(), x.data() + x.size())}, {"gait", jobs::gait_record(gait)}};
  if (const auto t = jobs::trajectory_record(gait.trajectory)) out["trajectory"] = *t;
  if (repeats > 0) {
    out["call_seconds"] = mean_seconds(repeats, [&] {
      const walker::PeriodicGait<double> g = evaluator.evaluate(x, job.gait_options(job.speeds.at(0)));
      const records::GaitRecord r = jobs::gait_record(g);
      const auto t = jobs::trajectory_record(g.trajectory);
      if (!r.real && t) std::abort();  // keeps the records from being optimised away
    });
    out["evaluate_seconds"] = mean_seconds(repeats, [&] {
      if (!evaluator.evaluate(x, job.gait_options(job.speeds.at(0))).real) std::abort();
    });
    out["repeats"] = repeats;
  }
  std::cout << out.dump() << "\n";
  return 0;
}

int store(const std::string& path, int points, unsigned seed) {
  const nlohmann::json spec = {{"scene", "walker"}, {"task", "optimise"}, {"foot", "point"}, {"speed", 1.0}};
  const jobs::WalkerJob job = walker_job(spec);
  const walker::GaitEvaluator evaluator(job.model());
  const walker::GaitStart start = walker::gait_start(evaluator, 1.0, std::nullopt);
  storage::ResultStore store(path);
  const std::int64_t id = store.submit("python-reference-" + std::to_string(seed), "walker", "sweep", spec.dump()).job_id;
  store.claim_next();
  store.add_curve(id, 0, "random gaits near the starting gait", "speed");
  std::mt19937_64 rng(seed);
  nlohmann::json shown = nlohmann::json::array();
  for (int i = 0; i < points; ++i) {
    walker::GaitOptions o = job.gait_options(1.0);
    o.keep_trajectories = i < 3;
    const walker::GaitStart near{walker::perturbed_gait(evaluator, start.x, 0.01, rng), "perturbed starting gait"};
    const walker::PeriodicGait<double> gait = evaluator.evaluate(near.x, o);
    const jobs::WalkerPoint p = jobs::walker_point(gait, near, {0, i}, gait.mean_speed);
    store.store_point(id, p.stored());
    if (i < 200) {
      nlohmann::json row = {{"curve", 0}, {"point", i}, {"parameter", gait.mean_speed}, {"gait", *p.values.gait}};
      if (p.trajectory) row["trajectory"] = *p.trajectory;
      shown.push_back(row);
    }
  }
  store.finish(id, storage::JobState::done, "", 0.0, 0.0, points);
  std::cout << nlohmann::json{{"job_id", id}, {"points", shown}}.dump() << "\n";
  return 0;
}

int forge_done(std::int64_t job_id, int count) {
  lcm::LCM lcm(wire::resolved_lcm_url(""));
  if (!lcm.good()) throw std::runtime_error("cannot open LCM");
  cyclopt_lcm::job_done_t m;
  m.job_id = job_id;
  m.request_id = "forged";
  m.state = "done";
  m.points_expected = m.points_converged = -1;
  const std::string bytes = wire::encode(m);
  for (int i = 0; i < count; ++i) {
    lcm.publish(channels::kDone, bytes.data(), static_cast<unsigned>(bytes.size()));
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  try {
    if (mode == "evaluate" && (argc == 3 || argc == 4)) return evaluate(argv[2], argc == 4 ? std::stoi(argv[3]) : 0);
    if (mode == "forge-done" && argc == 4) return forge_done(std::stoll(argv[2]), std::stoi(argv[3]));
    if (mode == "store" && argc == 5) return store(argv[2], std::stoi(argv[3]), static_cast<unsigned>(std::stoul(argv[4])));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cyclopt-python-reference: %s\n", e.what());
    return 1;
  }
  std::fprintf(stderr, "usage: cyclopt-python-reference evaluate SPEC_JSON [REPEATS] | store DB POINTS SEED | forge-done JOB_ID COUNT\n");
  return 2;
}
