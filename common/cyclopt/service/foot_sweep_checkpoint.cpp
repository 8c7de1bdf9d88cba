#include "cyclopt/service/foot_sweep_checkpoint.hpp"

#include "cyclopt/service/sweep_checkpoints.hpp"

#include <limits>
#include <stdexcept>
#include <string>

namespace cyclopt::service {

namespace {

using nlohmann::json;

double number(const json& j) { return j.is_null() ? std::numeric_limits<double>::quiet_NaN() : j.get<double>(); }

json best_to_json(const studies::BestPoint& b) {
  json j = {{"speed", b.speed}, {"found", b.found}, {"reason", b.reason}};
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
  if (b.found) {
    b.point = curve_point_from_json(j.at("point"));
    const int step = j.at("origin").at("step").get<int>();
    if (step < 0 || step > static_cast<int>(studies::SweepStep::gait_multistart))
      throw std::out_of_range("origin.step " + std::to_string(step) + " is no sweep step");
    b.origin = {static_cast<studies::SweepStep>(step), number(j.at("origin").at("speed"))};
  }
  return b;
}

}  // namespace

json foot_sweep_to_json(const studies::FootSweepSummary& s) {
  json best = json::array();
  for (const studies::BestPoint& b : s.best) best.push_back(best_to_json(b));
  return {{"name", s.name},         {"best", best},       {"f_mech", s.f_mech}, {"speeds_found", s.speeds_found},
          {"seconds", s.seconds},   {"curves", s.curves}, {"stopped", s.stopped}};
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
  return s;
}

}  // namespace cyclopt::service
