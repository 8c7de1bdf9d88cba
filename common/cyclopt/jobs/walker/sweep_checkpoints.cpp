#include "cyclopt/jobs/walker/sweep_checkpoints.hpp"

#include "cyclopt/jobs/walker/walker_records.hpp"
#include "cyclopt/records/walker_point_record.hpp"

#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <memory>
#include <string>

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

namespace {

using nlohmann::json;

// NaN and infinities have no JSON form: stored as null, read back as NaN.
double number(const json& j) { return j.is_null() ? std::numeric_limits<double>::quiet_NaN() : j.get<double>(); }

std::vector<double> as_vector(const Eigen::VectorXd& v) { return {v.data(), v.data() + v.size()}; }

Eigen::VectorXd vector_of(const std::vector<double>& v) {
  return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

Eigen::VectorXd vector_from_json(const json& a) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(a.size()));
  for (std::size_t i = 0; i < a.size(); ++i) v[static_cast<Eigen::Index>(i)] = number(a.at(i));
  return v;
}

nlp::Termination termination_named(const std::string& name) {
  for (int t = 0; t <= static_cast<int>(nlp::Termination::stalled); ++t)
    if (name == nlp::to_string(static_cast<nlp::Termination>(t))) return static_cast<nlp::Termination>(t);
  throw records::RecordError("solver.termination: no termination is called '" + name + "'");
}

// Parses one checkpoint; nullopt (computed again) when it is missing or unreadable.
template <class T>
std::optional<T> find(const std::map<std::string, std::string>& stored, const std::string& key,
                      T (*from_json)(const json&)) {
  const auto it = stored.find(key);
  if (it == stored.end()) return std::nullopt;
  const json j = json::parse(it->second, nullptr, false);
  if (j.is_discarded()) return std::nullopt;
  try {
    return from_json(j);
  } catch (const std::exception&) {  // json::exception, records::RecordError, std::out_of_range
    return std::nullopt;
  }
}

std::string solve_key(int batch, int start) {
  return "solve/" + std::to_string(batch) + "/" + std::to_string(start);
}
std::string run_key(int run) { return "run/" + std::to_string(run); }
std::string run_state_key(int run) { return "run_state/" + std::to_string(run); }

json curve_point_to_json(const continuation::CurvePoint& p) {
  json j = continuation_step_record(p);
  j["parameter"] = p.parameter;
  j["x"] = as_vector(p.x);
  j["objective"] = p.objective;
  j["corrector"] = summary_to_json(p.corrector);
  return j;
}

continuation::CurvePoint curve_point_from_json(const json& j) {
  const auto step = j.get<records::ContinuationStepRecord>();
  continuation::CurvePoint p;
  p.parameter = number(j.at("parameter"));
  p.curve_id = step.curve_id;
  p.on_grid = step.on_grid;
  p.converged = step.converged;
  p.x = vector_from_json(j.at("x"));
  p.objective = number(j.at("objective"));
  p.corrector = summary_from_json(j.at("corrector"));
  p.predictor_attempts = step.predictor_attempts;
  p.predictor_steps = step.predictor_steps;
  p.kappa = step.kappa;
  p.trust_region = step.trust_region;
  p.seconds = step.point_seconds;
  return p;
}

json best_to_json(const studies::BestPoint& b) {
  json j = {{"speed", b.speed}, {"found", b.found}, {"reason", b.reason}, {"closure_passes", b.closure_passes},
            {"closure_pass", b.closure_pass}, {"seed", b.seed}};
  if (b.found) {
    j["point"] = curve_point_to_json(b.point);
    j["origin"] = {{"step", static_cast<int>(b.origin.step)}, {"speed", b.origin.speed}};
  }
  return j;
}

studies::BestPoint best_from_json(const json& j) {
  studies::BestPoint b;
  b.speed = number(j.at("speed"));
  b.found = j.at("found").get<bool>();
  b.reason = j.at("reason").get<std::string>();
  b.closure_passes = j.value("closure_passes", 0);  // absent in checkpoints written before the closure
  b.closure_pass = j.value("closure_pass", 0);
  b.seed = j.value("seed", std::uint64_t{0});
  if (b.found) {
    b.point = curve_point_from_json(j.at("point"));
    const int step = j.at("origin").at("step").get<int>();
    if (step < 0 || step > static_cast<int>(studies::SweepStep::closure))
      throw std::out_of_range("origin.step " + std::to_string(step) + " is no sweep step");
    b.origin = {static_cast<studies::SweepStep>(step), number(j.at("origin").at("speed"))};
  }
  return b;
}

}  // namespace

json summary_to_json(const nlp::SolverSummary& s) {
  records::SolverRecord r = solver_record(s);
  r.equality_multipliers = as_vector(s.equality_multipliers);
  r.inequality_multipliers = as_vector(s.inequality_multipliers);
  r.bound_multipliers = as_vector(s.bound_multipliers);
  return r;
}

nlp::SolverSummary summary_from_json(const json& j) {
  const auto r = j.get<records::SolverRecord>();
  nlp::SolverSummary s;
  s.termination = termination_named(r.termination);
  s.message = r.message;
  s.iterations = r.iterations;
  s.function_evaluations = r.function_evaluations;
  s.jacobian_evaluations = r.jacobian_evaluations;
  s.failed_evaluations = r.failed_evaluations;
  s.wall_seconds = r.wall_seconds;
  s.objective = r.objective;
  s.kkt_error = r.kkt_error;
  s.constraint_violation = r.constraint_violation;
  s.x = vector_of(r.x);
  s.equality_multipliers = vector_of(r.equality_multipliers);
  s.inequality_multipliers = vector_of(r.inequality_multipliers);
  s.bound_multipliers = vector_of(r.bound_multipliers);
  return s;
}

