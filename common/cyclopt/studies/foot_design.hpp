#pragma once
// The foot-geometry optimisation of seed 001 section 10.2 (issue 15 item 3) as one study. For
// each area density rho of a list (seed: 10:10:70 kg/m^2), with the foot's mass, CoM, inertia and
// theta_F,0 following its geometry (appendix E, walker/foot_density.hpp):
//   1. design multistart: `starts` perturbations of the automatic starting gait of the start foot
//      (seed: P2-shoes-left-HMT, moved into the bounds 10.1), each on a randomly drawn foot around
//      it (the seed adds random numbers to all start values), at the design speed (seed: 2.3 m/s,
//      the highest), foot parameters and gait optimised together under (3.24) and (10.1); every
//      distinct optimum of the runs that passed the KKT test (an "acceptable" run is restarted, and
//      left out if it stays one) is classified (design_class.hpp: under-resolved, stilt, wheel,
//      no rolling, admissible) and the best admissible one is the density's design;
//   2. free-foot continuation: the design continued with QPSQP over the speed grid, downwards from
//      the design speed, the foot free (an optimal foot per speed, Fig. 10.2a orange) but for the
//      sharp corners of the design (k <= 1e-6 stays at its value, as k_H, k_T in Table 10.1); where the
//      QPSQP run stops, warm-started solves from (6.24) at the grid speeds below, down to the first
//      without a KKT point;
//   3. fixed-foot sweeps (speed_sweep.hpp) of the feet optimal at the highest and at the lowest
//      grid speed reached (Fig. 10.2a green and blue), each started from that foot's optimal gait
//      (SpeedSweepOptions::known_gaits) before its seed multistarts. The design's sweep needs only
//      step 1, so it runs on a thread of its own beside step 2 and the low-speed sweep. Where step 2
//      reached no speed below the design speed, the low-speed design is the design: one sweep.
// The references, swept once with the same options: the start foot with its own masses (Table
// 5.1) and point feet (Table D.1). Savings are those of foot_comparison.hpp: 1 - mean f_mech of
// the design / mean f_mech of the reference, over the grid speeds both reach.
// Resume (sweep_journal.hpp): every part of the study has a journal of its own, named
//   "references/start foot", "references/point feet"       the reference sweeps
//   "rho R/design"   the design multistart (batch 0) and the free-foot runs (QPSQP run 0,
//                    warm-started solves run 2; run 1 was a trivial-predictor run of older versions)
//   "rho R/high", "rho R/low"                              the fixed-foot sweeps of step 3
// so a resumed study replays what an earlier attempt finished instead of solving it again.
#include "cyclopt/foot/design_bounds.hpp"
#include "cyclopt/foot/foot_spec.hpp"
#include "cyclopt/studies/design_class.hpp"
#include "cyclopt/studies/foot_comparison.hpp"
#include "cyclopt/studies/foot_design_observer.hpp"
#include "cyclopt/studies/speed_sweep.hpp"

#include <random>
#include <string>
#include <vector>

