// The 16-foot comparison of seed 001 section 9.2 end to end as one foot_comparison job (the job
// kind's run() on an in-memory job context, as a worker runs it), with its wall time, and the
// mean saving of the best fitted foot against point feet beside the seed's ~60 % (64 % for P2
// shoes HMT, section 9.2.3). The feet are swept as the server's local executor sweeps them: as
// many at once as the machine has cores (run_units_in_parallel). Writes the job document (as `cyclopt export` would) and the two
// figures (foot_comparison, foot_outlines) into OUT_DIR.
//
//   foot_comparison_bench SPEEDS STARTS SEED_SPEEDS POINTS OUT_DIR [FEET]
//     SPEEDS "0.3:0.1:2.3"; STARTS per seed speed (seed: 20); SEED_SPEEDS "0.3,1.3,2.3" style
//     list or range; POINTS the grid size P (eq. 5.93, default of the service 200); FEET
//     comma-separated preset names (default: the 16 of section 9.2)
#include "machine_info.hpp"

#include "cyclopt/plot/foot_comparison_figures.hpp"
#include "cyclopt/jobs/foot/foot_kinds.hpp"
#include "cyclopt/service/job_spec.hpp"
#include "cyclopt/jobs/walker/sweep_checkpoints.hpp"
#include "cyclopt/service/unit_job_context.hpp"

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

namespace {

using namespace cyclopt;

// Keeps every stored point in memory; never stops. Takes calls from the units' threads at once.
class MemoryJobContext final : public service::JobContext {
 public:
  explicit MemoryJobContext(int unit_threads) : unit_threads_(unit_threads) {}
  std::int64_t job_id() const override { return 1; }
  const service::JobLimits& limits() const override { return limits_; }
  // Prints a report whose message and phase differ from the last of its curve (feet swept at once
  // report in turns).
  void report_progress(const service::ProgressReport& r) override {
    const std::lock_guard<std::mutex> lock(mutex_);
    std::string& last = last_line_[r.curve_id];
    const std::string line = r.message + (r.phase.empty() ? "" : " - " + r.phase);
    if (line != last) std::fprintf(stderr, "[%7.1f s] %s\n", elapsed(), (last = line).c_str());
  }
  void count_iterations(int n) override { iterations += n; }
  void announce(int) override {}
  void add_curve(int index, const std::string& name, const std::string& parameter) override {
    curves.push_back({{"curve", index}, {"name", name}, {"parameter_name", parameter}});
  }
  bool store_point(const storage::SolutionPoint& p) override {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!keys_.insert(p.key).second) return false;
    solutions.push_back({{"curve", p.key.curve_index}, {"point", p.key.point_index},
                         {"parameter", std::isfinite(p.parameter) ? nlohmann::json(p.parameter) : nlohmann::json()},
                         {"objective", std::isfinite(p.objective) ? nlohmann::json(p.objective) : nlohmann::json()},
                         {"status", p.status}, {"values", p.values()}});
    return true;
  }
  std::set<storage::PointKey> already_stored_points() override {
    const std::lock_guard<std::mutex> lock(mutex_);
    return keys_;
  }
  // A foot's sweep summary (its unit's result checkpoint, foot_comparison_kind.hpp) is printed as
  // it arrives, so a run stopped before the last foot still shows the feet it swept.
  void store_checkpoint(const std::string& key, const std::string& value) override {
    const std::lock_guard<std::mutex> lock(mutex_);
    checkpoints_[key] = value;
    const std::string suffix = jobs::kSweptFootCheckpoint;
    if (key.size() < suffix.size() || key.compare(key.size() - suffix.size(), suffix.size(), suffix) != 0) return;
    const studies::FootSweepSummary s = jobs::foot_sweep_from_json(nlohmann::json::parse(value));
    std::string f_mech;
    for (const double f : s.f_mech) {
      char number[32] = " -";
      if (std::isfinite(f)) std::snprintf(number, sizeof number, " %.6f", f);
      f_mech += number;
    }
    std::printf("[%7.1f s] swept %s: %d speeds with a KKT point in %.1f s; f_mech per speed:%s\n", elapsed(),
                s.name.c_str(), s.speeds_found, s.seconds, f_mech.c_str());
    std::fflush(stdout);
  }
  std::map<std::string, std::string> stored_checkpoints() override {
    const std::lock_guard<std::mutex> lock(mutex_);
    return checkpoints_;
  }
  service::StopReason stop_reason() override { return service::StopReason::none; }
  void run_units(const std::vector<service::WorkUnit>& units, const service::UnitRun& run) override {
    service::run_units_in_parallel(units, run, *this, unit_threads_);
  }

  double elapsed() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count(); }
  std::atomic<long long> iterations{0};
  nlohmann::json curves = nlohmann::json::array(), solutions = nlohmann::json::array();

 private:
  int unit_threads_;
  service::JobLimits limits_{1e9, 2000000000};
  std::set<storage::PointKey> keys_;
  std::map<std::string, std::string> checkpoints_;
  std::mutex mutex_;
  std::map<int, std::string> last_line_;  // per curve
  std::chrono::steady_clock::time_point t0_ = std::chrono::steady_clock::now();
};

