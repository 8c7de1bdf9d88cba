// Mass properties from geometry (seed 001, appendix E), checked against the closed-form
// properties of the generating polygon and against the seed's density of section 10.2.
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/foot/mass_properties.hpp"
#include "random_feet.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace cyclopt::foot {
namespace {

using testing::RandomFeet;
using testing::with_all_k;

FootProfile<double> profile_of(const FootSpec& s) { return make_profile(s.model, s.parameters, s.periodic_terms); }

struct PolygonProperties {
  double area, cx, cz, polar;  // polar: integral of |r|^2 dA about the origin
};

// Closed-form properties of a simple polygon from the vertex-pair formulas, evaluated
// independently of the foot code.
PolygonProperties polygon_properties(const FootSpec& s) {
  const auto& p = s.parameters;
  std::vector<std::array<double, 2>> v = {{0.0, 0.0}, {-p[1], -p[0]}, {p[2] - p[1], -p[0]}};
  if (s.model == FootModel::hmt)
    v.push_back({p[2] - p[1] + p[3] * std::cos(p[4]), -p[0] + p[3] * std::sin(p[4])});
  double a2 = 0, sx = 0, sz = 0, ip = 0;
  for (std::size_t j = 0; j < v.size(); ++j) {
    const auto [x0, z0] = v[j];
    const auto [x1, z1] = v[(j + 1) % v.size()];
    const double w = x0 * z1 - x1 * z0;
    a2 += w;
    sx += (x0 + x1) * w;
    sz += (z0 + z1) * w;
    ip += (x0 * x0 + x0 * x1 + x1 * x1 + z0 * z0 + z0 * z1 + z1 * z1) * w;
  }
  return {std::abs(a2) / 2, sx / (3 * a2), sz / (3 * a2), std::abs(ip) / 12};
}

// Acceptance 5b: a near-polygonal foot (all k = 1e-8) has the polygon's area, centroid and inertia.
TEST(MassProperties, NearPolygonalFootMatchesPolygonClosedForm) {
  RandomFeet rnd(8);
  std::vector<FootSpec> feet = {foot_preset("P1-barefoot-left-HM").spec, foot_preset("P2-shoes-left-HMT").spec};
  for (int i = 0; i < 20; ++i) {
    FootSpec s = rnd.any();
    if (s.parameters[hm::h_F] < 0.01) continue;  // a degenerate polygon has no area
    feet.push_back(s);
  }
  for (const FootSpec& base : feet) {
    const FootSpec s = with_all_k(base, 1e-8);
    const double rho = 30.0;
    const FootMassProperties<double> mp = mass_properties(profile_of(s), rho);
    const PolygonProperties poly = polygon_properties(s);
    const double len = s.parameters[hm::l_HM];
    EXPECT_NEAR(mp.area, poly.area, 1e-6 * poly.area) << base.name;
    EXPECT_NEAR(mp.mass, rho * poly.area, 1e-6 * rho * poly.area);
    EXPECT_NEAR(mp.com_x, poly.cx, 1e-6 * len);
    EXPECT_NEAR(mp.com_z, poly.cz, 1e-6 * len);
    EXPECT_NEAR(mp.inertia_ankle, rho * poly.polar, 1e-6 * rho * poly.polar);
    const double steiner = rho * poly.polar - rho * poly.area * (poly.cx * poly.cx + poly.cz * poly.cz);
    EXPECT_NEAR(mp.inertia_com, steiner, 1e-5 * rho * poly.polar);
  }
}

// Acceptance 5a: section 10.2 finds rho = 36.9 kg/m^2 for the HMT foot of P2 (shoes, left,
// Table B.9) so that the foot has the mass m_F = 0.96 kg of Table 5.1.
TEST(MassProperties, SeedDensityForP2ShoesGivesTableMass) {
  const FootMassProperties<double> unit = mass_properties(profile_of(foot_preset("P2-shoes-left-HMT").spec), 1.0);
  const double rho = 0.96 / unit.area;
  std::printf("P2 shoes left HMT: area %.6f m^2 -> rho = %.3f kg/m^2 (seed: 36.9); CoM (%.4f, %.4f) m, "
              "r_F %.4f m, J_S(rho) %.5f kg m^2, theta_F0 %.4f rad\n",
              unit.area, rho, unit.com_x, unit.com_z, unit.com_distance, rho * unit.inertia_com, unit.theta_F0);
  EXPECT_NEAR(rho, 36.9, 0.05);
}

// The quadrature converges: panels four times narrower change nothing beyond 1e-9 relative.
TEST(MassProperties, ConvergedInTheSampling) {
  const FootProfile<double> p = profile_of(foot_preset("P2-shoes-left-HMT").spec);
  const FootMassProperties<double> a = mass_properties(p, 1.0);
  MassPropertyOptions fine;
  fine.max_panel_width /= 4;
  const FootMassProperties<double> b = mass_properties(p, 1.0, fine);
  EXPECT_NEAR(a.area, b.area, 1e-9 * b.area);
  EXPECT_NEAR(a.com_x, b.com_x, 1e-9);
  EXPECT_NEAR(a.com_z, b.com_z, 1e-9);
  EXPECT_NEAR(a.inertia_ankle, b.inertia_ankle, 1e-9 * b.inertia_ankle);
}

// Exact parameter derivatives: Dual through the whole computation vs central differences.
TEST(MassProperties, ParameterDerivativesMatchCentralDifferences) {
  using D = ad::Dual<1>;
  const FootSpec s = foot_preset("P2-shoes-left-HMT").spec;
  for (int i = 0; i < s.parameters.size(); ++i) {
    FootParameters<D> pd = s.parameters.cast<D>();
    pd[i] = D::variable(s.parameters[i], 0);
    const FootMassProperties<D> mp = mass_properties(make_profile<D>(s.model, pd), D(36.9));
    const double h = 1e-6 * std::max(s.parameters[i], 1e-3);
    auto area_at = [&](double delta) {
      FootParameters<double> q = s.parameters;
      q[i] += delta;
      return mass_properties(make_profile(s.model, q), 36.9);
    };
    const auto plus = area_at(h), minus = area_at(-h);
    EXPECT_NEAR(mp.mass.d[0], (plus.mass - minus.mass) / (2 * h), 1e-4 * (1 + std::abs(mp.mass.d[0]))) << i;
    EXPECT_NEAR(mp.theta_F0.d[0], (plus.theta_F0 - minus.theta_F0) / (2 * h), 1e-4 * (1 + std::abs(mp.theta_F0.d[0])))
        << i;
  }
}

}  // namespace
}  // namespace cyclopt::foot
