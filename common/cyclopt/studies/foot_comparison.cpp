#include "cyclopt/studies/foot_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
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

// f_mech of the gait at each found best point (so also for an f_usq objective), NaN elsewhere.
std::vector<double> f_mech_of(const walker::WalkerModel<double>& model, const walker::GaitProblemOptions& problem,
                              const std::vector<BestPoint>& best) {
  std::vector<double> f;
  for (const BestPoint& b : best) {
    double value = kNaN;
    if (b.found) {
      walker::GaitProblemOptions po = problem;
      po.speed = b.speed;
      const walker::PeriodicGait<double> g = walker::GaitProblem(model, po).gait_at(b.point.x);
      if (g.real) value = g.f_mech;
    }
    f.push_back(value);
  }
  return f;
}

// Ranks the compared feet by saving and sets each foot's seed savings, rank and order_held.
void rank_feet(FootComparisonResult& r) {
  const FootSweepSummary& ref = r.feet[r.reference];
  for (std::size_t k = 0; k < r.feet.size(); ++k) {
    FootSweepSummary& s = r.feet[k];
    s.seed_savings.clear();
    if (k == r.reference) continue;
    for (std::size_t i = 0; i < s.seed_f_mech.size() && i < ref.seed_f_mech.size(); ++i) {
      int count = 0;
      double mean = 0.0;
      s.seed_savings.push_back(saving_of(s.seed_f_mech[i], ref.seed_f_mech[i], &count, &mean));
    }
    r.ranking.push_back(static_cast<int>(k));
  }
  std::stable_sort(r.ranking.begin(), r.ranking.end(), [&](int a, int b) {
    const double sa = r.feet[static_cast<std::size_t>(a)].saving, sb = r.feet[static_cast<std::size_t>(b)].saving;
    if (std::isfinite(sa) != std::isfinite(sb)) return std::isfinite(sa);
    return sa > sb;
  });
  for (std::size_t n = 0; n < r.ranking.size(); ++n) {
    FootSweepSummary& a = r.feet[static_cast<std::size_t>(r.ranking[n])];
    a.rank = static_cast<int>(n);
    if (n + 1 == r.ranking.size() || a.seed_savings.size() < 2) continue;
    const FootSweepSummary& b = r.feet[static_cast<std::size_t>(r.ranking[n + 1])];
    bool held = a.seed_savings.size() == b.seed_savings.size();
    for (std::size_t i = 0; held && i < a.seed_savings.size(); ++i)
      held = std::isfinite(a.seed_savings[i]) && (!std::isfinite(b.seed_savings[i]) || a.seed_savings[i] >= b.seed_savings[i]);
    a.order_held = held;
  }
}

}  // namespace

double spread(const std::vector<double>& values) {
  if (values.size() < 2 || !std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); })) return kNaN;
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  return *hi - *lo;
}

FootSweepSummary summarise_sweep(const std::string& name, const walker::WalkerModel<double>& model,
                                 const walker::GaitProblemOptions& problem, const SpeedSweepResult& sweep) {
  FootSweepSummary s;
  s.name = name;
  s.best = sweep.best;
  s.seconds = sweep.seconds;
  s.curves = sweep.curves;
  s.recoveries = sweep.recoveries;
  s.f_mech = f_mech_of(model, problem, sweep.best);
  s.speeds_found = static_cast<int>(std::count_if(s.f_mech.begin(), s.f_mech.end(), [](double f) { return std::isfinite(f); }));
  for (const SeedSearch& search : sweep.searches) {
    s.seeds.push_back(search.seed);
    s.seed_f_mech.push_back(search.best.size() == sweep.best.size() && sweep.searches.size() > 1 ? f_mech_of(model, problem, search.best)
                                                                                                 : s.f_mech);
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
  rank_feet(r);
  return r;
}

FootSweepSummary sweep_foot(const std::string& name, const walker::WalkerModel<double>& model,
                            const walker::GaitProblemOptions& problem, const SpeedSweepOptions& options,
                            SpeedSweepObserver& observer) {
  const SpeedSweepResult sweep = speed_sweep(model, problem, options, observer);
  FootSweepSummary s = summarise_sweep(name, model, problem, sweep);
  s.stopped = sweep.stopped;
  return s;
}

FootSweepSummary sweep_foot(const std::string& name, const walker::WalkerModel<double>& model,
                            const walker::GaitProblemOptions& problem, const SpeedSweepOptions& options,
                            const PointCallback& on_point) {
  PointObserver points(on_point);
  return sweep_foot(name, model, problem, options, points);
}

}  // namespace cyclopt::studies