nlohmann::json list_or_range(const std::string& text) {
  if (text.find(':') != std::string::npos) return text;
  nlohmann::json a = nlohmann::json::array();
  std::stringstream ss(text);
  for (std::string item; std::getline(ss, item, ',');) a.push_back(std::stod(item));
  return a;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 6) {
    std::fprintf(stderr, "usage: foot_comparison_bench SPEEDS STARTS SEED_SPEEDS POINTS OUT_DIR [FEET,...]\n");
    return 1;
  }
  nlohmann::json spec = {{"scene", "walker"}, {"task", "foot_comparison"}, {"speeds", argv[1]},
                         {"multistart", {{"starts", std::stoi(argv[2])}}},
                         {"continuation", {{"seed_speeds", list_or_range(argv[3])}}},
                         {"points", std::stoi(argv[4])}};
  if (argc > 6) {
    spec["feet"] = nlohmann::json::array();
    std::stringstream ss(argv[6]);
    for (std::string name; std::getline(ss, name, ',');) spec["feet"].push_back(name);
  }
  const std::string out_dir = argv[5];
  service::JobKindRegistry kinds;
  kinds.add(jobs::foot_comparison_kind());
  const service::ValidatedJobSpec job = service::validate_job_spec(spec, kinds);
  std::printf("foot_comparison_bench: %s; %s at start\nspec: %s\n", bench::machine_line().c_str(),
              bench::load_average().c_str(), spec.dump().c_str());
  const int unit_threads = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  std::printf("feet swept %d at a time (the server's local executor with its default workers)\n", unit_threads);
  const double cpu0 = bench::cpu_seconds();
  MemoryJobContext ctx(unit_threads);
  job.run(ctx);
  const double wall = ctx.elapsed(), cpu = bench::cpu_seconds() - cpu0;
  std::printf("wall %.1f s, CPU %.1f s, %lld solver iterations; %s at end\n\n", wall, cpu, ctx.iterations.load(),
              bench::load_average().c_str());

  std::printf("%-26s %7s %11s %7s %9s %8s\n", "foot", "speeds", "mean f_mech", "common", "saving", "sweep s");
  nlohmann::json reference_row, best_row;
  for (const nlohmann::json& s : ctx.solutions) {
    const nlohmann::json& v = s["values"];
    if (!v.contains("foot_spec")) continue;
    const auto num = [&](const char* k) { return v[k].is_number() ? v[k].get<double>() : std::nan(""); };
    std::printf("%-26s %3d/%-3d %11.5f %7d %8.1f%% %8.1f%s\n", v["foot"].get<std::string>().c_str(),
                v["speeds_found"].get<int>(), v["speeds"].get<int>(), num("mean_f_mech"), v["common_speeds"].get<int>(),
                100.0 * num("saving"), num("sweep_seconds"),
                v["reference"].get<bool>() ? "  (reference)" : v["best_fitted"].get<bool>() ? "  <- best fitted foot" : "");
    if (v["reference"].get<bool>()) reference_row = v;
    if (v["best_fitted"].get<bool>()) best_row = v;
  }
  std::printf("\nbest foot per speed:\n%6s %-26s %9s %9s %8s\n", "v m/s", "foot", "f_mech", "point", "saving");
  for (const nlohmann::json& s : ctx.solutions) {
    if (s["curve"].get<int>() != 0) continue;
    const nlohmann::json& v = s["values"];
    const auto num = [&](const char* k) { return v.contains(k) && v[k].is_number() ? v[k].get<double>() : std::nan(""); };
    std::printf("%6.2f %-26s %9.5f %9.5f %7.1f%%\n", s["parameter"].get<double>(), v.value("foot", std::string("-")).c_str(),
                num("f_mech"), num("reference_f_mech"), 100.0 * num("saving"));
  }
  if (!best_row.is_null())
    std::printf("\nmean saving of the best fitted foot (%s) against point feet: %.1f %% over %d speeds "
                "(seed 001 section 9.2.3: about 60 %%, 64 %% for P2 shoes HMT)\n",
                best_row["foot"].get<std::string>().c_str(), 100.0 * best_row["saving"].get<double>(),
                best_row["common_speeds"].get<int>());
  if (!reference_row.is_null() && reference_row["envelope_saving"].is_number())
    std::printf("mean saving of the envelope (best foot per speed) against point feet: %.1f %% over %d speeds\n",
                100.0 * reference_row["envelope_saving"].get<double>(), reference_row["envelope_common_speeds"].get<int>());

  std::filesystem::create_directories(out_dir);
  const nlohmann::json document = {{"id", 1},           {"scene", "walker"},       {"task", "foot_comparison"},
                                   {"spec", spec},      {"curves", ctx.curves},    {"solutions", ctx.solutions}};
  std::ofstream(out_dir + "/foot_comparison_job.json") << document.dump() << "\n";
  for (const plot::Figure& f : plot::foot_comparison_figures(document)) {
    const std::vector<std::string> paths = plot::write_figure(f, out_dir);
    std::printf("figure %s: %s %s\n", f.name.c_str(), paths[0].c_str(), paths[1].c_str());
  }
  return 0;
}
