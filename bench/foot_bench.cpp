// Speed against error of the foot library (seed 001, ch. 3, appendix E):
//  1. time per evaluation of F..F''' (double, Dual<1>, Dual<9>) and of the curvature radius;
//  2. appendix-E mass properties: time and error against a converged reference as the panel
//     width varies, next to the seed's 1000-point trapezoid rule on the same integrals.
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/foot/mass_properties.hpp"
#include "machine_info.hpp"

#include <chrono>
#include <cstdio>
#include <numbers>

using namespace cyclopt::foot;
using Clock = std::chrono::steady_clock;

template <class F>
double seconds_per_call(F&& f, int calls) {
  const auto t0 = Clock::now();
  for (int i = 0; i < calls; ++i) f(i);
  return std::chrono::duration<double>(Clock::now() - t0).count() / calls;
}

// The seed's rule for E.2: composite trapezoid with 1000 equidistant points on [-pi, pi].
double seed_trapezoid_area(const FootProfile<double>& p) {
  const int n = 1000;
  const double h = 2 * std::numbers::pi / (n - 1);
  double s = 0;
  for (int i = 0; i < n; ++i) {
    const double a = -std::numbers::pi + i * h;
    const double w = (i == 0 || i == n - 1) ? 0.5 : 1.0;
    s += w * rolling_contact(p, a).dF * curvature_radius(p, a);
  }
  return 0.5 * s * h;
}

int main() {
  std::printf("foot_bench on %s\n\n", cyclopt::bench::machine_line().c_str());
  volatile double sink = 0;
  std::printf("1. evaluation cost (ns per call, 1e6 angles over the admissible range)\n");
  std::printf("%-22s %10s %10s %10s %10s\n", "foot", "F..F'''", "R(3.14)", "Dual<1>", "Dual<9>");
  for (const char* name : {"P1-barefoot-left-HM", "P2-shoes-left-HMT"}) {
    const FootSpec s = foot_preset(name).spec;
    const FootProfile<double> p = make_profile(s.model, s.parameters);
    const int n = 1000000;
    auto theta = [&](int i) { return p.theta_min + (p.theta_max - p.theta_min) * (i + 0.5) / n; };
    const double t_f = seconds_per_call([&](int i) { sink = sink + rolling_contact(p, theta(i)).dddF; }, n);
    const double t_r = seconds_per_call([&](int i) { sink = sink + curvature_radius(p, theta(i)); }, n);
    using D1 = cyclopt::ad::Dual<1>;
    using D9 = cyclopt::ad::Dual<9>;
    const double t_d1 =
        seconds_per_call([&](int i) { sink = sink + rolling_contact(p, D1::variable(theta(i), 0)).dddF.d[0]; }, n / 4);
    FootParameters<D9> pd = s.parameters.cast<D9>();
    for (int j = 0; j < pd.size(); ++j) pd[j] = D9::variable(s.parameters[j], j);
    const FootProfile<D9> prof9 = make_profile<D9>(s.model, pd);
    const double t_d9 = seconds_per_call([&](int i) { sink = sink + rolling_contact(prof9, D9(theta(i))).dddF.d[0]; }, n / 10);
    std::printf("%-22s %10.1f %10.1f %10.1f %10.1f\n", name, t_f * 1e9, t_r * 1e9, t_d1 * 1e9, t_d9 * 1e9);
  }

  std::printf("\n2. appendix-E mass properties, P2 shoes left HMT (k_H = k_T = 1e-8), rho = 36.9 kg/m^2\n");
  const FootSpec s = foot_preset("P2-shoes-left-HMT").spec;
  const FootProfile<double> p = make_profile(s.model, s.parameters);
  MassPropertyOptions ref_opt;
  ref_opt.max_panel_width = 0.002;
  const FootMassProperties<double> ref = mass_properties(p, 36.9, ref_opt);
  std::printf("reference (panel width 0.002 rad): mass %.9f kg, CoM (%.9f, %.9f) m, J_S %.9f kg m^2\n", ref.mass,
              ref.com_x, ref.com_z, ref.inertia_com);
  std::printf("%-28s %12s %12s %12s %12s\n", "method", "time/ms", "rel.err m", "err CoM/m", "rel.err J_S");
  for (double w : {0.4, 0.2, 0.1, 0.05, 0.025}) {
    MassPropertyOptions o;
    o.max_panel_width = w;
    FootMassProperties<double> mp{};
    const double t = seconds_per_call([&](int) { mp = mass_properties(p, 36.9, o); }, 50);
    std::printf("GL10 panels, width %-8.3f %12.4f %12.2e %12.2e %12.2e\n", w, t * 1e3, std::abs(mp.mass / ref.mass - 1),
                std::hypot(mp.com_x - ref.com_x, mp.com_z - ref.com_z), std::abs(mp.inertia_com / ref.inertia_com - 1));
  }
  double area = 0;
  const double t = seconds_per_call([&](int) { area = seed_trapezoid_area(p); }, 50);
  std::printf("%-28s %12.4f %12.2e %12s %12s\n", "seed: trapezoid, 1000 pts", t * 1e3, std::abs(36.9 * area / ref.mass - 1),
              "-", "-");
  FootSpec sharp = s;
  for (int i = hmt::k_H; i < sharp.parameters.size(); ++i) sharp.parameters[i] = 1e-8;
  const FootProfile<double> ps = make_profile(sharp.model, sharp.parameters);
  const double sharp_ref = mass_properties(ps, 1.0, ref_opt).area;
  std::printf("same foot with every k = 1e-8 (near polygon): GL10 width 0.2 area error %.2e, seed trapezoid %.2e\n",
              std::abs(mass_properties(ps, 1.0).area / sharp_ref - 1), std::abs(seed_trapezoid_area(ps) / sharp_ref - 1));
  std::printf("\nseed section 10.2: rho = 36.9 kg/m^2 gives m_F = 0.96 kg; here rho = 0.96 / A = %.3f kg/m^2\n",
              0.96 / (ref.mass / 36.9));
  return sink == 12345.0;
}
