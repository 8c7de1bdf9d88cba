#include "cyclopt/io/task_spec_json.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <vector>

namespace cyclopt::io {

using namespace giant_swing;

namespace {

using nlohmann::json;

double number(const json& j, const std::string& key, const std::string& path, double lo, double hi,
              const std::string& unit) {
  const std::string field = path + "." + key;
  const json& v = j.at(key);
  if (!v.is_number()) throw SpecError(field, "must be a number in " + range_text(lo, hi, unit) + ", got " + v.dump());
  const double x = v.get<double>();
  if (!std::isfinite(x) || x < lo || x > hi)
    throw SpecError(field, "must be in " + range_text(lo, hi, unit) + ", got " + v.dump());
  return x;
}

int integer(const json& j, const std::string& key, const std::string& path, int lo, int hi) {
  const std::string field = path + "." + key;
  const json& v = j.at(key);
  if (!v.is_number_integer() || v.get<long long>() < lo || v.get<long long>() > hi)
    throw SpecError(field, "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
                                   v.dump());
  return v.get<int>();
}

void check_keys(const json& j, const std::string& path, std::initializer_list<const char*> allowed) {
  if (!j.is_object()) throw SpecError(path, "must be a JSON object, got " + std::string(j.type_name()));
  std::string list;
  for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
  for (const auto& [key, value] : j.items()) {
    bool known = false;
    for (const char* a : allowed) known = known || key == a;
    if (!known) throw SpecError(path + "." + key, "is not a known field; allowed: " + list);
  }
}

bool power_of_two(int n) { return n > 0 && (n & (n - 1)) == 0; }

constexpr double kMaxWeight = 1e6;
constexpr int kMaxSupportPoints = 64;
constexpr int kMaxRounds = 50;

OptimiserSettings optimiser_from_json(const json& j, const std::string& path) {
  check_keys(j, path,
             {"support_points", "max_support_points", "initial_step", "min_step", "f_tolerance", "same_vector_tolerance",
              "max_evaluations_per_run", "max_evaluations_per_stage", "max_evaluations", "start_vector"});
  OptimiserSettings o;
  auto power_field = [&](const char* key, int& out) {
    if (!j.contains(key)) return;
    out = integer(j, key, path, 4, kMaxSupportPoints);
    if (!power_of_two(out))
      throw SpecError(path + "." + key, "must be a power of two in [4, 64] (2^n support points), got " +
                                                std::to_string(out));
  };
  power_field("support_points", o.support_points);
  power_field("max_support_points", o.max_support_points);
  if (j.contains("initial_step")) o.initial_step = number(j, "initial_step", path, 1e-6, 1e4, "Nm");
  if (j.contains("min_step")) o.min_step = number(j, "min_step", path, 1e-9, 1e4, "Nm");
  if (j.contains("f_tolerance")) o.f_tolerance = number(j, "f_tolerance", path, 1e-16, 1.0, "");
  if (j.contains("same_vector_tolerance"))
    o.same_vector_tolerance = number(j, "same_vector_tolerance", path, 0.0, 1.0, "");
  if (j.contains("max_evaluations_per_run")) o.max_evaluations_per_run = integer(j, "max_evaluations_per_run", path, 10, 100000000);
  if (j.contains("max_evaluations_per_stage"))
    o.max_evaluations_per_stage = integer(j, "max_evaluations_per_stage", path, 10, 100000000);
  if (j.contains("max_evaluations")) o.max_evaluations = integer(j, "max_evaluations", path, 10, 1000000000);
  if (j.contains("start_vector")) {
    const json& v = j.at("start_vector");
    const std::string field = path + ".start_vector";
    if (!v.is_array() || !power_of_two(int(v.size())) || v.size() < 4 || v.size() > kMaxSupportPoints)
      throw SpecError(field, "must be an array of 4, 8, 16, 32 or 64 torques in [-1000, 1000] Nm");
    Eigen::VectorXd z(Eigen::Index(v.size()));
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (!v[i].is_number() || !std::isfinite(v[i].get<double>()) || std::abs(v[i].get<double>()) > 1000.0)
        throw SpecError(field + "[" + std::to_string(i) + "]", "must be a torque in [-1000, 1000] Nm, got " + v[i].dump());
      z[Eigen::Index(i)] = v[i].get<double>();
    }
    o.start_vector = z;
    o.support_points = int(v.size());
  }
  if (o.min_step > o.initial_step)
    throw SpecError(path + ".min_step", "must not exceed initial_step = " + std::to_string(o.initial_step) + " Nm");
  if (o.max_support_points < o.support_points)
    throw SpecError(path + ".max_support_points",
                        "must be at least support_points = " + std::to_string(o.support_points));
  return o;
}

}  // namespace

