// Job kind "foot_design" (scene walker; issue 15 item 3, seed 001 section 10.2): the foot-geometry
// optimisation of studies/foot_design.hpp as a job. Per density of a list, a multistart at the
// design speed with foot and gait free from the start foot, the best admissible design, its
// free-foot continuation over the speeds (an optimal foot per speed, Fig. 10.2a), the fixed-foot
// sweeps of the designs optimal at the highest and the lowest speed, and their savings against
// the start foot and point feet.
//
//   {"scene": "walker", "task": "foot_design", "foot": "P2-shoes-left-HMT", "speeds": "0.3:0.1:2.3",
//    "densities": "10:10:70", "design_speed": 2.3, "multistart": {"starts": 20}, "sweep_starts": 20}
//
// foot: the start foot, HM or HMT (default P2-shoes-left-HMT), also the start-foot reference with
// its own masses; densities (kg/m^2, default 10:10:70); design_speed (m/s, one of the speeds,
// default 2.3); speeds (default 0.3:0.1:2.3); multistart: starts (default 20), seed and scale of
// the design multistart, seed and scale of the sweeps too; sweep_starts: multistart runs per seed
// speed of every fixed-foot sweep (default 20); foot_scale: the spread of the feet the design
// starts draw around the start foot (studies::FootDesignOptions::foot_scale, default 1, 0: none);
// free_parameters: the foot parameters designed
// (default all of the model's; only foot parameters); design_bounds: (10.1) (walker/design_bounds_spec.hpp,
// default the seed's); references: sweep the start foot and point feet (default true; false: no
// savings); continuation: seed_speeds and min_trust_region of the sweeps and the continuation;
// points, bezier_degree, quadrature, objective, solver as for a sweep. Bad densities, bounds that
// exclude the start foot in a fixed parameter, a parameter the foot model does not have and a
// design speed off the grid are refused at submission, naming the field.
//
// Stored (records/foot_design_records.hpp): curve 0 one point per density (a DesignedFootRecord;
// status "no admissible design" where the multistart found none), curves 1, 2 the best point per
// speed of the start foot and point feet, per density k: curve 3 + 4k the multistart's optima
// (every class kept), 4 + 4k the free-foot continuation's points, 5 + 4k and 6 + 4k the best point
// per speed of the fixed-foot sweeps of the high- and low-speed designs. Each is stored when its
// phase ends; a resumed job replays the finished solves and runs from its checkpoints
// (walker/sweep_checkpoints.hpp) instead of solving them again.
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/io/foot_spec_json.hpp"
#include "cyclopt/jobs/foot/foot_kinds.hpp"
#include "cyclopt/jobs/solver_progress.hpp"
#include "cyclopt/jobs/walker/continuation_fields.hpp"
#include "cyclopt/jobs/walker/foot_sweep_points.hpp"
#include "cyclopt/jobs/walker/sweep_checkpoints.hpp"
#include "cyclopt/jobs/walker/walker_job_cost.hpp"
#include "cyclopt/jobs/walker/walker_job_json.hpp"
#include "cyclopt/jobs/walker/walker_job_spec.hpp"
#include "cyclopt/jobs/walker/walker_points.hpp"
#include "cyclopt/jobs/walker/walker_records.hpp"
#include "cyclopt/records/foot_design_records.hpp"
#include "cyclopt/service/spec_fields.hpp"
#include "cyclopt/service/unit_job_context.hpp"
#include "cyclopt/service/value_range.hpp"
#include "cyclopt/studies/foot_design.hpp"
#include "cyclopt/studies/optimum_sensitivities.hpp"
#include "cyclopt/studies/walker_family.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields
namespace {

constexpr const char* kDefaultStartFoot = "P2-shoes-left-HMT";  // seed 001 section 10.2
constexpr const char* kDefaultSpeeds = "0.3:0.1:2.3";
constexpr const char* kDefaultDensities = "10:10:70";             // kg/m^2
constexpr double kDefaultDesignSpeed = 2.3;                        // m/s, the highest of the grid
constexpr int kDefaultSweepStarts = 20;

struct DesignJob {
  WalkerJob walker;           // walker.foot: the start foot moved into (10.1); problem: foot free under (10.1)
  foot::FootSpec start_foot;  // as given: the start of every design and the start-foot reference
  // The study's options, filled from the spec (the job's observers are attached when it runs):
  // densities, design speed, the design multistart's starts, seed and scale, foot_scale, the
  // bounds and free parameters of walker.problem, references, known designs, and the sweeps'
  // options (their starts: sweep_starts).
  studies::FootDesignOptions design;
};

std::string number_text(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", x);
  return b;
}

std::vector<std::string> foot_parameter_names(foot::FootModel model) {
  std::vector<std::string> names;
  for (const foot::ParameterInfo& p : foot::parameter_layout(model)) names.emplace_back(p.name);
  return names;
}

DesignJob parse_design_job(const nlohmann::json& spec, const CommonJobFields& common_fields) {
  DesignJob j;
  nlohmann::json walker = spec;
  for (const char* key : {"densities", "design_speed", "references", "sweep_starts", "foot_scale", "continuation", "known_designs"})
    walker.erase(key);
  if (!walker.contains("foot")) walker["foot"] = kDefaultStartFoot;
  if (!walker.contains("speeds")) walker["speeds"] = kDefaultSpeeds;
  j.start_foot = io::foot_value(walker["foot"], "foot");
  if (j.start_foot.model == foot::FootModel::point)
    throw SpecError("foot", "the start foot must be a rolling foot (HM or HMT): point feet have no geometry to design");
  // Only the foot's geometry is designed (the density is set per design, the masses follow it).
  const std::vector<std::string> names = foot_parameter_names(j.start_foot.model);
  const std::string model(foot::to_string(j.start_foot.model));
  if (walker.contains("free_parameters")) {
    const nlohmann::json& fp = walker["free_parameters"];
    if (!fp.is_array() || fp.empty())
      throw SpecError("free_parameters", "must be a non-empty array of parameters of the " + model + " foot (" + join(names) + ")");
    for (std::size_t i = 0; i < fp.size(); ++i)
      if (!fp[i].is_string() || std::find(names.begin(), names.end(), fp[i].get<std::string>()) == names.end())
        throw SpecError("free_parameters[" + std::to_string(i) + "]",
                        fp[i].dump() + " is not a parameter of the " + model + " foot; admissible: " + join(names));
  } else {
    walker["free_parameters"] = studies::default_design_parameters(j.start_foot.model);
  }
  if (!walker.contains("design_bounds")) walker["design_bounds"] = nlohmann::json::object();  // the seed's (10.1)
  j.walker = parse_walker_job(walker, common_fields, true);
  if (j.walker.speeds.size() < 2) throw SpecError("speeds", "needs at least two values");
  studies::FootDesignOptions& design = j.design;
  design.starts = j.walker.starts;
  design.seed = j.walker.seeds.front();  // the design multistart's; the sweeps search once per seed
  design.scale = j.walker.scale;
  design.bounds = *j.walker.problem.design_bounds;
  design.free_parameters = j.walker.problem.free_parameters;
  design.constants = j.walker.constants;

  std::vector<double>& densities = design.densities;
  densities = parse_value_range(spec.contains("densities") ? spec["densities"] : nlohmann::json(kDefaultDensities),
                                "densities", foot::kMinDensity, foot::kMaxDensity);
  for (std::size_t i = 1; i < densities.size(); ++i)
    if (std::find(densities.begin(), densities.begin() + static_cast<std::ptrdiff_t>(i), densities[i]) !=
        densities.begin() + static_cast<std::ptrdiff_t>(i))
      throw SpecError("densities[" + std::to_string(i) + "]", "= " + number_text(densities[i]) + " kg/m^2 is listed twice");
  if (densities.size() > 100) throw SpecError("densities", "at most 100 densities");
  design.design_speed = spec.contains("design_speed")
                            ? number_value(spec["design_speed"], "design_speed", kMinWalkingSpeed, kMaxWalkingSpeed)
                            : kDefaultDesignSpeed;
  const auto on_grid = std::find_if(j.walker.speeds.begin(), j.walker.speeds.end(),
                                    [&](double v) { return std::abs(v - design.design_speed) <= 1e-9; });
  if (on_grid == j.walker.speeds.end())
    throw SpecError("design_speed", "= " + number_text(design.design_speed) + " m/s is not one of the speeds (" +
                                        number_text(j.walker.speeds.front()) + " .. " +
                                        number_text(j.walker.speeds.back()) + "); admissible: a value of the grid");
  design.design_speed = *on_grid;  // exactly the grid's value
  if (spec.contains("references")) {
    if (!spec["references"].is_boolean()) throw SpecError("references", "must be true or false");
    design.references = spec["references"].get<bool>();
  }
  design.sweep.starts = optional_integer(spec, "", "sweep_starts", 1, 1000).value_or(kDefaultSweepStarts);
  design.foot_scale = optional_number(spec, "", "foot_scale", 0.0, 3.0).value_or(design.foot_scale);
  studies::SpeedSweepOptions& sweep = design.sweep;
  sweep.speeds = j.walker.speeds;
  sweep.seeds = j.walker.seeds;  // the sweeps search once per seed
  sweep.scale = j.walker.scale;
  sweep.continuation.corrector = j.walker.solver;
  parse_sweep_continuation(spec, sweep);
  if (spec.contains("known_designs")) {
    const nlohmann::json& k = spec["known_designs"];
    if (!k.is_array() || k.size() > 100) throw SpecError("known_designs", "must be an array of at most 100 {density, z} objects");
    const walker::WalkerModel<double> model = j.walker.model();
    const int gait = walker::gait_parameter_count(model.joint_count, model.constants.bezier_degree);
    const int n = gait + static_cast<int>(j.walker.problem.free_parameters.size());
    for (std::size_t i = 0; i < k.size(); ++i) {
      const std::string field = "known_designs[" + std::to_string(i) + "]";
      const nlohmann::json& d = object_value(k[i], field);
      reject_unknown_keys(d, field, {"density", "z"});
      studies::KnownDesign known;
      if (!d.contains("density")) throw SpecError(field + ".density", "is required (one of densities)");
      known.density = number_value(d["density"], field + ".density", foot::kMinDensity, foot::kMaxDensity);
      if (std::find(design.densities.begin(), design.densities.end(), known.density) == design.densities.end())
        throw SpecError(field + ".density", "= " + number_text(known.density) + " kg/m^2 is not one of densities");
      if (!d.contains("z") || !d["z"].is_array() || static_cast<int>(d["z"].size()) != n)
        throw SpecError(field + ".z", "must be an array of " + std::to_string(n) + " numbers: the " + std::to_string(gait) +
                                          " gait parameters (rad), then the free foot parameters " +
                                          join(j.walker.problem.free_parameters));
      known.z.resize(n);
      for (int m = 0; m < n; ++m)
        known.z[m] = number_value(d["z"][static_cast<std::size_t>(m)], field + ".z[" + std::to_string(m) + "]", -100.0, 100.0);
      design.known_designs.push_back(std::move(known));
    }
  }
  return j;
}

records::DesignedFoot designed_foot(const walker::WalkerModel<double>& m) {
  records::DesignedFoot f;
  const std::vector<std::string> names = foot_parameter_names(m.foot_model);
  for (std::size_t i = 0; i < names.size(); ++i) f.parameters[names[i]] = m.foot_parameters[static_cast<Eigen::Index>(i)];
  f.m_F = m.segments[walker::m_F];
  f.r_F = m.segments[walker::r_F];
  f.J_F = m.segments[walker::J_F];
  f.theta_F0 = m.foot_zero_angle;
  return f;
}

double mean_of_finite(const std::vector<double>& v) {
  double sum = 0.0;
  int n = 0;
  for (double x : v)
    if (std::isfinite(x)) sum += x, ++n;
  return n > 0 ? sum / n : records::kUnset;
}

// The study's work units (issue 18): "start-foot" and "point-feet", the reference sweeps (when
// the job has references), then "density-<k>" per density (design multistart, free-foot
// continuation, two fixed-foot sweeps). Each stores its curves' points as it finds them and, at
// its end, its result as the unit's checkpoint kUnitResult: a reference its sweep summary, a
// density its DesignedFootRecord (savings not yet known) and its two fixed-foot sweeps. The job
// then adds the savings against the references and stores each density's record (curve 0).
constexpr const char* kUnitResult = "result";
constexpr int kFirstDensityUnit = 2;
constexpr studies::DesignReference kReferences[] = {studies::DesignReference::start_foot,
                                                    studies::DesignReference::point_feet};
constexpr const char* kReferenceUnits[] = {"start-foot", "point-feet"};

std::vector<WorkUnit> design_units(const DesignJob& job) {
  std::vector<WorkUnit> units;
  if (job.design.references)
    for (int i = 0; i < kFirstDensityUnit; ++i) units.push_back({kReferenceUnits[i], i});
  for (std::size_t k = 0; k < job.design.densities.size(); ++k)
    units.push_back({"density-" + std::to_string(k), kFirstDensityUnit + static_cast<int>(k)});
  return units;
}

int total_points(const DesignJob& job) {
  const int n = static_cast<int>(job.design.densities.size());
  const int speeds = static_cast<int>(job.walker.speeds.size());
  return n + (job.design.references ? 2 * speeds : 0) + 2 * n * speeds;
}

// One work unit of the study, computed against its unit's context.
class DesignUnit {
 public:
  DesignUnit(const DesignJob& job, JobContext& ctx) : job_(job), ctx_(ctx) {
    base_ = job.walker.problem;  // the fixed-foot problem of the references and step 3
    base_.free_parameters.clear();
    base_.design_bounds.reset();
  }
  void run(const WorkUnit& unit);

