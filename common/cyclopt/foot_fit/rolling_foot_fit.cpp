#include "cyclopt/foot_fit/rolling_foot_fit.hpp"

#include "cyclopt/autodiff/dual.hpp"
#include "cyclopt/foot/convexity_constraints.hpp"
#include "cyclopt/foot/foot_profile.hpp"

#include <Eigen/QR>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace cyclopt::foot_fit {
namespace {

constexpr double kSharp = 1e-8;  // rad: the fixed k_H, k_M, k_T of (4.13) / (4.18)
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kCollapsedK = 1e-4;  // rad: a fitted k below this gets one restart
constexpr double kRestartK = 0.05;    // rad: from there (the middle of the seed's fitted k_HM)
using D = ad::Dual<foot::kMaxFootParameters>;

int parameter_count(foot::FootModel m) { return m == foot::FootModel::hm ? int{foot::hm::count} : int{foot::hmt::count}; }

ConvexityCheck convexity_of(foot::FootModel model, const foot::FootParameters<double>& p) {
  ConvexityCheck c;
  const foot::LinearInequalities li = foot::convexity_constraints(model);
  const Eigen::VectorXd v = li.A * p + li.b;
  c.convex = true;
  for (Eigen::Index r = 0; r < v.size(); ++r) {
    c.names.push_back(li.names[r]);
    c.values.push_back(v[r]);
    c.convex = c.convex && v[r] >= 0.0;
  }
  if (model == foot::FootModel::hmt) {
    const double margin = foot::toe_convexity_margin(p);
    c.names.push_back("toe convexity margin x_T h_F - z_T l_HA > 0");
    c.values.push_back(margin);
    c.convex = c.convex && margin > 0.0;
  }
  return c;
}

// Runs the arrow solver for `model` from (p, theta, x_off) and fills the report.
FootFitResult run_fit(foot::FootModel model, const std::vector<AnkleTrack>& tracks, const foot::FootParameters<double>& p0,
                      const std::vector<Eigen::VectorXd>& theta0, const std::vector<double>& x_off0, const FitBounds& bounds,
                      const ArrowOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  const int P = parameter_count(model), K = static_cast<int>(tracks.size());
  int N = 0;
  for (const AnkleTrack& t : tracks) N += t.samples();
  Eigen::VectorXd global(P + K), local(N), lower(P + K), upper(P + K);
  global.head(P) = p0;
  lower.head(P) = bounds.lower;
  upper.head(P) = bounds.upper;
  for (int k = 0, j0 = 0; k < K; j0 += tracks[k].samples(), ++k) {
    global[P + k] = x_off0[k];
    lower[P + k] = -kInf;
    upper[P + k] = kInf;
    local.segment(j0, tracks[k].samples()) = theta0[k];
  }
  const ArrowResidual residual = rolling_ankle_residual(model, tracks);
  ArrowSummary s = solve_arrow_least_squares(residual, global, local, lower, upper, options);
  // A free regularisation that collapsed towards 0 sits on a plateau: with tanh(a/k) and k far
  // below the spacing of the fitted angles no sample sees the transition, so the gradient in k
  // vanishes without the fit being good. Restart once from k = kRestartK and keep the better.
  for (int i = 0; i < P; ++i) {
    const bool regularisation = foot::parameter_layout(model)[i].kind == foot::ParameterKind::regularisation;
    if (!regularisation || lower[i] == upper[i] || global[i] > kCollapsedK) continue;
    Eigen::VectorXd g2 = global, l2 = local;
    g2[i] = std::clamp(kRestartK, lower[i], upper[i]);
    ArrowSummary s2 = solve_arrow_least_squares(residual, g2, l2, lower, upper, options);
    s2.iterations += s.iterations;
    s2.evaluations += s.evaluations;
    if (s2.cost < s.cost) {
      global = g2;
      local = l2;
      s = s2;
    }
  }

  FootFitResult r;
  r.model = model;
  r.parameters = global.head(P);
  r.samples = N;
  r.converged = s.converged;
  r.iterations = s.iterations;
  r.message = s.message;
  int free_globals = 0;
  for (Eigen::Index i = 0; i < s.free.size(); ++i) free_globals += s.free[i] ? 1 : 0;
  r.unknowns = N + free_globals;
  for (int k = 0, j0 = 0; k < K; j0 += tracks[k].samples(), ++k) {
    r.theta.push_back(local.segment(j0, tracks[k].samples()));
    r.x_off.push_back(global[P + k]);
  }
  // Residuals per sample and trial.
  double sum2 = 0.0;
  for (int k = 0; k < K; ++k) {
    TrialResidual tr{tracks[k].source, tracks[k].samples(), 0.0, 0.0};
    double t2 = 0.0;
    for (int j = 0; j < tracks[k].samples(); ++j) {
      const double d = (r.model_ankle(k, j) - Eigen::Vector2d(tracks[k].x[j], tracks[k].z[j])).norm();
      t2 += d * d;
      tr.max = std::max(tr.max, d);
    }
    tr.rms = std::sqrt(t2 / std::max(1, tr.samples));
    sum2 += t2;
    r.max_residual = std::max(r.max_residual, tr.max);
    r.trials.push_back(tr);
  }
  r.rms = std::sqrt(sum2 / std::max(1, N));
  const int dof = 2 * N - r.unknowns;
  r.noise_estimate = dof > 0 ? std::sqrt(sum2 / dof) : std::numeric_limits<double>::quiet_NaN();
  // Standard errors of the free globals: sigma^2 times the inverse reduced normal matrix.
  std::vector<Eigen::Index> idx;
  for (Eigen::Index i = 0; i < P + K; ++i)
    if (s.free[i]) idx.push_back(i);
  Eigen::MatrixXd Sf(idx.size(), idx.size());
  for (std::size_t a = 0; a < idx.size(); ++a)
    for (std::size_t b = 0; b < idx.size(); ++b) Sf(a, b) = s.reduced_normal_matrix(idx[a], idx[b]);
  const Eigen::MatrixXd cov = r.noise_estimate * r.noise_estimate * Sf.completeOrthogonalDecomposition().pseudoInverse();
  const auto layout = foot::parameter_layout(model);
  for (int i = 0; i < P; ++i) {
    ParameterEstimate e;
    e.name = std::string(layout[i].name);
    e.unit = std::string(layout[i].unit);
    e.value = global[i];
    e.lower = lower[i];
    e.upper = upper[i];
    e.fixed = lower[i] == upper[i];
    e.at_bound = !e.fixed && !s.free[i];
    e.standard_error = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t a = 0; a < idx.size(); ++a)
      if (idx[a] == i) e.standard_error = std::sqrt(std::max(cov(a, a), 0.0));
    r.estimates.push_back(e);
  }
  r.convexity = convexity_of(model, r.parameters);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return r;
}

}  // namespace