namespace cyclopt::studies {

// A design found before at `density` (z: the design problem's variables - the gait parameters,
// then the free foot parameters in free_parameters' order): solved as a further start of that
// density's design multistart, after the drawn ones (e.g. to refine a stored design, or a test
// that needs a design whatever path the drawn starts take).
struct KnownDesign {
  double density = 0.0;
  Eigen::VectorXd z;
};

struct FootDesignOptions {
  std::vector<double> densities{10, 20, 30, 40, 50, 60, 70};  // kg/m^2, each > 0
  double design_speed = 2.3;            // m/s, one of sweep.speeds
  int starts = 20;                      // design multistart runs per density (seed: 20)
  std::uint64_t seed = 1;               // base seed of the perturbations
  double scale = 0.05;                  // rad, of the gait perturbations
  // Each design start also draws its foot: every free foot parameter times exp(foot_scale N(0,1)),
  // kept in its range, (10.1) and convexity (3.21/3.24); 0 starts every run from the start foot.
  // rho 10, 8 starts: 0 found 0.02782 at best at 2.3 m/s, 1 the seed's design (Table 10.1, 0.02405).
  double foot_scale = 1.0;
  foot::DesignBounds bounds;            // (10.1)
  // Foot parameters optimised; empty: default_design_parameters (below).
  std::vector<std::string> free_parameters;
  // An optimum whose objective moves by more than this (relative) on a grid kResolutionFactor
  // times finer is under-resolved, no design (design_class.hpp). > 0.
  double resolution_tolerance = kResolutionTolerance;
  double objective_tolerance = 1e-5;    // distinct design optima (multistart.hpp)
  double x_tolerance = 1e-2;
  bool references = true;               // sweep the start foot and point feet (else savings are NaN)
  std::vector<KnownDesign> known_designs;  // each density one of densities, z of the design problem's size
  // Grid (speeds), continuation and corrector of steps 2 and 3 and the references; its starts,
  // seed and scale are those of the fixed-foot sweeps. Its corrector's on_iteration is called one
  // call at a time, though from the study's two threads (step 3), as the observer is.
  SpeedSweepOptions sweep;
  walker::WalkingConstants constants;   // P and M of every model of the study
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
  nlp::SolverSummary summary;        // of the first of them
};

// How one design multistart run ended (its solves with restarts added up), for reports of where
// the multistart's time goes.
struct DesignRun {
  nlp::Termination termination = nlp::Termination::numerical_failure;
  int iterations = 0;
  int evaluations = 0;  // of the problem, with and without derivatives
  double seconds = 0.0;
  double objective = 0.0;
};

// Which of a density's two fixed-foot designs answers "which foot walks best over the grid",
// the seed's "best of the optimised models" (section 10.2); better_design decides.
enum class DesignAnswer { design, low_speed_design };
const char* to_string(DesignAnswer a);  // "design", "low-speed design"

struct DensityDesign {
  double density = 0.0;
  // The design problem: the start foot with the density, moved into (10.1), and the problem with
  // the foot free under (10.1) at the design speed (the multistart's and step 2's, over the speed).
  walker::WalkerModel<double> model;
  walker::GaitProblemOptions problem;
  int kkt_starts = 0;                     // design multistart runs that reached a KKT point
  std::vector<DesignRun> runs;            // every design multistart run, in start order
  std::vector<DesignOptimum> optima;      // best first
  int best = -1;                          // index of the best admissible optimum, -1 if none
  int class_counts[5] = {0, 0, 0, 0, 0};  // optima per DesignClass
  ContinuationResult free_foot;           // step 2 (empty without a design)
  // Step 2's problem: the design's foot (free_foot's x holds its free parameters; those with a
  // sharp corner, k <= 1e-6, stay fixed at the design's values) over the speed.
  walker::WalkerModel<double> free_foot_model;
  walker::GaitProblemOptions free_foot_problem;
  std::vector<double> free_foot_f_mech;   // per grid speed, NaN where step 2 has no converged point
  foot::FootSpec low_speed_foot;          // optimal at the lowest grid speed step 2 reached
  double low_speed = 0.0;
  FootSweepSummary high, low;             // step 3 for the design and for low_speed_foot
  double saving_vs_start = 0.0, saving_vs_point = 0.0;  // of `high`; NaN without references
  double low_saving_vs_start = 0.0, low_saving_vs_point = 0.0;
  DesignAnswer answer = DesignAnswer::design;           // better_design(high, low), set by add_savings
  const FootSweepSummary& answer_sweep() const { return answer == DesignAnswer::design ? high : low; }
  double answer_saving_vs_start() const { return answer == DesignAnswer::design ? saving_vs_start : low_saving_vs_start; }
  double answer_saving_vs_point() const { return answer == DesignAnswer::design ? saving_vs_point : low_saving_vs_point; }
  // Wall time of step 1, of step 2, and from the end of step 2 until both sweeps of step 3 ended
  // (the design's began with step 2: high.seconds, low.seconds are each sweep's own); they add up
  // to `seconds`.
  double multistart_seconds = 0.0, continuation_seconds = 0.0, sweep_seconds = 0.0, seconds = 0.0;
  bool stopped = false;
};

struct FootDesignResult {
  std::vector<double> speeds;
  FootSweepSummary start_foot, point_feet;  // the references (when options.references)
  double reference_seconds = 0.0;
  std::vector<DensityDesign> designs;       // in the order of options.densities
  int best_design = -1;                     // the density whose answer saves most against the start foot
  double seconds = 0.0;
};

// start: the start foot (HM or HMT, without density; its masses are the start-foot reference's).
// Throws std::invalid_argument naming the option for invalid options (a density <= 0, a design
// speed not on the grid, a free parameter the model does not have, bounds that exclude the start
// foot in a parameter that is not free).
// The observer (foot_design_observer.hpp) sees the steps, the results as they are found and the
// progress, gives the journals of an earlier attempt, and may stop the study.
FootDesignResult design_feet(const foot::FootSpec& start, const walker::GaitProblemOptions& problem,
                             const FootDesignOptions& options, FootDesignObserver& observer);

// design_feet's independent pieces, for a caller that runs them apart (foot_design_kind.hpp: one
// work unit each). They throw as design_feet does.
enum class DesignReference { start_foot, point_feet };
const char* reference_part(DesignReference which);  // its journal's name (above)
// The reference's walker: the start foot with its own masses, or point feet.
walker::WalkerModel<double> reference_model(DesignReference which, const foot::FootSpec& start,
                                            const walker::WalkingConstants& constants);
FootSweepSummary sweep_reference(DesignReference which, const foot::FootSpec& start, const walker::GaitProblemOptions& problem,
                                 const FootDesignOptions& options, FootDesignObserver& observer);
// Steps 1-3 for one density (of options.densities or not); the savings are left NaN.
DensityDesign design_density(double rho, const foot::FootSpec& start, const walker::GaitProblemOptions& problem,
                             const FootDesignOptions& options, FootDesignObserver& observer);
// The foot parameters a design frees by default: all of the model's but the corner curvatures
// (HM: k_H, k_M; HMT: k_H, k_T), which stay at the start foot's values, as the seed holds them at
// 1e-8 in its fits (4.13, 4.18) and in all its designs (Tables 10.1, 10.2). Freed, f depends on
// such a k about like log k (free_foot_parameters in foot_design.cpp), so KKT tests rarely settle.
std::vector<std::string> default_design_parameters(foot::FootModel model);
// The foot of one design start (FootDesignOptions::foot_scale): every free parameter of `start`
// times exp(scale N(0,1)), kept in its range (parameter_layout) and moved into (10.1); redrawn
// until it satisfies (3.21/3.24) and the HMT toe margin; `start`'s parameters after 100 draws.
foot::FootParameters<double> draw_design_foot(const foot::FootSpec& start, const std::vector<std::string>& free,
                                              const foot::DesignBounds& bounds, double scale, std::mt19937_64& rng);
// The better of a density's fixed-foot sweeps: the one that reached more grid speeds; of equal
// reach, the one with the lower mean f_mech over the grid speeds both reached (the design on a
// tie). The seed names the design optimal at the design speed; the foot optimal at a lower speed
// can walk the whole range more cheaply (rho 10: its sweep 0.01047 against 0.01140, run D of
// bench/results/foot_design_bench.txt), and a user asking for the best foot over the range gets it.
DesignAnswer better_design(const FootSweepSummary& high, const FootSweepSummary& low);
// The savings of the density's fixed-foot sweeps against the two references (NaN where a
// reference was not swept), and its answer (better_design).
void add_savings(DensityDesign& design, const std::vector<double>& speeds, const FootSweepSummary& start_foot,
                 const FootSweepSummary& point_feet);

}  // namespace cyclopt::studies