 private:
  bool running() { return ctx_.stop_reason() == StopReason::none; }
  void store(const storage::SolutionPoint& p) {
    if (ctx_.store_point(p)) ++stored_;  // a resumed job's replayed phases find their points stored
  }
  void store_sweep(int curve, const walker::WalkerModel<double>& model, const studies::FootSweepSummary& s) {
    for (const ComparedSpeedPoint& p : best_points(studies::walker_family(model, base_, "speed"), s, curve)) store(p.stored());
  }
  studies::FootDesignOptions options(PhaseProgress& progress);
  class Observer;
  void store_multistart(int k, const studies::DensityDesign& d);
  void store_free_foot(int k, const studies::DensityDesign& d);
  records::DesignedFootRecord design_record(const studies::DensityDesign& d) const;
  bool on_density(int k, const studies::DensityDesign& d, studies::DesignPhase phase);
  std::string step() {
    const std::lock_guard lock(mutex_);
    return step_;
  }

  const DesignJob& job_;
  JobContext& ctx_;
  walker::GaitProblemOptions base_;
  int stored_ = 0;
  std::mutex mutex_;  // step_: written by the study's thread, read by multistart workers
  std::string step_;
};

void DesignUnit::store_multistart(int k, const studies::DensityDesign& d) {
  const walker::GaitProblem shape(d.model, d.problem);
  for (std::size_t i = 0; i < d.optima.size(); ++i) {
    const studies::DesignOptimum& m = d.optima[i];
    walker::GaitOptimum opt;
    opt.summary = m.summary;
    opt.z = m.z;
    opt.gait = shape.gait_at(m.z);
    opt.start = "design multistart run " + std::to_string(m.starts.front());
    WalkerPoint p = walker_point(opt, {records::design_multistart_curve(k), static_cast<int>(i)}, static_cast<double>(i + 1));
    p.row.required = false;  // every optimum is kept; the density's record (curve 0) is what was asked for
    records::DesignPointRecord r;
    r.density = d.density;
    r.foot = designed_foot(shape.model_at(m.z));
    r.active_bounds = m.active_bounds;
    r.design_class = studies::to_string(m.classification.design_class);
    r.class_reason = m.classification.reason;
    r.reached_by_starts = m.starts;
    r.design = static_cast<int>(i) == d.best;
    store(p.stored(r));
  }
}

void DesignUnit::store_free_foot(int k, const studies::DensityDesign& d) {
  const continuation::ParametricProblem family = studies::walker_family(d.free_foot_model, d.free_foot_problem, "speed");
  for (std::size_t i = 0; i < d.free_foot.points.size(); ++i) {
    const continuation::CurvePoint& c = d.free_foot.points[i];
    WalkerPoint p = walker_point(family, c, {records::free_foot_curve(k), static_cast<int>(i)});
    p.row.required = false;  // the continuation may stop before the lowest speed (section 10.2)
    records::DesignPointRecord r;
    r.density = d.density;
    walker::GaitProblemOptions at = d.free_foot_problem;
    at.speed = c.parameter;
    r.foot = designed_foot(walker::GaitProblem(d.free_foot_model, at).model_at(c.x));
    store(p.stored(r));
  }
}

records::DesignedFootRecord DesignUnit::design_record(const studies::DensityDesign& d) const {
  records::DesignedFootRecord r;
  r.density = d.density;
  r.starts = job_.walker.starts;
  r.kkt_starts = d.kkt_starts;
  r.admissible_optima = d.class_counts[static_cast<int>(studies::DesignClass::admissible)];
  r.stilt_optima = d.class_counts[static_cast<int>(studies::DesignClass::stilt)];
  r.wheel_optima = d.class_counts[static_cast<int>(studies::DesignClass::wheel)];
  r.no_rolling_optima = d.class_counts[static_cast<int>(studies::DesignClass::no_rolling)];
  r.under_resolved_optima = d.class_counts[static_cast<int>(studies::DesignClass::under_resolved)];
  r.best = d.best;
  r.speeds = static_cast<int>(job_.walker.speeds.size());
  r.multistart_seconds = d.multistart_seconds;
  r.continuation_seconds = d.continuation_seconds;
  r.sweep_seconds = d.sweep_seconds;
  r.seconds = d.seconds;
  if (d.best < 0) {
    r.reason = d.kkt_starts == 0
                   ? "no design multistart run reached a KKT point (" + std::to_string(r.starts) + " starts)"
                   : "every optimum of the design multistart is degenerate: " + std::to_string(r.stilt_optima) +
                         " stilt, " + std::to_string(r.wheel_optima) + " wheel, " + std::to_string(r.no_rolling_optima) +
                         " no rolling, " + std::to_string(r.under_resolved_optima) + " under-resolved (design_class.hpp; " +
                         std::to_string(r.kkt_starts) + " of " + std::to_string(r.starts) + " starts reached a KKT point)";
    return r;
  }
  const studies::DesignOptimum& best = d.optima[static_cast<std::size_t>(d.best)];
  r.admissible = true;
  r.design_objective = best.objective;
  r.design = designed_foot(walker::GaitProblem(d.model, d.problem).model_at(best.z));
  r.active_bounds = best.active_bounds;
  walker::GaitOptimum at;
  at.summary = best.summary;
  at.z = best.z;
  r.sensitivities = sensitivities_record(studies::optimum_sensitivities(d.model, d.problem, at, {}, stop_predicate(ctx_)));
  r.free_foot_speeds = static_cast<int>(std::count_if(d.free_foot_f_mech.begin(), d.free_foot_f_mech.end(),
                                                      [](double f) { return std::isfinite(f); }));
  r.low_speed = d.low_speed;
  r.low_speed_design = designed_foot(walker::make_walker_model(d.low_speed_foot, job_.walker.constants));
  r.speeds_reached = d.high.speeds_found;
  r.mean_f_mech = mean_of_finite(d.high.f_mech);
  r.low_speeds_reached = d.low.speeds_found;
  r.low_mean_f_mech = mean_of_finite(d.low.f_mech);
  return r;
}

// Stores what a phase found (unless the job was stopped in it: then its result may be partial,
// and the resumed job replays the phase from its checkpoints).
bool DesignUnit::on_density(int k, const studies::DensityDesign& d, studies::DesignPhase phase) {
  if (!running()) return false;
  switch (phase) {
    case studies::DesignPhase::multistart: store_multistart(k, d); break;
    case studies::DesignPhase::free_foot: store_free_foot(k, d); break;
    case studies::DesignPhase::high_sweep:
      store_sweep(records::high_design_curve(k),
                  walker::make_walker_model(d.optima[static_cast<std::size_t>(d.best)].foot, job_.walker.constants), d.high);
      break;
    case studies::DesignPhase::low_sweep:
      store_sweep(records::low_design_curve(k), walker::make_walker_model(d.low_speed_foot, job_.walker.constants), d.low);
      break;
  }
  return running();
}

studies::FootDesignOptions DesignUnit::options(PhaseProgress& progress) {
  studies::FootDesignOptions o = job_.design;
  o.sweep.continuation.corrector.on_iteration = progress.iterations();
  o.sweep.continuation.corrector.should_stop = stop_predicate(ctx_);
  return o;
}

// What the study shows the unit: each step and its progress - the step (density and phase) as the
// message and the phase, with the sweep's or multistart's phase after it (so a phase change names
// its density) -, each density's phases as they end (stored, on_density), and the unit's journals.
class DesignUnit::Observer final : public studies::FootDesignObserver {
 public:
  // density: the unit's index into the job's densities (negative for a reference's unit).
  Observer(DesignUnit& unit, PhaseProgress& progress, int density) : unit_(unit), progress_(progress), density_(density) {}
  bool on_step(const std::string& s) override {
    {
      const std::lock_guard lock(unit_.mutex_);
      unit_.step_ = s;
    }
    progress_.set({.points_done = unit_.stored_, .points_total = total_points(unit_.job_), .message = s, .phase = s});
    return unit_.running();
  }
  bool on_density(const studies::DensityDesign& d, studies::DesignPhase phase) override {
    return unit_.on_density(density_, d, phase);
  }
  void on_multistart_progress(double, int done, double best) override {
    const std::string s = unit_.step();
    progress_.set({.points_done = unit_.stored_, .points_total = total_points(unit_.job_), .message = s,
                   .phase = s + ": design multistart", .phase_done = done, .phase_total = unit_.job_.walker.starts,
                   .best_objective = best});
  }
  void on_sweep_progress(const studies::SweepProgress& sp) override {
    ProgressReport r = sweep_progress_report(sp, unit_.step());
    r.phase = r.message + ": " + without_curve_number(r.phase);
    r.points_done = unit_.stored_;
    r.points_total = total_points(unit_.job_);
    progress_.set(r);
  }
  studies::SweepJournal journal(const std::string& part) override { return sweep_journal(unit_.ctx_, part + "/"); }