FitBounds seed_bounds(foot::FootModel model, double z_min) {
  FitBounds b;
  if (model == foot::FootModel::hm) {  // eq. (4.13), library order h_F, l_HA, l_HM, k_H, k_HM, k_M
    b.lower.resize(foot::hm::count);
    b.upper.resize(foot::hm::count);
    b.lower << 0.5 * z_min, 0.0, 0.0, kSharp, kSharp, kSharp;
    b.upper << kInf, kInf, kInf, kSharp, 10.0, kSharp;
  } else if (model == foot::FootModel::hmt) {  // eq. (4.18): h_F, l_HA, l_HM, l_MT, gamma_F, k_H, k_HM, k_MT, k_T
    b.lower.resize(foot::hmt::count);
    b.upper.resize(foot::hmt::count);
    b.lower << 0.5 * z_min, 0.0, 0.0, 0.0, 0.0, kSharp, kSharp, kSharp, kSharp;
    b.upper << kInf, kInf, kInf, z_min, 0.5 * std::numbers::pi, kSharp, 10.0, 10.0, kSharp;
  } else {
    throw std::invalid_argument("model: only HM and HMT feet can be fitted");
  }
  return b;
}

FitBounds widened_to_contain(FitBounds b, const foot::FootParameters<double>& p) {
  for (Eigen::Index i = 0; i < p.size(); ++i)
    if (p[i] > b.upper[i] || p[i] < b.lower[i]) {
      b.upper[i] = std::max(b.upper[i], 2.0 * p[i]);
      b.lower[i] = std::min(b.lower[i], 0.5 * p[i]);
    }
  return b;
}

