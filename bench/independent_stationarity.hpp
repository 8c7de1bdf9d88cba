#pragma once
// A gait's distance from a (nonsmooth) KKT point of the seed's f_mech problem, computed without the
// solver's multipliers, its AD derivatives or its kink model (issue 52 acceptance 1; the measure of
// bench/results/speed_sweep_bench.txt block "12-06 03:05" item 4):
//
//   f_mech = F(p, t, L) = sum_j sum_i rule(p_ji, p_j,i+1, t_i+1 - t_i) / (m g L)   (5.102, Fig. 5.3)
//
// with the joint powers p = u q_dot, the grid times t and the step length L of the gait at z. The
// derivatives in the gait parameters are complex steps on the templated gait (of p, t, L and the
// constraints: n complex gait evaluations; central differences were 6e-4 off at 0.3 m/s, where the
// gait nearly stops mid-step), F's in t a central difference (F is linear in each interval's
// length), and F's in a power sample away from its kink the rule's own partial derivative (forward
// mode on its two ends). The samples with |p| <= eps are at their
// kink: there the slope of F is replaced by a free sigma in [0, w] - the trapezoid weight of the
// sample ("sample box", item 4's measure) or, stricter, only for intervals whose two samples are both
// within eps, half the interval's weight per end ("interval box": the seed's rule is smooth at a
// vanishing sample whose neighbour does not vanish). The residual is the least
//   | grad_rest + sum sigma_k grad p_k + J_eq' y + J_act' mu |_inf
// over sigma in the boxes, free y and mu >= 0 on the inequalities with |c_i| <= active, in the
// infinity norm at the least-squares multipliers (a bound-constrained least-squares problem solved
// by the primal active-set QP method of qp/, not the solver's BVLS).

#include "cyclopt/autodiff/dual.hpp"
#include "cyclopt/qp/active_set_solver.hpp"
#include "cyclopt/walker/gait_problem.hpp"
#include "cyclopt/walker/positive_power.hpp"

#include <Eigen/Core>

#include <cmath>
#include <complex>
#include <limits>
#include <vector>

