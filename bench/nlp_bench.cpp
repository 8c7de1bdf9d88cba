// Solver cost at the walker's size (issue 4: ~30 variables, ~2000 dense inequality constraints)
// on a synthetic smooth NLP with a known feasible point: Ipopt and the seed's SQP from the same
// 20 perturbed starts (multistart on all cores), iterations, evaluations, time, agreement.
#include "cyclopt/nlp/multistart.hpp"
#include "machine_info.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

using namespace cyclopt::nlp;

namespace {

// f = |x - a|^2 + 0.05 sum x^4;  c_eq = B x + 0.05 x'x - b;  c_in = G x + 0.1 sin(G x) - h <= 0,
// with b, h built from a feasible point x_f (h with random margins, a fifth of them zero).
struct SyntheticData {
  Eigen::VectorXd a, x_feasible, b, h;
  Eigen::MatrixXd B, G;
};

SyntheticData make_data(int n, int m_eq, int m_in, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  SyntheticData d;
  d.a = Eigen::VectorXd::NullaryExpr(n, [&] { return 2.0 * normal(rng); });
  d.x_feasible = Eigen::VectorXd::NullaryExpr(n, [&] { return 0.3 * normal(rng); });
  d.B = Eigen::MatrixXd::NullaryExpr(m_eq, n, [&] { return normal(rng); });
  d.b = d.B * d.x_feasible + Eigen::VectorXd::Constant(m_eq, 0.05 * d.x_feasible.squaredNorm());
  d.G = Eigen::MatrixXd::NullaryExpr(m_in, n, [&] { return normal(rng); });
  const Eigen::VectorXd gx = d.G * d.x_feasible;
  d.h = gx + 0.1 * gx.array().sin().matrix();
  for (int i = 0; i < m_in; ++i)
    if (uniform(rng) > 0.2) d.h[i] += 3.0 * uniform(rng);
  return d;
}

class SyntheticProblem : public Problem {
 public:
  explicit SyntheticProblem(const SyntheticData& d) : d_(d) {}
  int num_variables() const override { return static_cast<int>(d_.a.size()); }
  int num_equalities() const override { return static_cast<int>(d_.b.size()); }
  int num_inequalities() const override { return static_cast<int>(d_.h.size()); }
  EvaluationStatus evaluate(const Eigen::VectorXd& x, bool with_derivatives, Evaluation& e) override {
    const Eigen::VectorXd gx = d_.G * x;
    e.objective = (x - d_.a).squaredNorm() + 0.05 * x.array().pow(4).sum();
    e.equalities = d_.B * x + Eigen::VectorXd::Constant(d_.b.size(), 0.05 * x.squaredNorm()) - d_.b;
    e.inequalities = gx + 0.1 * gx.array().sin().matrix() - d_.h;
    if (with_derivatives) {
      e.gradient = 2.0 * (x - d_.a) + 0.2 * x.array().cube().matrix();
      e.equality_jacobian = d_.B + 0.1 * Eigen::VectorXd::Ones(d_.b.size()) * x.transpose();
      e.inequality_jacobian = (1.0 + 0.1 * gx.array().cos()).matrix().asDiagonal() * d_.G;
    }
    return EvaluationStatus::success();
  }

 private:
  const SyntheticData& d_;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

}  // namespace

// Usage: nlp_bench [m_in = 2000] [starts = 20] [print_level = 0] [solver = both | ipopt | sqp]
int main(int argc, char** argv) {
  const int n = 30, m_eq = 6;
  const int m_in = argc > 1 ? std::atoi(argv[1]) : 2000, starts = argc > 2 ? std::atoi(argv[2]) : 20;
  std::printf("nlp_bench on %s\n", cyclopt::bench::machine_line().c_str());
  std::printf("synthetic NLP: n = %d, m_eq = %d, m_in = %d (dense), %d starts x_f + N(0, 0.5^2)\n\n", n, m_eq, m_in, starts);
  const SyntheticData data = make_data(n, m_eq, m_in, 2026);
  std::vector<MultistartResult> results;
  const int print_level = argc > 3 ? std::atoi(argv[3]) : 0;
  const std::string only = argc > 4 ? argv[4] : "both";
  for (SolverKind kind : {SolverKind::ipopt, SolverKind::sqp}) {
    if (only != "both" && parse_solver_kind(only, "solver argument") != kind) continue;
    MultistartOptions o;
    o.solver.print_level = print_level;
    o.num_starts = starts;
    o.base_seed = 7;
    o.solver.solver = kind;
    results.push_back(multistart([&] { return std::make_unique<SyntheticProblem>(data); },
                                 [&](std::mt19937_64& rng) {
                                   std::normal_distribution<double> normal(0.0, 0.5);
                                   return Eigen::VectorXd(data.x_feasible + Eigen::VectorXd::NullaryExpr(n, [&] { return normal(rng); }));
                                 },
                                 o));
    const MultistartResult& r = results.back();
    std::vector<double> seconds, iterations, evaluations;
    for (const SolverSummary& s : r.runs) {
      seconds.push_back(s.wall_seconds);
      iterations.push_back(s.iterations);
      evaluations.push_back(s.function_evaluations + s.jacobian_evaluations);
    }
    std::printf("%-6s KKT successes %2d/%d, distinct optima %zu, best f %.12f\n", to_string(kind), r.successes, starts,
                r.optima.size(), r.optima.empty() ? NAN : r.optima.front().objective);
    std::printf("       median per start: %.0f iterations, %.0f evaluations, %.3f s; multistart wall %.2f s\n", median(iterations),
                median(evaluations), median(seconds), r.wall_seconds);
    for (size_t i = 0; i < r.runs.size(); ++i)
      if (!r.runs[i].success())
        std::printf("       start %zu: %s after %d iterations: %s\n", i, to_string(r.runs[i].termination), r.runs[i].iterations,
                    r.runs[i].message.c_str());
  }
  if (results.size() < 2) return 0;
  double worst = 0.0;
  for (int i = 0; i < starts; ++i) {
    const SolverSummary &a = results[0].runs[static_cast<size_t>(i)], &b = results[1].runs[static_cast<size_t>(i)];
    if (a.success() && b.success()) worst = std::max(worst, std::abs(a.objective - b.objective) / std::max(1.0, std::abs(a.objective)));
  }
  std::printf("\nlargest relative objective difference ipopt vs sqp from the same start: %.1e\n", worst);
}
