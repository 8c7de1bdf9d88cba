#include "cyclopt/nlp/damped_bfgs.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <cmath>
#include <limits>

namespace cyclopt::nlp {
namespace {

// r of eq. (6.21).
Eigen::VectorXd damped_gradient_change(const Eigen::MatrixXd& W, const Eigen::VectorXd& s, const Eigen::VectorXd& y) {
  const Eigen::VectorXd Ws = W * s;
  const double sWs = s.dot(Ws), sy = s.dot(y);
  if (sy >= 0.2 * sWs) return y;
  const double theta = 0.8 * sWs / (sWs - sy);
  return theta * y + (1.0 - theta) * Ws;
}

}  // namespace

void damped_bfgs_update(Eigen::MatrixXd& W, const Eigen::VectorXd& s, const Eigen::VectorXd& y) {
  const Eigen::VectorXd Ws = W * s;
  const double sWs = s.dot(Ws);
  if (!(sWs > 0.0)) return;
  const Eigen::VectorXd r = damped_gradient_change(W, s, y);
  W += r * (r.transpose() / s.dot(r)) - Ws * (Ws.transpose() / sWs);
  W = 0.5 * (W + W.transpose()).eval();  // keep exactly symmetric against rounding drift
  // In exact arithmetic (6.22) keeps W positive definite; in floating point the curvature along
  // directions the steps keep revisiting can collapse to rounding level (eigenvalues 1e-13 beside
  // 1e4 seen on the walker). Such a W is restored to the floor of (6.24) - a safeguard, not in the seed.
  const Eigen::LLT<Eigen::MatrixXd> llt(W);
  const Eigen::VectorXd pivots = llt.matrixLLT().diagonal();
  if (llt.info() != Eigen::Success ||
      !(pivots.cwiseAbs2().minCoeff() >= std::sqrt(std::numeric_limits<double>::epsilon()) * W.diagonal().maxCoeff()))
    W = clamped_hessian(W);
}

Eigen::MatrixXd scaled_identity_update(const Eigen::VectorXd& s, const Eigen::VectorXd& y) {
  const Eigen::Index n = s.size();
  Eigen::MatrixXd W = Eigen::MatrixXd::Identity(n, n);
  if (!(s.squaredNorm() > 0.0)) return W;
  const Eigen::VectorXd r = damped_gradient_change(W, s, y);
  W *= r.squaredNorm() / s.dot(r);
  damped_bfgs_update(W, s, y);
  return W;
}

Eigen::MatrixXd clamped_hessian(const Eigen::MatrixXd& H) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(0.5 * (H + H.transpose()));
  const double largest = eigen.eigenvalues().maxCoeff();
  if (!(largest > 0.0)) return Eigen::MatrixXd::Identity(H.rows(), H.cols());
  const double floor = std::sqrt(std::numeric_limits<double>::epsilon()) * largest;
  return eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(floor).asDiagonal() * eigen.eigenvectors().transpose();
}

}  // namespace cyclopt::nlp