ArrowResidual rolling_ankle_residual(foot::FootModel model, const std::vector<AnkleTrack>& tracks) {
  const int P = parameter_count(model), K = static_cast<int>(tracks.size());
  int N = 0;
  for (const AnkleTrack& t : tracks) N += t.samples();
  return [model, &tracks, P, K, N](const Eigen::VectorXd& global, const Eigen::VectorXd& local, bool with_jacobian,
                                   ArrowEvaluation& out) {
    const foot::FootParameters<double> p = global.head(P);
    const foot::FootProfile<double> prof = foot::make_profile(model, p);
    const double f0 = foot::rolling_contact(prof, 0.0).F;
    out.r.resize(2, N);
    if (with_jacobian) out.local_jacobian.resize(2, N);
    for (int k = 0, j = 0; k < K; ++k)
      for (int i = 0; i < tracks[k].samples(); ++i, ++j) {
        const foot::RollingContact<double> c = foot::rolling_contact(prof, local[j]);
        out.r(0, j) = global[P + k] + c.F - f0 - tracks[k].x[i];  // eq. (4.15a) / (4.20a)
        out.r(1, j) = c.dF - tracks[k].z[i];                      // eq. (4.15b) / (4.20b)
        if (with_jacobian) out.local_jacobian.col(j) << c.dF, c.ddF;  // d r_j / d theta_j
      }
    if (!with_jacobian) return out.r.allFinite();
    // F is a sum over transitions of l_i times a function of (theta - delta_i, k_i) (eq. 3.19 /
    // 3.22). Per sample, each transition is differentiated in (delta_i, k_i) with Dual<2> at unit
    // length; the chain to p goes through d(l_i, delta_i, k_i)/dp, once per evaluation from the
    // profile built in Dual<9>.
    using D2 = ad::Dual<2>;
    foot::FootParameters<D> pd(P);
    for (int i = 0; i < P; ++i) pd[i] = D::variable(global[i], i);
    const foot::FootProfile<D> prof_d = foot::make_profile(model, pd);
    const int T = prof.transition_count;
    // Rows of d(l, delta, k)/dp per transition.
    using Rows3 = Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, foot::kMaxFootParameters>;
    using Rows2 = Eigen::Matrix<double, 2, Eigen::Dynamic, 0, 2, foot::kMaxFootParameters>;
    Rows3 dtr[4];
    for (int t = 0; t < T; ++t) {
      dtr[t].resize(3, P);
      dtr[t].row(0) = prof_d.transitions[t].length.d.head(P).transpose();
      dtr[t].row(1) = prof_d.transitions[t].angle.d.head(P).transpose();
      dtr[t].row(2) = prof_d.transitions[t].k.d.head(P).transpose();
    }
    // d[F, F'] / d(l, delta, k) of transition t at theta, from its unit-length contribution.
    auto transition_partials = [&](int t, double theta, Eigen::Matrix<double, 2, 3>& out_partials) {
      const foot::Transition<double>& tr = prof.transitions[t];
      const foot::Transition<D2> unit{D2(1.0), D2::variable(tr.angle, 0), D2::variable(tr.k, 1)};
      foot::RollingContact<D2> u{D2(0.0), D2(0.0), D2(0.0), D2(0.0)};
      foot::detail::add_transition(unit, prof.periodic_terms, D2(theta), u);
      out_partials << u.F.v, tr.length * u.F.d[0], tr.length * u.F.d[1], u.dF.v, tr.length * u.dF.d[0], tr.length * u.dF.d[1];
    };
    Eigen::Matrix<double, 1, Eigen::Dynamic, Eigen::RowMajor, 1, foot::kMaxFootParameters> df0 =
        Eigen::RowVectorXd::Zero(P);
    Eigen::Matrix<double, 2, 3> partials;
    for (int t = 0; t < T; ++t) {
      transition_partials(t, 0.0, partials);
      df0 += partials.row(0) * dtr[t];
    }
    out.global_jacobian.setZero(2 * N, P + K);
    for (int k = 0, j = 0; k < K; ++k)
      for (int i = 0; i < tracks[k].samples(); ++i, ++j) {
        Rows2 dp = Rows2::Zero(2, P);
        for (int t = 0; t < T; ++t) {
          transition_partials(t, local[j], partials);
          dp.noalias() += partials * dtr[t];
        }
        dp.row(0) -= df0;
        out.global_jacobian.block(2 * j, 0, 2, P) = dp;
        out.global_jacobian(2 * j, P + k) = 1.0;
      }
    return out.r.allFinite() && out.local_jacobian.allFinite() && out.global_jacobian.allFinite();
  };
}