json run_to_json(const continuation::ContinuationResult& r) {
  json points = json::array(), jumps = json::array();
  for (const continuation::CurvePoint& p : r.points) points.push_back(curve_point_to_json(p));
  for (const continuation::CurveJump& c : r.jumps)
    jumps.push_back({c.from_curve, c.to_curve, c.from_parameter, c.to_parameter, c.objective_before, c.objective_after,
                     c.relative_distance});
  return {{"points", points},
          {"jumps", jumps},
          {"finished", r.finished},
          {"message", r.message},
          {"next_curve_id", r.next_curve_id},
          {"corrector_iterations", r.corrector_iterations},
          {"predictor_steps", r.predictor_steps},
          {"seconds", r.seconds}};
}

continuation::ContinuationResult run_from_json(const json& j) {
  continuation::ContinuationResult r;
  for (const json& p : j.at("points")) r.points.push_back(curve_point_from_json(p));
  for (const json& c : j.at("jumps"))
    r.jumps.push_back({c.at(0).get<int>(), c.at(1).get<int>(), number(c.at(2)), number(c.at(3)), number(c.at(4)),
                       number(c.at(5)), number(c.at(6))});
  r.finished = j.at("finished").get<bool>();
  r.message = j.at("message").get<std::string>();
  r.next_curve_id = j.at("next_curve_id").get<int>();
  r.corrector_iterations = j.at("corrector_iterations").get<int>();
  r.predictor_steps = j.at("predictor_steps").get<int>();
  r.seconds = number(j.at("seconds"));
  return r;
}

json run_state_to_json(const continuation::RunState& s) {
  json j = {{"run", run_to_json(s.result)},
            {"curve_id", s.curve_id},
            {"next_value", s.next_value},
            {"tried_value", s.tried_value},
            {"trust_region", s.trust_region}};
  if (s.secant) j["secant"] = *s.secant;
  return j;
}

continuation::RunState run_state_from_json(const json& j) {
  continuation::RunState s;
  s.result = run_from_json(j.at("run"));
  s.curve_id = j.at("curve_id").get<int>();
  s.next_value = j.at("next_value").get<std::size_t>();
  s.tried_value = j.at("tried_value").get<std::size_t>();
  s.trust_region = number(j.at("trust_region"));
  if (j.contains("secant")) s.secant = number(j.at("secant"));
  return s;
}

studies::SweepJournal sweep_journal(JobContext& ctx, const std::string& prefix) {
  // Shared by the find functions; read once, when the sweep starts.
  const auto stored = std::make_shared<const std::map<std::string, std::string>>(ctx.stored_checkpoints());
  studies::SweepJournal j;
  j.find_solve = [stored, prefix](int batch, int start) {
    return find(*stored, prefix + solve_key(batch, start), summary_from_json);
  };
  j.record_solve = [&ctx, prefix](int batch, int start, const nlp::SolverSummary& s) {
    ctx.store_checkpoint(prefix + solve_key(batch, start), summary_to_json(s).dump());
  };
  j.find_run = [stored, prefix](int run) { return find(*stored, prefix + run_key(run), run_from_json); };
  j.record_run = [&ctx, prefix](int run, const continuation::ContinuationResult& r) {
    ctx.store_checkpoint(prefix + run_key(run), run_to_json(r).dump());
  };
  j.find_run_state = [stored, prefix](int run) {
    return find(*stored, prefix + run_state_key(run), run_state_from_json);
  };
  j.record_run_state = [&ctx, prefix](int run, const continuation::RunState& s) {
    ctx.store_checkpoint(prefix + run_state_key(run), run_state_to_json(s).dump());
  };
  return j;
}

json foot_sweep_to_json(const studies::FootSweepSummary& s) {
  json best = json::array();
  for (const studies::BestPoint& b : s.best) best.push_back(best_to_json(b));
  return {{"name", s.name},       {"best", best},       {"f_mech", s.f_mech},   {"speeds_found", s.speeds_found},
          {"seconds", s.seconds}, {"curves", s.curves}, {"stopped", s.stopped}, {"seeds", s.seeds},
          {"seed_f_mech", s.seed_f_mech}};
}

studies::FootSweepSummary foot_sweep_from_json(const json& j) {
  studies::FootSweepSummary s;
  s.name = j.at("name").get<std::string>();
  for (const json& b : j.at("best")) s.best.push_back(best_from_json(b));
  for (const json& f : j.at("f_mech")) s.f_mech.push_back(number(f));
  s.speeds_found = j.at("speeds_found").get<int>();
  s.seconds = number(j.at("seconds"));
  s.curves = j.at("curves").get<int>();
  s.stopped = j.at("stopped").get<bool>();
  // Checkpoints written before the searches per seed: one search, its f_mech the foot's.
  s.seeds = j.contains("seeds") ? j["seeds"].get<std::vector<std::uint64_t>>() : std::vector<std::uint64_t>{1};
  if (j.contains("seed_f_mech"))
    for (const json& per_seed : j["seed_f_mech"]) {
      s.seed_f_mech.emplace_back();
      for (const json& f : per_seed) s.seed_f_mech.back().push_back(number(f));
    }
  else
    s.seed_f_mech = {s.f_mech};
  return s;
}

}  // namespace cyclopt::jobs
