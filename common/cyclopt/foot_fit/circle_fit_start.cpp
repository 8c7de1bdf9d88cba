#include "cyclopt/foot_fit/circle_fit_start.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cyclopt::foot_fit {

GroundCircle fit_ground_circle(const std::vector<double>& x, const std::vector<double>& z, bool heel) {
  const int n = static_cast<int>(x.size());
  const char* side = heel ? "heel (x < 0)" : "forefoot (x >= 0)";
  if (n < 3)
    throw std::invalid_argument(std::string("circle fit (eq. 4.10): ") + std::to_string(n) + " ankle points on the " + side +
                                " side of the lowest point, at least 3 needed (does the rolling phase include it?)");
  // x^2 + z^2 = u x + w with u = 2c, w = R^2 - c^2.
  Eigen::MatrixXd A(n, 2);
  Eigen::VectorXd b(n);
  for (int j = 0; j < n; ++j) {
    A(j, 0) = x[j];
    A(j, 1) = 1.0;
    b[j] = x[j] * x[j] + z[j] * z[j];
  }
  GroundCircle c;
  c.samples = n;
  const Eigen::Vector2d uw = A.colPivHouseholderQr().solve(b);
  double centre = 0.5 * uw[0], w = uw[1];
  if (heel ? centre > 0.0 : centre < 0.0) {
    centre = 0.0;
    w = b.mean();
    c.centre_on_bound = true;
  }
  const double r2 = w + centre * centre;
  if (!(r2 > 0.0)) throw std::invalid_argument(std::string("circle fit (eq. 4.10): degenerate circle on the ") + side + " side");
  c.centre = centre;
  c.radius = std::sqrt(r2);
  return c;
}

CircleFitStart circle_fit_start(const std::vector<AnkleTrack>& tracks) {
  if (tracks.empty()) throw std::invalid_argument("circle fit: no trials");
  CircleFitStart s;
  std::vector<double> xn, zn, xp, zp;
  s.z_min = std::numeric_limits<double>::infinity();
  for (const AnkleTrack& t : tracks) {
    const int lowest = static_cast<int>(std::min_element(t.z.begin(), t.z.end()) - t.z.begin());
    s.x_off.push_back(t.x[lowest]);
    s.z_min = std::min(s.z_min, t.z[lowest]);  // eq. (4.11a)
    for (int j = 0; j < t.samples(); ++j) {
      const double xs = t.x[j] - t.x[lowest];
      (xs < 0.0 ? xn : xp).push_back(xs);  // eq. (4.9)
      (xs < 0.0 ? zn : zp).push_back(t.z[j]);
    }
  }
  s.heel = fit_ground_circle(xn, zn, true);
  s.forefoot = fit_ground_circle(xp, zp, false);
  s.hm.resize(foot::hm::count);
  s.hm[foot::hm::h_F] = s.z_min;                               // (4.11a)
  s.hm[foot::hm::l_HA] = -s.heel.centre;                       // (4.11b)
  s.hm[foot::hm::l_HM] = s.forefoot.centre - s.heel.centre;    // (4.11c)
  s.hm[foot::hm::k_H] = 1e-8;                                  // section 4.2, after (4.17)
  s.hm[foot::hm::k_M] = 1e-8;
  s.hm[foot::hm::k_HM] = 0.1;
  // The angle at which the flat foot's ankle comes closest to each point, eq. (4.12).
  auto angle = [](const GroundCircle& c, double x, double z) {
    return std::acos(std::clamp(-c.centre / c.radius, -1.0, 1.0)) - std::atan2(z, x - c.centre);
  };
  for (std::size_t k = 0; k < tracks.size(); ++k) {
    const AnkleTrack& t = tracks[k];
    Eigen::VectorXd th(t.samples());
    for (int j = 0; j < t.samples(); ++j) {
      const double xs = t.x[j] - s.x_off[k];
      th[j] = angle(xs < 0.0 ? s.heel : s.forefoot, xs, t.z[j]);
    }
    s.theta.push_back(th);
  }
  return s;
}

}  // namespace cyclopt::foot_fit
