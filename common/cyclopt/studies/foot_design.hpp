#pragma once
// The foot-geometry optimisation of seed 001 section 10.2 (issue 15 item 3) as one study. For
// each area density rho of a list (seed: 10:10:70 kg/m^2), with the foot's mass, CoM, inertia and
// theta_F,0 following its geometry (appendix E, walker/foot_density.hpp):
//   1. design multistart: `starts` perturbations of the automatic starting gait of the start foot
//      (seed: P2-shoes-left-HMT, moved into the bounds 10.1) at the design speed (seed: 2.3 m/s, the
//      highest), foot parameters and gait optimised together under (3.24) and (10.1); every
//      distinct optimum is classified (design_class.hpp: stilt, wheel, no rolling, admissible) and
//      the best admissible one is the density's design;
//   2. free-foot continuation: the design continued with QPSQP over the speed grid, downwards from
//      the design speed, the foot free (an optimal foot per speed, Fig. 10.2a orange); where the
//      QPSQP run stops, the rest of the grid with the trivial predictor (warm starts);
//   3. fixed-foot sweeps (speed_sweep.hpp) of the feet optimal at the highest and at the lowest
//      grid speed reached (Fig. 10.2a green and blue), each started from that foot's optimal gait
//      (SpeedSweepOptions::known_gaits) before its seed multistarts.
// The references, swept once with the same options: the start foot with its own masses (Table
// 5.1) and point feet (Table D.1). Savings are those of foot_comparison.hpp: 1 - mean f_mech of
// the design / mean f_mech of the reference, over the grid speeds both reach.
#include "cyclopt/foot/design_bounds.hpp"
#include "cyclopt/foot/foot_spec.hpp"
#include "cyclopt/studies/design_class.hpp"
#include "cyclopt/studies/foot_comparison.hpp"
#include "cyclopt/studies/speed_sweep.hpp"

#include <functional>
#include <string>
#include <vector>

namespace cyclopt::studies {

struct FootDesignOptions {
  std::vector<double> densities{10, 20, 30, 40, 50, 60, 70};  // kg/m^2, each > 0
  double design_speed = 2.3;            // m/s, one of sweep.speeds
  int starts = 20;                      // design multistart runs per density (seed: 20)
  std::uint64_t seed = 1;               // base seed of the perturbations
  double scale = 0.05;                  // rad, of the perturbations
  foot::DesignBounds bounds;            // (10.1)
  std::vector<std::string> free_parameters;  // foot parameters optimised; empty: all of the model's
  double objective_tolerance = 1e-5;    // distinct design optima (multistart.hpp)
  double x_tolerance = 1e-2;
  bool references = true;               // sweep the start foot and point feet (else savings are NaN)
  // Grid (speeds), continuation and corrector of steps 2 and 3 and the references; its starts,
  // seed and scale are those of the fixed-foot sweeps. Its on_progress reports each sweep.
  SpeedSweepOptions sweep;
  // Called when a step begins: "references", "rho 10: design multistart", ... Returning false
  // stops the study (the result holds what was done).
  std::function<bool(const std::string& step)> on_step;
};

// One distinct optimum of a design multistart.
struct DesignOptimum {
  double objective = 0.0;            // at the design speed
  Eigen::VectorXd z;                 // gait and free parameters (GaitProblem layout)
  foot::FootSpec foot;               // the designed foot, with the density
  double mass = 0.0, com_distance = 0.0, inertia = 0.0, zero_angle = 0.0;  // m_F, r_F, J_F, theta_F,0
  std::vector<std::string> active_bounds;  // rows of (10.1) within 1e-6 of their bound
  DesignClassification classification;
  std::vector<int> starts;           // multistart runs that reached it
};

struct DensityDesign {
  double density = 0.0;
  int kkt_starts = 0;                     // design multistart runs that reached a KKT point
  std::vector<DesignOptimum> optima;      // best first
  int best = -1;                          // index of the best admissible optimum, -1 if none
  int class_counts[4] = {0, 0, 0, 0};     // optima per DesignClass
  ContinuationResult free_foot;           // step 2 (empty without a design)
  std::vector<double> free_foot_f_mech;   // per grid speed, NaN where step 2 has no converged point
  foot::FootSpec low_speed_foot;          // optimal at the lowest grid speed step 2 reached
  double low_speed = 0.0;
  FootSweepSummary high, low;             // step 3 for the design and for low_speed_foot
  double saving_vs_start = 0.0, saving_vs_point = 0.0;  // of `high`; NaN without references
  double low_saving_vs_start = 0.0, low_saving_vs_point = 0.0;
  double multistart_seconds = 0.0, continuation_seconds = 0.0, sweep_seconds = 0.0, seconds = 0.0;
  bool stopped = false;
};

struct FootDesignResult {
  std::vector<double> speeds;
  FootSweepSummary start_foot, point_feet;  // the references (when options.references)
  double reference_seconds = 0.0;
  std::vector<DensityDesign> designs;       // in the order of options.densities
  int best_design = -1;                     // the density whose design saves most against the start foot
  double seconds = 0.0;
};

// start: the start foot (HM or HMT, without density; its masses are the start-foot reference's).
// Throws std::invalid_argument naming the option for invalid options (a density <= 0, a design
// speed not on the grid, a free parameter the model does not have, bounds that exclude the start
// foot in a parameter that is not free).
FootDesignResult design_feet(const foot::FootSpec& start, const walker::GaitProblemOptions& problem,
                             const FootDesignOptions& options);

}  // namespace cyclopt::studies
