#include "cyclopt/qp/bounded_least_squares.hpp"

#include <Eigen/QR>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace cyclopt::qp {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

enum class State { free, at_lower, at_upper };

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument("solve_bounded_least_squares: " + message);
}

// Minimum-norm least-squares solution z of A_F z = rhs on the listed columns.
VectorXd free_solution(const MatrixXd& A, const std::vector<int>& free, const VectorXd& rhs) {
  if (free.empty()) return VectorXd();
  const MatrixXd AF = A(Eigen::all, free);
  return Eigen::CompleteOrthogonalDecomposition<MatrixXd>(AF).solve(rhs);
}

}  // namespace

BoundedLeastSquaresSolution solve_bounded_least_squares(const MatrixXd& A, const VectorXd& b, const VectorXd& lower,
                                                       const VectorXd& upper, const BoundedLeastSquaresOptions& options) {
  const Index m = A.rows(), n = A.cols();
  require(b.size() == m, "b has " + std::to_string(b.size()) + " entries, A " + std::to_string(m) + " rows");
  require(lower.size() == n && upper.size() == n, "lower and upper need one entry per column of A (" + std::to_string(n) + ")");
  require(A.allFinite() && b.allFinite(), "A and b must be finite");
  for (Index j = 0; j < n; ++j)
    require(!std::isnan(lower[j]) && !std::isnan(upper[j]) && lower[j] <= upper[j],
            "lower[" + std::to_string(j) + "] <= upper[" + std::to_string(j) + "] must hold");
  require(options.optimality_tolerance > 0, "options.optimality_tolerance must be > 0");
  require(options.max_iterations >= 1, "options.max_iterations must be >= 1");

  BoundedLeastSquaresSolution out;
  out.x = VectorXd::Zero(n);
  std::vector<State> state(static_cast<size_t>(n));
  std::vector<int> free;
  for (Index j = 0; j < n; ++j) {
    const size_t k = static_cast<size_t>(j);
    if (std::isfinite(lower[j])) state[k] = State::at_lower, out.x[j] = lower[j];
    else if (std::isfinite(upper[j])) state[k] = State::at_upper, out.x[j] = upper[j];
    else state[k] = State::free, free.push_back(static_cast<int>(j));
  }
  const VectorXd column_norms = A.colwise().norm().transpose();
  const double scale = std::max(1.0, b.norm());
  std::vector<char> excluded(static_cast<size_t>(n), 0);  // freed and bounced straight back: skipped until x moves
  int entering = -1;
  for (;;) {
    // Inner loop: the free set's least-squares solution, as far as the bounds allow.
    for (;;) {
      if (free.empty()) break;
      VectorXd rhs = b;
      for (Index j = 0; j < n; ++j)
        if (state[static_cast<size_t>(j)] != State::free) rhs -= out.x[j] * A.col(j);
      const VectorXd z = free_solution(A, free, rhs);
      double alpha = 1.0;
      for (size_t k = 0; k < free.size(); ++k) {
        const int j = free[k];
        const double from = out.x[j], to = z[static_cast<Index>(k)];
        if (to < lower[j]) alpha = std::min(alpha, (lower[j] - from) / (to - from));
        else if (to > upper[j]) alpha = std::min(alpha, (upper[j] - from) / (to - from));
      }
      alpha = std::max(0.0, alpha);
      for (size_t k = 0; k < free.size(); ++k) out.x[free[k]] += alpha * (z[static_cast<Index>(k)] - out.x[free[k]]);
      if (alpha >= 1.0) {
        if (alpha > 0.0) std::fill(excluded.begin(), excluded.end(), 0);
        break;
      }
      // Variables that reached (or, by rounding, crossed) a bound leave the free set there.
      std::vector<int> still_free;
      for (int j : free) {
        const size_t k = static_cast<size_t>(j);
        const double gap = 1e-14 * std::max(1.0, std::abs(out.x[j]));
        if (out.x[j] <= lower[j] + gap) state[k] = State::at_lower, out.x[j] = lower[j];
        else if (out.x[j] >= upper[j] - gap) state[k] = State::at_upper, out.x[j] = upper[j];
        else still_free.push_back(j);
      }
      if (still_free.size() == free.size()) {  // rounding: the limiting variable stayed inside; bound it
        double nearest = std::numeric_limits<double>::infinity();
        int limiting = free.front();
        for (int j : free) {
          const double d = std::min(out.x[j] - lower[j], upper[j] - out.x[j]);
          if (d < nearest) nearest = d, limiting = j;
        }
        const bool to_lower = out.x[limiting] - lower[limiting] <= upper[limiting] - out.x[limiting];
        state[static_cast<size_t>(limiting)] = to_lower ? State::at_lower : State::at_upper;
        out.x[limiting] = to_lower ? lower[limiting] : upper[limiting];
        std::erase(still_free, limiting);
      }
      if (alpha == 0.0 && entering >= 0 && state[static_cast<size_t>(entering)] != State::free)
        excluded[static_cast<size_t>(entering)] = 1;  // entered and left without moving x: degenerate
      else if (alpha > 0.0)
        std::fill(excluded.begin(), excluded.end(), 0);
      free = std::move(still_free);
      if (++out.iterations >= options.max_iterations) {
        out.residual = A * out.x - b;
        return out;
      }
    }
    // Outer step: free the bound variable whose gradient points furthest into its box.
    out.residual = A * out.x - b;
    const VectorXd descent = -(A.transpose() * out.residual);  // -gradient of 1/2 |Ax - b|^2
    const double threshold = options.optimality_tolerance * scale;
    entering = -1;
    double best = threshold;
    for (Index j = 0; j < n; ++j) {
      const size_t k = static_cast<size_t>(j);
      if (state[k] == State::free || excluded[k] || column_norms[j] == 0.0) continue;
      const double into_box = (state[k] == State::at_lower ? descent[j] : -descent[j]) / column_norms[j];
      if (into_box > best) best = into_box, entering = static_cast<int>(j);
    }
    if (entering < 0) {
      out.converged = true;
      return out;
    }
    state[static_cast<size_t>(entering)] = State::free;
    free.push_back(entering);
    if (++out.iterations >= options.max_iterations) return out;
  }
}

}  // namespace cyclopt::qp
