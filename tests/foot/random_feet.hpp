#pragma once
// Random admissible feet for property tests: geometry in the range of the seed's fits and of
// its optimisations (section 10.2), regularisation k log-uniform in [k_min, k_max].

#include "cyclopt/foot/convexity_constraints.hpp"
#include "cyclopt/foot/foot_spec.hpp"

#include <cmath>
#include <numbers>
#include <random>

namespace cyclopt::foot::testing {

class RandomFeet {
 public:
  explicit RandomFeet(unsigned seed, double k_min = 1e-8, double k_max = 0.5) : rng_(seed), k_min_(k_min), k_max_(k_max) {}

  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  double log_uniform_k() { return std::exp(uniform(std::log(k_min_), std::log(k_max_))); }

  FootSpec hm() {
    FootSpec s;
    s.model = FootModel::hm;
    s.parameters.resize(hm::count);
    const double l_hm = uniform(0.08, 0.40);
    s.parameters << uniform(0.0, 0.12), uniform(0.0, l_hm), l_hm, log_uniform_k(), log_uniform_k(), log_uniform_k();
    validate(s);
    return s;
  }

  FootSpec hmt() {
    for (;;) {
      FootSpec s;
      s.model = FootModel::hmt;
      s.parameters.resize(hmt::count);
      const double l_hm = uniform(0.08, 0.40);
      s.parameters << uniform(0.01, 0.12), uniform(0.0, l_hm), l_hm, uniform(0.0, 0.12),
          uniform(0.0, std::numbers::pi / 2), log_uniform_k(), log_uniform_k(), log_uniform_k(), log_uniform_k();
      if (toe_convexity_margin(s.parameters) < 0.0) continue;  // outside the admissible set
      validate(s);
      return s;
    }
  }

  FootSpec any() { return uniform(0.0, 1.0) < 0.5 ? hm() : hmt(); }

 private:
  std::mt19937_64 rng_;
  double k_min_, k_max_;
};

// Every entry of the parameter vector's k's set to one value.
inline FootSpec with_all_k(FootSpec s, double k) {
  const int first_k = s.model == FootModel::hm ? int{hm::k_H} : int{hmt::k_H};
  for (int i = first_k; i < s.parameters.size(); ++i) s.parameters[i] = k;
  return s;
}

}  // namespace cyclopt::foot::testing
