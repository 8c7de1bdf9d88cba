#include "cyclopt/studies/foot_comparison.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace cyclopt::studies {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Mean of a over the indices where both a and b are finite, and their count.
std::pair<double, double> common_means(const std::vector<double>& a, const std::vector<double>& b, int* count) {
  double sa = 0.0, sb = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
    if (std::isfinite(a[i]) && std::isfinite(b[i])) {
      sa += a[i];
      sb += b[i];
      ++n;
    }
  *count = n;
  return n ? std::pair{sa / n, sb / n} : std::pair{kNaN, kNaN};
}

double saving_of(const std::vector<double>& f, const std::vector<double>& reference, int* count, double* mean) {
  const auto [m, mr] = common_means(f, reference, count);
  *mean = m;
  return *count && mr > 0.0 ? 1.0 - m / mr : kNaN;
}

}  // namespace

FootSweepSummary summarise_sweep(const std::string& name, const walker::WalkerModel<double>& model,
                                 const walker::GaitProblemOptions& problem, const SpeedSweepResult& sweep) {
  FootSweepSummary s;
  s.name = name;
  s.best = sweep.best;
  s.seconds = sweep.seconds;
  s.curves = sweep.curves;
  s.recoveries = sweep.recoveries;
  for (const BestPoint& b : sweep.best) {
    double f = kNaN;
    if (b.found) {
      walker::GaitProblemOptions po = problem;
      po.speed = b.speed;
      const walker::PeriodicGait<double> g = walker::GaitProblem(model, po).gait_at(b.point.x);
      if (g.real) f = g.f_mech;
    }
    s.f_mech.push_back(f);
    s.speeds_found += std::isfinite(f);
  }
  return s;
}

FootComparisonResult summarise_feet(std::vector<double> speeds, std::vector<FootSweepSummary> feet, std::size_t reference) {
  if (reference >= feet.size()) throw std::invalid_argument("foot comparison: reference index out of range");
  FootComparisonResult r;
  r.speeds = std::move(speeds);
  r.feet = std::move(feet);
  r.reference = reference;
  const std::vector<double>& ref = r.feet[reference].f_mech;
  const int ref_found = r.feet[reference].speeds_found;
  double best_saving = -std::numeric_limits<double>::infinity();
  bool best_complete = false;
  for (std::size_t k = 0; k < r.feet.size(); ++k) {
    FootSweepSummary& s = r.feet[k];
    if (k == reference) {
      s.mean_f_mech = common_means(s.f_mech, ref, &s.common_speeds).first;
      s.saving = 0.0;
      continue;
    }
    s.saving = saving_of(s.f_mech, ref, &s.common_speeds, &s.mean_f_mech);
    if (!std::isfinite(s.saving)) continue;
    const bool complete = s.common_speeds == ref_found;  // reaches every speed the reference reaches
    if ((complete && !best_complete) || (complete == best_complete && s.saving > best_saving)) {
      best_saving = s.saving;
      best_complete = complete;
      r.best_mean_foot = static_cast<int>(k);
    }
  }
  for (std::size_t i = 0; i < r.speeds.size(); ++i) {
    int best = -1;
    for (std::size_t k = 0; k < r.feet.size(); ++k) {
      if (k == reference || i >= r.feet[k].f_mech.size() || !std::isfinite(r.feet[k].f_mech[i])) continue;
      if (best < 0 || r.feet[k].f_mech[i] < r.feet[static_cast<std::size_t>(best)].f_mech[i]) best = static_cast<int>(k);
    }
    r.best_foot.push_back(best);
    r.envelope_f_mech.push_back(best < 0 ? kNaN : r.feet[static_cast<std::size_t>(best)].f_mech[i]);
  }
  double envelope_mean = 0.0;
  r.envelope_saving = saving_of(r.envelope_f_mech, ref, &r.envelope_common_speeds, &envelope_mean);
  return r;
}

FootSweepSummary sweep_foot(const std::string& name, const walker::WalkerModel<double>& model,
                            const walker::GaitProblemOptions& problem, const SpeedSweepOptions& options,
                            const PointCallback& on_point) {
  bool stopped = false;
  const SpeedSweepResult sweep = speed_sweep(model, problem, options, [&](const CurvePoint& c) {
    if (on_point && !on_point(c)) stopped = true;
    return !stopped;
  });
  FootSweepSummary s = summarise_sweep(name, model, problem, sweep);
  s.stopped = stopped;
  return s;
}

}  // namespace cyclopt::studies