TaskSpec task_spec_from_json(const json& j, const std::string& path) {
  check_keys(j, path,
             {"task", "name", "omega_deg_s", "initial_rate_deg_s", "rounds", "weights", "alpha_min_deg",
              "alpha_max_deg", "alpha_ddot_max_deg_s2", "relative_tolerance", "optimiser"});
  const std::string kinds = "one of \"single_swing\", \"periodic_sequence\", \"accelerating\", \"decelerating\"";
  if (!j.contains("task")) throw SpecError(path + ".task", "is required: " + kinds);
  const json& k = j.at("task");
  TaskKind kind{};
  bool found = false;
  for (TaskKind c : {TaskKind::single_swing, TaskKind::periodic_sequence, TaskKind::accelerating, TaskKind::decelerating})
    if (k.is_string() && k.get<std::string>() == to_string(c)) kind = c, found = true;
  if (!found) throw SpecError(path + ".task", "must be " + kinds + ", got " + k.dump());
  TaskSpec s = default_task(kind);
  const double rad = 1.0 / kDegPerRad;
  if (j.contains("name")) {
    if (!j.at("name").is_string()) throw SpecError(path + ".name", "must be a string");
    s.name = j.at("name").get<std::string>();
  }
  if (j.contains("omega_deg_s")) {
    const double ratio = s.initial_rate / s.omega;
    s.omega = number(j, "omega_deg_s", path, 1.0, 360.0, "deg/s") * rad;
    s.initial_rate = ratio * s.omega;
  }
  if (j.contains("initial_rate_deg_s")) s.initial_rate = number(j, "initial_rate_deg_s", path, 1.0, 720.0, "deg/s") * rad;
  if (j.contains("rounds")) {
    s.rounds = integer(j, "rounds", path, 1, kMaxRounds);
    if (kind != TaskKind::periodic_sequence && s.rounds != 1)
      throw SpecError(path + ".rounds", "must be 1 for task " + std::string(to_string(kind)) +
                                                " (only periodic_sequence evaluates several rounds)");
  }
  if (j.contains("weights")) {
    const json& w = j.at("weights");
    const std::string wp = path + ".weights";
    check_keys(w, wp, {"phi_rate", "alpha", "alpha_rate", "friction", "jerk", "moment"});
    auto weight = [&](const char* key, double& out) {
      if (w.contains(key)) out = number(w, key, wp, 0.0, kMaxWeight, "");
    };
    weight("phi_rate", s.weights.phi_rate);
    weight("alpha", s.weights.alpha);
    weight("alpha_rate", s.weights.alpha_rate);
    weight("friction", s.weights.friction);
    weight("jerk", s.weights.jerk);
    weight("moment", s.weights.moment);
  }
  if (j.contains("alpha_min_deg")) s.ranges.alpha_min = number(j, "alpha_min_deg", path, -90.0, 0.0, "deg") * rad;
  if (j.contains("alpha_max_deg")) s.ranges.alpha_max = number(j, "alpha_max_deg", path, 0.0, 180.0, "deg") * rad;
  if (j.contains("alpha_ddot_max_deg_s2"))
    s.ranges.alpha_acceleration_max = number(j, "alpha_ddot_max_deg_s2", path, 1.0, 1e6, "deg/s^2") * rad;
  if (j.contains("relative_tolerance")) s.relative_tolerance = number(j, "relative_tolerance", path, 1e-13, 1e-4, "");
  if (j.contains("optimiser")) s.optimiser = optimiser_from_json(j.at("optimiser"), path + ".optimiser");
  return s;
}

json to_json(const TaskSpec& s) {
  json j;
  j["task"] = to_string(s.kind);
  if (!s.name.empty()) j["name"] = s.name;
  j["omega_deg_s"] = s.omega * kDegPerRad;
  j["initial_rate_deg_s"] = s.initial_rate * kDegPerRad;
  j["rounds"] = s.rounds;
  j["weights"] = {{"phi_rate", s.weights.phi_rate}, {"alpha", s.weights.alpha},   {"alpha_rate", s.weights.alpha_rate},
                  {"friction", s.weights.friction}, {"jerk", s.weights.jerk},     {"moment", s.weights.moment}};
  j["alpha_min_deg"] = s.ranges.alpha_min * kDegPerRad;
  j["alpha_max_deg"] = s.ranges.alpha_max * kDegPerRad;
  if (std::isfinite(s.ranges.alpha_acceleration_max))
    j["alpha_ddot_max_deg_s2"] = s.ranges.alpha_acceleration_max * kDegPerRad;
  j["relative_tolerance"] = s.relative_tolerance;
  const OptimiserSettings& o = s.optimiser;
  j["optimiser"] = {{"support_points", o.support_points},
                    {"max_support_points", o.max_support_points},
                    {"initial_step", o.initial_step},
                    {"min_step", o.min_step},
                    {"f_tolerance", o.f_tolerance},
                    {"same_vector_tolerance", o.same_vector_tolerance},
                    {"max_evaluations_per_run", o.max_evaluations_per_run},
                    {"max_evaluations_per_stage", o.max_evaluations_per_stage},
                    {"max_evaluations", o.max_evaluations}};
  if (o.start_vector) j["optimiser"]["start_vector"] = std::vector<double>(o.start_vector->begin(), o.start_vector->end());
  return j;
}

}  // namespace cyclopt::io
