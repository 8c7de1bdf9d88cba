#pragma once
// Gaits shared by the walker tests: the automatic starting gait of each reference foot (the seed's
// HM P1 barefoot, HMT P2 shoes, point feet of Table D.1), computed once per test binary.

#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/walker/starting_gait.hpp"

#include <map>
#include <memory>
#include <string>
#include <utility>

namespace cyclopt::walker::testing {

inline const char* const kReferenceFeet[] = {"P1-barefoot-left-HM", "P2-shoes-left-HMT", "point"};

struct ReferenceGait {
  std::unique_ptr<GaitEvaluator> evaluator;
  StartingGait start;
};

inline WalkerModel<double> reference_model(const std::string& foot, int points = 200) {
  WalkingConstants c;
  c.points = points;
  return make_walker_model(foot::foot_preset(foot).spec, c);
}

inline const ReferenceGait& reference_gait(const std::string& foot, double speed = 1.3, int points = 200) {
  static std::map<std::tuple<std::string, double, int>, ReferenceGait> cache;
  auto key = std::make_tuple(foot, speed, points);
  auto it = cache.find(key);
  if (it == cache.end()) {
    ReferenceGait r;
    r.evaluator = std::make_unique<GaitEvaluator>(reference_model(foot, points));
    StartingGaitOptions o;
    o.speed = speed;
    r.start = starting_gait(*r.evaluator, o);
    it = cache.emplace(key, std::move(r)).first;
  }
  return it->second;
}

// Every number a real gait reports is finite (the hard cases must never hide a NaN).
inline bool all_finite(const PeriodicGait<double>& g) {
  return std::isfinite(g.objective) && std::isfinite(g.f_mech) && std::isfinite(g.f_usq) &&
         std::isfinite(g.speed_equality) && g.inequalities.allFinite() && std::isfinite(g.step_length) &&
         std::isfinite(g.step_period) && std::isfinite(g.floquet) && std::isfinite(g.zeta_plus) &&
         std::isfinite(g.impact_energy_loss);
}

}  // namespace cyclopt::walker::testing