foot::FootSpec FootFitResult::spec(const std::string& name) const {
  foot::FootSpec s;
  s.model = model;
  s.parameters = parameters;
  s.name = name;
  return s;
}

Eigen::Vector2d FootFitResult::model_ankle(int k, int j) const {
  const foot::FootProfile<double> prof = foot::make_profile(model, parameters);
  const double f0 = foot::rolling_contact(prof, 0.0).F;
  const foot::RollingContact<double> c = foot::rolling_contact(prof, theta[k][j]);
  return {x_off[k] + c.F - f0, c.dF};
}

FootFitResult fit_hm(const std::vector<AnkleTrack>& tracks, const CircleFitStart& start, const FootFitOptions& o) {
  const FitBounds b = o.hm_bounds ? *o.hm_bounds : seed_bounds(foot::FootModel::hm, start.z_min);
  return run_fit(foot::FootModel::hm, tracks, start.hm, start.theta, start.x_off, b, o.solver);
}

FootFitResult fit_hmt(const std::vector<AnkleTrack>& tracks, const FootFitResult& hm, double z_min, const FootFitOptions& o) {
  if (hm.model != foot::FootModel::hm) throw std::invalid_argument("fit_hmt: starts from an HM fit");
  namespace H = foot::hm;
  namespace T = foot::hmt;
  foot::FootParameters<double> p(T::count);
  p[T::h_F] = hm.parameters[H::h_F];
  p[T::l_HA] = hm.parameters[H::l_HA];
  p[T::l_HM] = hm.parameters[H::l_HM];
  p[T::l_MT] = hm.parameters[H::l_HM] / 10.0;  // section 4.2, after (4.22)
  p[T::gamma_F] = std::numbers::pi / 6.0;
  p[T::k_H] = hm.parameters[H::k_H];
  p[T::k_HM] = hm.parameters[H::k_HM];
  p[T::k_MT] = hm.parameters[H::k_HM];
  p[T::k_T] = hm.parameters[H::k_M];
  FitBounds b = o.hmt_bounds ? *o.hmt_bounds : seed_bounds(foot::FootModel::hmt, z_min);
  if (!o.hmt_bounds && !o.toe_bound) b.upper[T::l_MT] = kInf;
  // HMT contains HM: with l_MT = 0 the T transition is HM's M transition (eq. 3.23d -> 3.20c).
  // Besides the seed's start, two from the HM solution so embedded: a short toe (l_MT = l_HM/100,
  // taken from the sole, so toe angle and rounding are not degenerate) and l_MT = 0 exactly (the
  // HM residual itself: as the solver accepts only decreasing steps, the best of the three is
  // never worse than the HM fit). The seed notes (Fig. 4.5) that the HMT fit depends on its start.
  std::vector<foot::FootParameters<double>> starts{p, p, p};
  starts[1][T::l_MT] = hm.parameters[H::l_HM] / 100.0;
  starts[1][T::l_HM] = hm.parameters[H::l_HM] - starts[1][T::l_MT];
  starts[2][T::l_MT] = 0.0;
  FootFitResult best;
  double seconds = 0.0;
  int iterations = 0;
  for (const foot::FootParameters<double>& start : starts) {
    FootFitResult r = run_fit(foot::FootModel::hmt, tracks, start.cwiseMax(b.lower).cwiseMin(b.upper), hm.theta, hm.x_off, b, o.solver);
    seconds += r.seconds;
    iterations += r.iterations;
    if (iterations == r.iterations || r.rms < best.rms) best = std::move(r);
  }
  best.seconds = seconds;
  best.iterations = iterations;
  return best;
}

RollingFootFit fit_rolling_foot(const std::vector<AnkleTrack>& tracks, const FootFitOptions& o) {
  RollingFootFit f;
  f.start = circle_fit_start(tracks);
  f.hm = fit_hm(tracks, f.start, o);
  f.hmt = fit_hmt(tracks, f.hm, f.start.z_min, o);
  return f;
}

}  // namespace cyclopt::foot_fit