namespace cyclopt::bench {

struct IndependentStationarity {
  bool evaluated = false;
  double violation = std::numeric_limits<double>::quiet_NaN();  // max(|c_eq|, max(c_in, 0))
  double sample_box = std::numeric_limits<double>::quiet_NaN();    // residual, item 4's measure
  double interval_box = std::numeric_limits<double>::quiet_NaN();  // residual, intervals gated
  int samples_at_kink = 0;  // |p| <= eps
};

namespace detail {

template <class T>
struct GaitSample {
  Eigen::Matrix<T, Eigen::Dynamic, 1> power;  // sample j P + i
  Eigen::Matrix<T, Eigen::Dynamic, 1> time;
  T step_length{};
  Eigen::Matrix<T, Eigen::Dynamic, 1> constraints;  // [c_eq; c_in]
};

template <class MT, class XVector, class T = typename XVector::Scalar>
bool sample_gait(const walker::WalkerModel<MT>& model, const walker::BezierBasis& basis, const XVector& x,
                 const walker::GaitOptions& options, GaitSample<T>& s) {
  const walker::PeriodicGait<T> g = walker::periodic_gait(model, basis, x, options);
  if (!g.real) return false;
  const walker::GaitTrajectory<T>& tr = g.trajectory;
  const Eigen::Index joints = tr.torque.rows(), points = tr.torque.cols();
  s.power.resize(joints * points);
  for (Eigen::Index j = 0; j < joints; ++j)
    for (Eigen::Index i = 0; i < points; ++i) s.power[j * points + i] = tr.torque(j, i) * tr.q_dot(1 + j, i);
  s.time = tr.time;
  s.step_length = g.step_length;
  s.constraints.resize(1 + g.inequalities.size());
  s.constraints << g.speed_equality, g.inequalities;
  return true;
}

// |g + M v|_inf at the least |g + M v|_2 over lower <= v <= upper: the QP min 1/2 |g + M v|^2 solved by
// the primal active-set method of qp/ on unit-norm columns (a 1e-12 ridge keeps its reduced
// Hessians regular). Never above |g|_inf for a solution worth the name (v = 0 is admissible): NaN
// otherwise.
inline double least_residual(const Eigen::VectorXd& g, const Eigen::MatrixXd& M, const Eigen::VectorXd& lower,
                             const Eigen::VectorXd& upper) {
  const Eigen::Index m = M.cols();
  const Eigen::VectorXd scale = M.colwise().norm().transpose().cwiseMax(1e-300);
  const Eigen::MatrixXd Ms = M * scale.cwiseInverse().asDiagonal();
  qp::QuadraticProgram q;
  q.hessian = Ms.transpose() * Ms + 1e-12 * Eigen::MatrixXd::Identity(m, m);
  q.gradient = Ms.transpose() * g;
  q.equality_matrix = Eigen::MatrixXd(0, m);
  q.equality_rhs = Eigen::VectorXd(0);
  q.inequality_matrix = Eigen::MatrixXd(0, m);
  q.inequality_rhs = Eigen::VectorXd(0);
  q.lower_bounds = lower.cwiseProduct(scale);
  q.upper_bounds = upper.cwiseProduct(scale);
  qp::ActiveSetOptions o;
  o.max_iterations = 100000;
  const qp::QpSolution s = qp::solve_active_set(q, o);
  if (s.status != qp::QpStatus::optimal) return std::numeric_limits<double>::quiet_NaN();
  const double r = (g + Ms * s.x).lpNorm<Eigen::Infinity>();
  return r <= g.lpNorm<Eigen::Infinity>() * (1.0 + 1e-12) ? r : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace detail

// eps: the kink band (W); active: the inequalities counted active (scaled units, |c_i| <= active).
inline IndependentStationarity independent_stationarity(const walker::GaitProblem& problem, const Eigen::VectorXd& z,
                                                        double eps, double active) {
  using Eigen::Index;
  using Eigen::MatrixXd;
  using Eigen::VectorXd;
  constexpr double inf = std::numeric_limits<double>::infinity();
  IndependentStationarity out;
  using C = std::complex<double>;
  constexpr double kStep = 1e-30;  // complex step
  const walker::WalkerModel<double> model = problem.model_at(z);
  const walker::GaitEvaluator evaluator(model);
  walker::GaitOptions options;
  options.speed = problem.options().speed;
  const Eigen::VectorXd x = problem.gait_parameters(z);
  detail::GaitSample<double> s0;
  if (!detail::sample_gait(model, evaluator.basis(), x, options, s0)) return out;
  const Index n = x.size(), samples = s0.power.size(), points = s0.time.size(), joints = samples / points;
  const Index m = s0.constraints.size();
  out.violation = std::max(std::abs(s0.constraints[0]), std::max(0.0, s0.constraints.tail(m - 1).maxCoeff()));
  // Derivatives in the gait parameters by the complex step on the templated gait (free model
  // parameters are not differentiated: the bench's problems have none).
  const walker::WalkerModel<C> complex_model = walker::cast_model<C>(model);
  MatrixXd Jp(samples, n), Jt(points, n), Jc(m, n);
  VectorXd JL(n);
  for (Index j = 0; j < n; ++j) {
    Eigen::VectorXcd xc = x.cast<C>();
    xc[j] += C(0.0, kStep);
    detail::GaitSample<C> sc;
    if (!detail::sample_gait(complex_model, evaluator.basis(), xc, options, sc)) return out;
    Jp.col(j) = sc.power.imag() / kStep;
    Jt.col(j) = sc.time.imag() / kStep;
    Jc.col(j) = sc.constraints.imag() / kStep;
    JL[j] = sc.step_length.imag() / kStep;
  }
  out.evaluated = true;
  const double weight = model.total_mass * model.constants.gravity;
  const double L = s0.step_length;
  const auto interval = [&](double a, double b, Index i, const VectorXd& t) {  // rule of one interval, / (m g L)
    return walker::positive_part_trapezoid(a, b, t[i + 1] - t[i]) / (weight * L);
  };
  const auto F = [&](const VectorXd& p, const VectorXd& t) {
    double sum = 0.0;
    for (Index j = 0; j < joints; ++j)
      for (Index i = 0; i + 1 < points; ++i) sum += interval(p[j * points + i], p[j * points + i + 1], i, t);
    return sum;
  };
  // The smooth part of the gradient: through t (F is linear in each dt) and L (F ~ 1 / L).
  VectorXd dF_dt(points);
  for (Index i = 0; i < points; ++i) {
    const double h = 1e-9 * std::max(1.0, std::abs(s0.time[i]));
    VectorXd tp = s0.time, tm = s0.time;
    tp[i] += h;
    tm[i] -= h;
    dF_dt[i] = (F(s0.power, tp) - F(s0.power, tm)) / (2.0 * h);
  }
  const VectorXd smooth = Jt.transpose() * dF_dt - F(s0.power, s0.time) / L * JL;
  // d(interval rule)/d(end): the rule's exact partial derivative (forward mode in its two ends; a
  // central difference is useless near a held joint, where the rule's curvature is dt / |p|).
  const auto end_slope = [&](Index left, Index i, bool right_end) {
    using D = ad::Dual<2>;
    const D rule = walker::positive_part_trapezoid(D::variable(s0.power[left], 0), D::variable(s0.power[left + 1], 1),
                                                   D(s0.time[i + 1] - s0.time[i]));
    return rule.d[right_end ? 1 : 0] / (weight * L);
  };
  std::vector<Index> active_rows{0};  // the equality, then the active inequalities
  for (Index r = 1; r < m; ++r)
    if (std::abs(s0.constraints[r]) <= active) active_rows.push_back(r);
  const Index a = static_cast<Index>(active_rows.size());
  for (Index k = 0; k < samples; ++k) out.samples_at_kink += std::abs(s0.power[k]) <= eps;
  for (bool gated : {false, true}) {
    VectorXd g = smooth, box = VectorXd::Zero(samples);
    for (Index j = 0; j < joints; ++j)
      for (Index i = 0; i + 1 < points; ++i) {
        const Index left = j * points + i;
        const bool near_left = std::abs(s0.power[left]) <= eps, near_right = std::abs(s0.power[left + 1]) <= eps;
        const double half = 0.5 * (s0.time[i + 1] - s0.time[i]) / (weight * L);
        // Ungated: a sample at its kink takes [0, half] from each of its intervals; gated only from
        // intervals at their kink (both ends), its other intervals keep their slope.
        const bool kinked = gated ? near_left && near_right : false;
        for (bool right_end : {false, true}) {
          const Index k = left + (right_end ? 1 : 0);
          const bool at_kink = gated ? kinked : (right_end ? near_right : near_left);
          if (at_kink) box[k] += half;
          else g += end_slope(left, i, right_end) * Jp.row(k).transpose();
        }
      }
    std::vector<Index> kinked;
    for (Index k = 0; k < samples; ++k)
      if (box[k] > 0.0) kinked.push_back(k);
    const Index K = static_cast<Index>(kinked.size());
    MatrixXd M(n, K + a);
    VectorXd lo(K + a), hi(K + a);
    for (Index c = 0; c < K; ++c) {
      M.col(c) = Jp.row(kinked[static_cast<size_t>(c)]).transpose();
      lo[c] = 0.0;
      hi[c] = box[kinked[static_cast<size_t>(c)]];
    }
    for (Index c = 0; c < a; ++c) {
      M.col(K + c) = Jc.row(active_rows[static_cast<size_t>(c)]).transpose();
      lo[K + c] = c == 0 ? -inf : 0.0;
      hi[K + c] = inf;
    }
    (gated ? out.interval_box : out.sample_box) = detail::least_residual(g, M, lo, hi);
  }
  return out;
}

}  // namespace cyclopt::bench
