#pragma once
// Damped BFGS approximation W of the Hessian of the Lagrangian (seed 001, section 6.2.3;
// Nocedal & Wright, Procedure 18.2). W stays symmetric positive definite.

#include <Eigen/Core>

namespace cyclopt::nlp {

// eqs. (6.21), (6.22): with step s = x_{k+1} - x_k and y = grad L(x_{k+1}) - grad L(x_k) (6.20),
// r = theta y + (1 - theta) W s, theta = 1 if s'y >= 0.2 s'Ws, else 0.8 s'Ws / (s'Ws - s'y);
// W <- W - W s s' W / (s'Ws) + r r' / (s'r). No change for s = 0.
void damped_bfgs_update(Eigen::MatrixXd& W, const Eigen::VectorXd& s, const Eigen::VectorXd& y);

// eq. (6.25), started from W_1 = I: W_2 is the damped update (6.22) of the scaled identity
// delta I, delta = r'r / (s'r) with r from (6.21) at W = I (Nocedal & Wright eq. (6.20) with y
// replaced by the damped r). The OCR of (6.25) is garbled; this is the derivation from the
// reference it cites. Returns W_2.
Eigen::MatrixXd scaled_identity_update(const Eigen::VectorXd& s, const Eigen::VectorXd& y);

// eq. (6.24): the symmetric matrix H with its eigenvalues raised to max(lambda_i, sqrt(eps) lambda_max),
// a positive definite W_1 from a (complex-step/AD) Hessian of the Lagrangian (6.23). If
// lambda_max <= 0 (no positive curvature at all) the identity is returned.
Eigen::MatrixXd clamped_hessian(const Eigen::MatrixXd& H);

}  // namespace cyclopt::nlp
