#include "cyclopt/nlp/kinked_terms.hpp"

#include <algorithm>
#include <cmath>

namespace cyclopt::nlp {

namespace {

Eigen::VectorXd reach(const KinkedTerms& kinks, double band) {
  return band * kinks.jacobian.rowwise().lpNorm<Eigen::Infinity>();
}

// The NearKinks of the listed terms (ascending, distinct).
NearKinks of_terms(const KinkedTerms& kinks, std::vector<int> terms) {
  NearKinks near;
  near.terms = std::move(terms);
  const Eigen::Index samples = kinks.values.size();
  std::vector<int> position(static_cast<size_t>(samples), -1);
  for (int k : near.terms) position[static_cast<size_t>(kinks.terms[static_cast<size_t>(k)].sample)] = 0;
  for (Eigen::Index s = 0; s < samples; ++s)
    if (position[static_cast<size_t>(s)] >= 0) {
      position[static_cast<size_t>(s)] = static_cast<int>(near.samples.size());
      near.samples.push_back(static_cast<int>(s));
    }
  near.weights = Eigen::VectorXd::Zero(near.size());
  near.slopes = Eigen::VectorXd::Zero(near.size());
  for (int k : near.terms) {
    const KinkedTerm& t = kinks.terms[static_cast<size_t>(k)];
    const int i = position[static_cast<size_t>(t.sample)];
    near.weights[i] += t.weight;
    near.slopes[i] += t.slope;
  }
  return near;
}

}  // namespace

NearKinks near_kinks(const KinkedTerms& kinks, double band) {
  const Eigen::VectorXd r = reach(kinks, band);
  auto at_kink = [&](int s) { return std::abs(kinks.values[s]) <= r[s]; };
  std::vector<int> terms;
  for (size_t k = 0; k < kinks.terms.size(); ++k) {
    const KinkedTerm& t = kinks.terms[k];
    if (at_kink(t.sample) && (t.partner < 0 || at_kink(t.partner))) terms.push_back(static_cast<int>(k));
  }
  return of_terms(kinks, std::move(terms));
}

Eigen::VectorXd kink_slopes(const KinkedTerms& kinks, const NearKinks& near) {
  Eigen::VectorXd slopes = Eigen::VectorXd::Zero(near.size());
  std::vector<int> position(static_cast<size_t>(kinks.values.size()), -1);
  for (size_t i = 0; i < near.samples.size(); ++i) position[static_cast<size_t>(near.samples[i])] = static_cast<int>(i);
  for (int k : near.terms) {
    const KinkedTerm& t = kinks.terms[static_cast<size_t>(k)];
    slopes[position[static_cast<size_t>(t.sample)]] += t.slope;
  }
  return slopes;
}

Eigen::MatrixXd kink_jacobian(const KinkedTerms& kinks, const NearKinks& near) {
  return kinks.jacobian(near.samples, Eigen::all);
}

double kink_band(const Eigen::VectorXd& x, double relative_band) {
  return relative_band * std::max(1.0, x.size() ? x.lpNorm<Eigen::Infinity>() : 0.0);
}

}  // namespace cyclopt::nlp
