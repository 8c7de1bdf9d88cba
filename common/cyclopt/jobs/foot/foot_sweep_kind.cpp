// Job kind "foot_sweep" (scene walker): the foot's mass properties (seed 001,
// appendix E) and its rolling kinematics over a grid of one foot parameter. Cheap, so the whole
// service can be exercised end-to-end before the walker optimisation kinds exist.
//
//   {"scene": "walker", "task": "foot_sweep",
//    "foot": "P2-shoes-left-HMT" | {foot spec, proto/schemas/foot.schema.json},
//    "sweep": {"parameter": "density" | a parameter of the foot model (e.g. "k_HM"),
//              "values": "lo:step:hi" | number | [numbers]},
//    "samples": 2..200 rolling-kinematics samples stored as each point's trajectory (default 13),
//    "point_delay_ms": 0..10000 extra wall time per point (default 0; for resume tests)}
//
// Every grid value must give a valid foot (checked by validate()); without a density in the
// foot, 36.9 kg/m^2 is used (seed 001, section 10.2). Each point (curve 0, point i) stores the
// foot's mass properties and admissible angles (records::FootMassRecord), objective = mass (kg),
// and the rolling samples as its trajectory (records::FootRollingRecord).
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/io/foot_report.hpp"
#include "cyclopt/io/foot_spec_json.hpp"
#include "cyclopt/jobs/foot/foot_kinds.hpp"
#include "cyclopt/records/foot_sweep_records.hpp"
#include "cyclopt/service/spec_fields.hpp"
#include "cyclopt/service/value_range.hpp"

#include <chrono>
#include <thread>

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

namespace {

constexpr double kDefaultFootDensity = 36.9;  // kg/m^2
constexpr int kMaxPointDelayMs = 10000;

struct FootSweep {
  foot::FootSpec base;
  std::string parameter;
  std::vector<double> values;
  int samples = 13;
  int point_delay_ms = 0;
};

// The foot at one grid value; throws SpecError (with the foot's own field names) if invalid.
foot::FootSpec foot_at(const FootSweep& s, double value) {
  foot::FootSpec f = s.base;
  if (s.parameter == "density") {
    f.density = value;
  } else {
    const auto layout = foot::parameter_layout(f.model);
    for (std::size_t i = 0; i < layout.size(); ++i)
      if (layout[i].name == s.parameter) f.parameters[static_cast<Eigen::Index>(i)] = value;
  }
  if (!f.density) f.density = kDefaultFootDensity;
  foot::validate(f);
  return f;
}

FootSweep parse(const nlohmann::json& spec, const CommonJobFields&) {
  FootSweep s;
  if (!spec.contains("foot")) throw SpecError("foot", "is required: a preset name or a foot spec object");
  s.base = io::foot_value(spec["foot"], "foot");
  if (!spec.contains("sweep")) throw SpecError("sweep", "is required: {\"parameter\": ..., \"values\": \"lo:step:hi\"}");
  const nlohmann::json& sw = object_value(spec["sweep"], "sweep");
  reject_unknown_keys(sw, "sweep", {"parameter", "values"});
  std::vector<std::string> names = {"density"};
  double lo = 1e-6, hi = foot::kMaxDensity;
  const auto layout = foot::parameter_layout(s.base.model);
  for (const auto& p : layout) names.emplace_back(p.name);
  if (!sw.contains("parameter")) throw SpecError("sweep.parameter", "is required (" + join(names) + ")");
  s.parameter = enum_value(sw["parameter"], "sweep.parameter", names);
  for (const auto& p : layout)
    if (p.name == s.parameter) lo = p.min, hi = p.max;
  if (!sw.contains("values")) throw SpecError("sweep.values", "is required: \"lo:step:hi\", a number or an array");
  s.values = parse_value_range(sw["values"], "sweep.values", lo, hi);
  s.samples = optional_integer(spec, "", "samples", 2, 200).value_or(s.samples);
  s.point_delay_ms = optional_integer(spec, "", "point_delay_ms", 0, kMaxPointDelayMs).value_or(0);
  for (std::size_t i = 0; i < s.values.size(); ++i) {
    try {
      foot_at(s, s.values[i]);
    } catch (const SpecError& e) {
      throw SpecError("sweep.values[" + std::to_string(i) + "]",
                      s.parameter + " = " + std::to_string(s.values[i]) + " gives an invalid foot: " + e.what());
    }
  }
  return s;
}

// Sleeps in short slices so a cancellation or shutdown is noticed within ~10 ms.
void delay(int ms, JobContext& ctx) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(ms);
  while (std::chrono::steady_clock::now() < until && ctx.stop_reason() == StopReason::none)
    std::this_thread::sleep_for(std::min<std::chrono::steady_clock::duration>(std::chrono::milliseconds(10),
                                                                              until - std::chrono::steady_clock::now()));
}

void run(const FootSweep& s, JobContext& ctx) {
  const int n = static_cast<int>(s.values.size());
  ctx.announce(n);
  ctx.add_curve(0, "foot sweep over " + s.parameter, s.parameter);
  const std::set<storage::PointKey> done = ctx.already_stored_points();
  int stored = static_cast<int>(done.size());
  for (int i = 0; i < n; ++i) {
    if (done.count({0, i})) continue;
    if (ctx.stop_reason() != StopReason::none) return;
    delay(s.point_delay_ms, ctx);
    if (ctx.stop_reason() != StopReason::none) return;
    const nlohmann::json report = io::foot_report(foot_at(s, s.values[i]), {.samples = s.samples});
    nlohmann::json mass = report["mass_properties"];
    mass["theta_min"] = report["admissible_theta"][0];
    mass["theta_max"] = report["admissible_theta"][1];
    const auto values = mass.get<records::FootMassRecord>();
    storage::SolutionPoint p;
    p.key = {0, i};
    p.parameter = s.values[i];
    p.set_values(values);
    p.objective = values.mass;
    p.constraint_violation = 0.0;
    p.iterations = 1;
    p.set_trajectory(report["rolling"].get<records::FootRollingRecord>());
    ctx.count_iterations(1);
    if (ctx.store_point(p)) ++stored;
    ctx.report_progress({.iteration = 1,
                         .objective = p.objective,
                         .constraint_violation = 0.0,
                         .parameter = p.parameter,
                         .curve_id = 0,
                         .points_done = stored,
                         .points_total = n,
                         .message = s.parameter + " = " + std::to_string(p.parameter)});
  }
}

// The resolved spec (resolved_spec.hpp): the foot as its full parameters (its density only when
// given: without it every grid value gets the default), the grid as its values.
nlohmann::json resolve(const FootSweep& s) {
  return {{"foot", io::to_json(s.base)},
          {"sweep", {{"parameter", s.parameter}, {"values", s.values}}},
          {"samples", s.samples},
          {"point_delay_ms", s.point_delay_ms}};
}

}  // namespace

JobKind foot_sweep_kind() {
  // No estimate: at most 10000 cheap grid points.
  return typed_job_kind<FootSweep>("foot_sweep", {"walker"}, {"foot", "sweep", "samples", "point_delay_ms"}, parse, run,
                                   resolve);
}

}  // namespace cyclopt::jobs