 private:
  DesignUnit& unit_;
  PhaseProgress& progress_;
  const int density_;
};

void DesignUnit::run(const WorkUnit& unit) {
  if (ctx_.stored_checkpoints().count(kUnitResult)) return;  // done by an earlier attempt
  stored_ = static_cast<int>(ctx_.already_stored_points().size());
  PhaseProgress progress(ctx_, {.points_done = stored_, .points_total = total_points(job_)});
  const studies::FootDesignOptions o = options(progress);
  const int k = unit.index - kFirstDensityUnit;
  Observer observer(*this, progress, k);
  try {
    if (unit.index < kFirstDensityUnit) {
      const studies::DesignReference which = kReferences[unit.index];
      const std::string part = studies::reference_part(which);
      if (!observer.on_step(part)) return;
      const studies::FootSweepSummary s = studies::sweep_reference(which, job_.start_foot, base_, o, observer);
      if (!running()) return;
      store_sweep(which == studies::DesignReference::start_foot ? records::kStartFootCurve : records::kPointFeetCurve,
                  studies::reference_model(which, job_.start_foot, job_.walker.constants), s);
      ctx_.store_checkpoint(kUnitResult, foot_sweep_to_json(s).dump());
      return;
    }
    if (k >= static_cast<int>(job_.design.densities.size()))
      throw std::logic_error("foot_design: no density " + std::to_string(k) + " in the job");
    const studies::DensityDesign d =
        studies::design_density(job_.design.densities[static_cast<std::size_t>(k)], job_.start_foot, base_, o, observer);
    if (d.stopped || !running()) return;
    ctx_.store_checkpoint(kUnitResult, nlohmann::json{{"record", nlohmann::json(design_record(d))},
                                                      {"high", foot_sweep_to_json(d.high)},
                                                      {"low", foot_sweep_to_json(d.low)}}
                                           .dump());
  } catch (const std::invalid_argument& e) {  // parse_design_job checks what the study refuses
    throw std::logic_error(std::string("foot_design: options the spec check let through: ") + e.what());
  }
}

// What a density's unit left: its record (savings not yet known) and its two fixed-foot sweeps.
struct DensityResult {
  records::DesignedFootRecord record;
  studies::DensityDesign sweeps;  // high and low only
};

DensityResult density_result(const nlohmann::json& j) {
  DensityResult r{j.at("record").get<records::DesignedFootRecord>(), {}};
  r.sweeps.high = foot_sweep_from_json(j.at("high"));
  r.sweeps.low = foot_sweep_from_json(j.at("low"));
  return r;
}

void run_design(const DesignJob& job, JobContext& ctx) {
  ctx.announce(total_points(job));
  ctx.add_curve(records::kDesignCurve, "designed foot per density", "density");
  if (job.design.references) {
    ctx.add_curve(records::kStartFootCurve, "start foot " + job.start_foot.name + " (own masses)", "speed");
    ctx.add_curve(records::kPointFeetCurve, "point feet", "speed");
  }
  for (std::size_t k = 0; k < job.design.densities.size(); ++k) {
    const int i = static_cast<int>(k);
    const std::string rho = "rho " + number_text(job.design.densities[k]) + ": ";
    ctx.add_curve(records::design_multistart_curve(i), rho + "design multistart optima, best first", "rank");
    ctx.add_curve(records::free_foot_curve(i), rho + "free-foot continuation", "speed");
    ctx.add_curve(records::high_design_curve(i), rho + "fixed-foot sweep of the design", "speed");
    ctx.add_curve(records::low_design_curve(i), rho + "fixed-foot sweep of the low-speed design", "speed");
  }
  const std::vector<WorkUnit> units = design_units(job);
  ctx.run_units(units, [&job](const WorkUnit& unit, JobContext& c) { DesignUnit(job, c).run(unit); });
  if (ctx.stop_reason() != StopReason::none) return;
  const std::map<std::string, std::string> stored = ctx.stored_checkpoints();
  studies::FootSweepSummary references[2];
  for (const WorkUnit& unit : units) {
    if (unit.index < kFirstDensityUnit) {
      references[unit.index] =
          unit_result(stored, unit, kUnitResult, [](const nlohmann::json& j) { return foot_sweep_from_json(j); });
      continue;
    }
    DensityResult d = unit_result(stored, unit, kUnitResult, density_result);
    records::DesignedFootRecord& r = d.record;
    if (r.admissible) {
      studies::add_savings(d.sweeps, job.walker.speeds, references[0], references[1]);
      r.saving_vs_start = d.sweeps.saving_vs_start;
      r.saving_vs_point = d.sweeps.saving_vs_point;
      r.low_saving_vs_start = d.sweeps.low_saving_vs_start;
      r.low_saving_vs_point = d.sweeps.low_saving_vs_point;
      r.answer = studies::to_string(d.sweeps.answer);
    }
    storage::SolutionPoint p;
    p.key = {records::kDesignCurve, unit.index - kFirstDensityUnit};
    p.parameter = r.density;
    if (r.admissible)
      p.objective = r.design_objective;
    else
      p.status = "no admissible design";
    p.set_values(r);
    ctx.store_point(p);
  }
}

// Per density a design multistart (foot free: the rolling-foot cost with more variables), a
// continuation over the speeds below the design speed and two sweeps; the two reference sweeps.
JobCost design_cost(const DesignJob& j) {
  const int speeds = static_cast<int>(j.walker.speeds.size());
  const int seeds = static_cast<int>(j.design.sweep.seed_speeds.size());
  const int below = static_cast<int>(std::count_if(j.walker.speeds.begin(), j.walker.speeds.end(),
                                                   [&](double v) { return v < j.design.design_speed; }));
  WalkerJob sweep = j.walker;
  sweep.starts = j.design.sweep.starts;
  const double multistart = walker_job_cost(j.walker, "multistart", 1, 0).seconds;
  const double continuation = walker_job_cost(j.walker, "continuation", below + 1, 0).seconds;
  const JobCost one_sweep = walker_job_cost(sweep, "sweep", speeds, seeds);
  const double density = multistart + continuation + 2.0 * one_sweep.seconds;
  JobCost c;
  c.seconds = static_cast<double>(j.design.densities.size()) * density + (j.design.references ? 2.0 * one_sweep.seconds : 0.0);
  c.memory_bytes = std::max(walker_job_cost(j.walker, "multistart", 1, 0).memory_bytes, one_sweep.memory_bytes);
  c.field = "densities";
  c.breakdown = std::to_string(j.design.densities.size()) + " densities x (design multistart of " + std::to_string(j.walker.starts) +
                " starts " + duration_text(multistart) + " + free-foot continuation " + duration_text(continuation) +
                " + 2 fixed-foot sweeps of " + duration_text(one_sweep.seconds) + ")" +
                (j.design.references ? " + 2 reference sweeps" : "");
  return c;
}

// The resolved spec (resolved_spec.hpp): the walker fields of a sweep with the start foot as
// given (as its full parameters) and the free foot parameters and design bounds spelled out, and
// every design field.
nlohmann::json design_job_json(const DesignJob& j) {
  nlohmann::json r = walker_job_json(j.walker, true, true);
  records::WalkerSetupRecord setup = walker_setup(j.walker);  // with the start foot as given
  setup.foot = io::to_json(j.start_foot);
  setup.design_speed = j.design.design_speed;
  r.update(nlohmann::json(setup));
  r["densities"] = j.design.densities;
  r["references"] = j.design.references;
  r["sweep_starts"] = j.design.sweep.starts;
  r["foot_scale"] = j.design.foot_scale;
  r["continuation"] = sweep_continuation_json(j.design.sweep);
  if (!j.design.known_designs.empty()) {
    r["known_designs"] = nlohmann::json::array();
    for (const studies::KnownDesign& k : j.design.known_designs)
      r["known_designs"].push_back({{"density", k.density}, {"z", std::vector<double>(k.z.data(), k.z.data() + k.z.size())}});
  }
  return r;
}

}  // namespace

JobKind foot_design_kind() {
  std::vector<std::string> fields;
  for (const std::string& f : walker_job_fields(true))
    if (f != "start") fields.push_back(f);
  fields.insert(fields.end(), {"densities", "design_speed", "references", "sweep_starts", "foot_scale", "continuation", "known_designs"});
  return with_work_units<DesignJob>(typed_job_kind<DesignJob>("foot_design", {"walker"}, fields, parse_design_job,
                                                              run_design, design_job_json, design_cost),
                                    [](const DesignJob& job, const WorkUnit& unit, JobContext& ctx) {
                                      DesignUnit(job, ctx).run(unit);
                                    });
}

}  // namespace cyclopt::jobs
