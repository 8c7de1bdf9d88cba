#include "cyclopt/nlp/nelder_mead.hpp"

#include <cmath>
#include <limits>
#include <vector>

namespace cyclopt::nlp {

const char* to_string(NelderMeadTermination t) {
  switch (t) {
    case NelderMeadTermination::converged: return "converged";
    case NelderMeadTermination::max_evaluations: return "max_evaluations";
  }
  return "unknown";
}

NelderMeadSummary nelder_mead(const std::function<double(const Eigen::VectorXd&)>& f, const Eigen::VectorXd& x0,
                              const NelderMeadOptions& options) {
  const Eigen::Index n = x0.size();
  NelderMeadSummary summary;
  std::vector<Eigen::VectorXd> p(static_cast<std::size_t>(n + 1), x0);
  std::vector<double> y(p.size());
  auto evaluate = [&](const Eigen::VectorXd& x) {
    ++summary.evaluations;
    const double v = f(x);
    return std::isnan(v) ? std::numeric_limits<double>::infinity() : v;
  };
  for (Eigen::Index i = 0; i < n; ++i) p[static_cast<std::size_t>(i + 1)][i] += options.initial_step;  // (4.2)
  for (std::size_t i = 0; i < p.size(); ++i) y[i] = evaluate(p[i]);
  Eigen::VectorXd psum = Eigen::VectorXd::Zero(n);  // (4.4)
  for (const auto& pi : p) psum += pi;

  // amotry: p_try = p_s + c (p_ihi - p_s) with p_s = (psum - p_ihi)/n (4.5, 4.6); replaces p_ihi if better.
  auto try_point = [&](std::size_t ihi, double c) {
    const Eigen::VectorXd ps = (psum - p[ihi]) / double(n);
    const Eigen::VectorXd ptry = ps + c * (p[ihi] - ps);
    const double ytry = evaluate(ptry);
    if (ytry < y[ihi]) {
      y[ihi] = ytry;
      psum += ptry - p[ihi];
      p[ihi] = ptry;
    }
    return ytry;
  };

  for (;;) {
    std::size_t ilo = 0, ihi = y[0] > y[1] ? 0 : 1, inhi = y[0] > y[1] ? 1 : 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (y[i] <= y[ilo]) ilo = i;
      if (y[i] > y[ihi]) {
        inhi = ihi;
        ihi = i;
      } else if (y[i] > y[inhi] && i != ihi) {
        inhi = i;
      }
    }
    const double spread = 2.0 * std::abs(y[ihi] - y[ilo]) / (std::abs(y[ihi]) + std::abs(y[ilo]) + 1e-300);
    if (spread < options.f_tolerance || summary.evaluations >= options.max_evaluations) {
      summary.termination =
          spread < options.f_tolerance ? NelderMeadTermination::converged : NelderMeadTermination::max_evaluations;
      summary.x = p[ilo];
      summary.f = y[ilo];
      return summary;
    }
    ++summary.iterations;
    const double ytry = try_point(ihi, -1.0);  // reflection
    if (ytry <= y[ilo]) {
      try_point(ihi, 2.0);  // expansion
    } else if (ytry >= y[inhi]) {
      const double ysave = y[ihi];
      if (try_point(ihi, 0.5) >= ysave) {  // contraction failed: multiple contraction (4.8)
        for (std::size_t i = 0; i < p.size(); ++i) {
          if (i == ilo) continue;
          p[i] = 0.5 * (p[i] + p[ilo]);
          y[i] = evaluate(p[i]);
        }
        psum.setZero();
        for (const auto& pi : p) psum += pi;
      }
    }
  }
}

}  // namespace cyclopt::nlp
