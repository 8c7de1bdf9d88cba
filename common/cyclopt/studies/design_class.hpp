#pragma once
// Degenerate optima of the foot-geometry optimisation (seed 001 section 10.2, issue 15 item 4),
// recognised by documented rules instead of by eye. First a kind the seed does not name, because
// its optima are checked by eye and in simulation:
//   under-resolved: the optimum exists only on the P grid (5.93): its objective on a grid
//              kResolutionFactor times finer differs by more than kResolutionTolerance (relative),
//              or no gait exists there. The optimiser found a gait whose fast dynamics fall
//              between grid points, so the quadrature of the positive power (5.100) misses most
//              of the work: rho 10, 2026-12-05, f_mech 0.0044 at 2.3 m/s on P = 200, 0.18 on 4P
//              and 0.12 on 64P; its positive work (1.1 J) was below the impact loss it must make
//              up (6.5 J), and the forward simulation did not take the step.
// Then the three kinds of optimum the seed discards:
//   stilt      (Fig. 10.3a): the foot degenerates to a thin rod without area or mass, so the swing
//              foot moves for free, and the walker takes very short, fast steps (60 mm at 38 Hz at
//              2.3 m/s). Rule: foot area A (E.2) < kStiltArea, or step frequency > kStiltFrequency.
//   wheel      (Fig. 10.3b): a near-circular sole centred at the ankle; the legs stay almost still
//              and the walker rolls on the sole like a wheel. Rule: over the step the stance ankle
//              travels more than kWheelRolling step lengths while the hip's horizontal offset from
//              the stance ankle varies by less than kWheelLegSwing step lengths (in walking the
//              leg sweeps about one step length under the hip).
//   no rolling (Fig. 9.10a, 9.15): heel or toe walking - the contact point stays at one end of
//              the sole. Rule: the contact point x_C = x_0 + F + F'' (2.21) travels less than
//              kRollingFraction of the sole length (l_HM, + l_MT for HMT) during the stance.
// The rules are checked in this order; the first that holds names the class. Point feet are
// never stilt, wheel or no rolling (they have no sole).

#include "cyclopt/walker/periodic_gait.hpp"
#include "cyclopt/walker/walker_model.hpp"

#include <string>

namespace cyclopt::studies {

enum class DesignClass { admissible, stilt, wheel, no_rolling, under_resolved };
const char* to_string(DesignClass c);

// A resolved optimum moves by ~1e-3 from P = 200 to the limit (bench/results/walker_bench.txt);
// the artefact above by a factor 40.
inline constexpr int kResolutionFactor = 4;
inline constexpr double kResolutionTolerance = 0.1;
inline constexpr double kStiltArea = 1e-4;        // m^2 (1 cm^2; the seed's flat feet have tens of cm^2)
// Hz: between the seed's admissible rho = 10 design (Table 10.1), whose optimal gait at 2.3 m/s
// steps at 5.46 Hz (0.42 m steps; measured here, the design problem's KKT point from that foot),
// and its stilt's 38 Hz (Fig. 10.3a). A rule at 5 Hz discarded the seed's best design.
inline constexpr double kStiltFrequency = 15.0;
inline constexpr double kWheelRolling = 0.5;      // step lengths of ankle travel
inline constexpr double kWheelLegSwing = 0.25;    // step lengths of hip-over-ankle excursion
inline constexpr double kRollingFraction = 0.2;   // of the sole length

struct DesignClassification {
  DesignClass design_class = DesignClass::admissible;
  std::string reason;        // the rule and the measured values
  // The measured quantities the rules use.
  double objective = 0.0;            // of the gait, on its grid
  double refined_objective = 0.0;    // on the grid kResolutionFactor times finer (NaN: no gait there)
  double foot_area = 0.0;            // m^2
  double step_frequency = 0.0;       // Hz
  double ankle_travel = 0.0;         // m, max - min of the stance ankle's x over the step
  double leg_swing = 0.0;            // m, max - min of x_H - x_A over the step
  double contact_travel = 0.0;       // m, max - min of x_C over the step
  double sole_length = 0.0;          // m
};

// The resolution rule alone: the objective on the finer grid lies within `tolerance` (relative)
// of the objective on the grid (false where the finer grid has no gait: refined_objective NaN).
bool resolved(double objective, double refined_objective, double tolerance = kResolutionTolerance);

// `gait` must carry its trajectory (GaitOptions::trajectories); `model` is the model the gait was
// computed for (the designed foot); refined_objective: the gait's objective on the finer grid
// (walker::GaitProblem::refined_objective with kResolutionFactor), compared within
// resolution_tolerance.
DesignClassification classify_design(const walker::WalkerModel<double>& model, const walker::PeriodicGait<double>& gait,
                                     double refined_objective, double resolution_tolerance = kResolutionTolerance);

}  // namespace cyclopt::studies
