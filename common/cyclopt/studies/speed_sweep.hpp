#pragma once
// The automatic study workflow of seed 001 chapter 9 (Fig. 9.7) over the mean speed:
//   1. multistart at a few seed speeds (0.3, 1.3, 2.3 m/s) from the automatic starting gait;
//   2. the best optimum of each (unless it lies on a curve already found) is continued with the
//      QPSQP method in both directions over the whole speed grid;
//   2b. (optional, not in the seed) up to runner_ups further optima of each, within
//      runner_up_margin of its best, are continued both ways while they are the best known;
//   3. every curve jumped to is continued back, against the direction it was found in, so its
//      extent is known (the seed chose the existence ranges by hand);
//   4. per grid speed, the best converged point of all curves is selected (by hand in the seed).
// A run stops where it joins a curve an earlier run followed (a converged point at a grid speed
// with the same f and x, same_objective / same_x): from there on that run's result is known. A curve
// jumped to next to a converged point of a known curve (continuation::same_optimum_nearby) is not
// continued back: that would retrace the known curve.
// Beyond the seed (issue 16), the sweep then recovers every grid speed that no curve reached with a
// KKT point (a continuation stopped at the minimal step before it, or ended at a fold), and every
// point that may be dominated (a neighbouring speed's best curve did not reach this speed, so the
// selected point may be a worse local optimum than that curve would give). Per target speed, in
// this order until one gives a KKT point:
//   R1 neighbour start: a solve at the speed from the converged point nearest in speed of each
//      curve (the dominated test: only from the neighbour's point), jumping over the place where
//      continuation failed;
//   R2 neighbour multistart (unreached speeds, and dominated tests where R1 found no KKT point at
//      all): `starts` (dominance tests: `dominance_starts`) perturbations of those points;
//   R3 gait multistart (unreached speeds that were no seed speed): `starts` perturbations of the
//      automatic starting gait at that speed, as at the seed speeds.
// A recovered point better than what the speed had opens a new curve, continued with QPSQP in
// both directions while it is the best known (a run stops at the first grid speed where another
// curve is at least as good), so it fills the neighbouring gaps too. Targets nearest to a reached
// speed go first; an unreached speed is tried again whenever curves were opened since its last try
// (R1 and R2 from those curves only: a later recovery's curve may pass nearer to it), each (speed,
// neighbour curve) pair of a dominance test once, so the recovery ends (max_curves). A speed still
// without a point gets a reason naming what was tried and which options to change.
// Closure (issue 21 item 3, not in the seed): the envelope is then closed. In a pass, every grid
// speed is solved from the best points of its neighbouring speeds and from the converged point
// nearest to it of every curve that has none at it, within one grid step (each such start once per
// speed); a point better than the speed's best by more than closure.min_improvement (relative)
// opens a curve, continued both ways while it is the best known. Passes repeat until one improves
// no best point (the envelope is "closed") or closure.max_passes / closure.max_seconds end them.
// Several seeds (SpeedSweepOptions::seeds): the whole search above runs once per seed, each on its
// own (a search sees only its own curves); the envelope is the best point per speed over all
// seeds' searches, and seed_spread says how far the seeds' own envelopes differ per speed - how
// sure the answer is. Curve ids run on from one search to the next.
// BestPoint::step tells which step found the curve through the selected point.
// The two runs from a new point (upwards and downwards) are computed at once when a core is spare
// (nlp/spare_core.hpp): below the start speed the upward run has no point, so the downward run is
// the same whichever ran first, and on_point sees the points in the order of one thread (the
// downward run's once the upward run has ended). The corrector's callbacks (on_iteration,
// should_stop) are called from several threads, as they are by multistart workers.
// Before step 1, known gaits (options.known_gaits: a gait the caller solved at a grid speed, such as
// a foot design's optimum, section 10.2) are solved from and continued in both directions like a
// seed optimum; the seed multistarts follow and add what they find off those curves.
#include "cyclopt/continuation/continuation_solver.hpp"
#include "cyclopt/studies/speed_sweep_observer.hpp"
#include "cyclopt/walker/gait_problem.hpp"
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace cyclopt::studies {

using continuation::ContinuationOptions;
using continuation::ContinuationResult;
using continuation::CurvePoint;
using continuation::PointCallback;

// A gait known at a grid speed: x in the layout of GaitProblem::gait_parameters.
struct KnownGait {
  double speed = 0.0;
  Eigen::VectorXd x;
};

// The closure of the envelope (above).
struct EnvelopeClosureOptions {
  bool enabled = true;
  double min_improvement = 1e-4;  // relative: a point must beat the speed's best by more to count
  int max_passes = 8;             // >= 1
  double max_seconds = 0.0;       // wall budget of the closure; 0: none. A pass begun is finished.
};

struct SpeedSweepOptions {
  std::vector<double> speeds;                       // the grid, strictly ascending, >= 2 values
  std::vector<double> seed_speeds{0.3, 1.3, 2.3};   // multistart at the nearest grid values
  int starts = 20;                                  // multistart runs per seed speed (seed: 20)
  // Base seeds of the random perturbations: one search per seed (above), >= 1 distinct values.
  std::vector<std::uint64_t> seeds{1};
  double scale = 0.05;                              // rad, of the perturbations
  // R2 perturbations in a dominance test (below; an unreached speed gets `starts`); 0: `starts`.
  // Fewer are faster and find fewer better optima - measured with 20 starts and 5 here
  // (bench/results/speed_sweep_bench.txt, foot_design_bench.txt): P2-shoes HMT the same 21 optima in
  // 129 s instead of 191 s, but the foot design's low-speed sweeps kept worse optima at 0.4-0.7 m/s
  // (rho 40 saving 17.6 % instead of 19.6 %, rho 60 6.7 % instead of 7.8 %), hence the default.
  int dominance_starts = 0;
  // Curves continued at most (each jump or recovery opens one), per search: each of `seeds` has its own.
  int max_curves = 24;
  // Step 2b (not in the seed): up to runner_ups further distinct optima of each seed-speed
  // multistart, within runner_up_margin (relative) of its best, are continued both ways while they
  // are the best known (a run stops at the first grid speed where another curve is at least as
  // good). An optimum slightly worse at the seed speed may lie on the curve that is best elsewhere.
  // Measured on P2-shoes HMT, 20 starts (bench/results/speed_sweep_bench.txt): with starts 2-21
  // instead of 1-20 the 2.3 m/s multistart finds a 1.9 % better optimum there, continues only it and
  // misses the curve that is best from 2.2 m/s down (mean f_mech 0.02476 instead of 0.02196); with
  // runner_ups 2 both start sets give the same curves over 0.7-2.3 m/s (means 0.02245 and 0.02259),
  // but the extra curves change the low-speed recovery's path (0.3 m/s 0.0088 instead of 0.0019
  // with starts 1-20) and cost 5-40 s, so the default is the seed's 0.
  int runner_ups = 0;
  double runner_up_margin = 0.05;
  bool recover = true;                              // R1-R3 above; false: the seed's workflow only
  EnvelopeClosureOptions closure;
  // A seed optimum lies on a known curve if a converged point there has |f - f_c| <=
  // same_objective * max(1, |f|) and |x - x_c|_inf <= same_x.
  double same_objective = 1e-6;
  double same_x = 1e-3;
  ContinuationOptions continuation;                 // for the multistart solves too (corrector)
  // MaxIter of the corrector at each continuation point (the multistart solves keep
  // continuation.corrector.max_iterations): a corrector that has not converged by then counts as
  // failed and the trust region shrinks, instead of spending MaxIter = 2000 iterations per failing
  // try (HMT P2 downwards near 0.46 m/s: ~16000 corrector iterations per run). >= 1.
  int corrector_max_iterations = 300;
  // Coarse-to-fine multistart (issue 16 item 3): a batch of perturbed starts (step 1, R2, R3) is
  // solved with P = coarse_points grid points of (5.93) first - the gait parameters (5.92) do not
  // depend on P, and a Jacobian costs ~P - and every distinct coarse optimum is then polished at
  // the model's P. Every reported optimum is a KKT point at the model's P. If no coarse solve
  // converged, the starts are solved at P only when no coarse solve ended feasible either (the
  // coarse grid may lack the gait); where coarse solves reached feasible gaits but no KKT point,
  // solving the starts again at P found none either (P2-shoes HMT at 0.3 m/s: 0/20 in 14 s; the
  // rho 10 low-speed design of the foot design study: 0/20 in 59 s CPU). 0, or >= the model's P:
  // every start at the model's P. Measured on this 2-core machine
  // (bench/results/speed_sweep_bench.txt): point feet the same optima at all 21 speeds in 29.6
  // instead of 41.7 s; P2-shoes HMT (with R2 after a failed dominance R1) every speed as good or
  // better (2.3 m/s f_mech 0.0427 instead of 0.0497) in the same time.
  int coarse_points = 100;
  // What texts (progress, recovery triggers and reasons) add to a curve id when they name a
  // curve: the caller's number of the curve (a sweep job stores curve c as curve_index c + 1), so
  // progress, query and plots use one numbering.
  int curve_label_offset = 0;
  std::vector<KnownGait> known_gaits;              // solved from and continued first (each speed on the grid)
};

// The step of the sweep that found a curve (the first point of it).
enum class SweepStep {
  seed_multistart,       // step 1: multistart from the automatic starting gait at a seed speed
  known_gait,            // a solve from options.known_gaits
  jump,                  // a continuation run converged onto another curve (curve_jump.hpp)
  neighbour_start,       // R1
  neighbour_multistart,  // R2
  gait_multistart,       // R3
  closure,               // a start of the envelope's closure
};
const char* to_string(SweepStep step);

struct CurveOrigin {
  SweepStep step = SweepStep::seed_multistart;
  double speed = 0.0;  // where the step found the curve's first point
};

struct BestPoint {
  double speed = 0.0;
  bool found = false;
  CurvePoint point;    // when found
  CurveOrigin origin;  // of point.curve_id, when found
  std::string reason;  // when not
  int closure_passes = 0;  // closure passes that solved at this speed (0: none had a new start here)
  int closure_pass = 0;    // the pass that found the point's curve (0: not the closure)
  std::uint64_t seed = 0;  // of the search that found the point
};
// "R1 neighbour start at 0.40 m/s, continued" (how the point was found) or the reason.
std::string describe(const BestPoint& best);

// One recovery target and what was tried there.
struct RecoveryAttempt {
  double speed = 0.0;
  std::string trigger;  // "unreached" (", again from curves opened since") or "dominated? curve c is best at v m/s"
  int solves = 0;       // R1-R3 local solves spent
  bool found = false;   // a better KKT point than the speed had
  SweepStep step = SweepStep::neighbour_start;  // that found it (when found)
  double objective = 0.0;                       // when found
  double seconds = 0.0;
};

// How the closure of one search ended.
struct EnvelopeClosure {
  bool closed = false;  // the last pass improved no best point
  int passes = 0;
  int solves = 0;       // local solves of its starts
  double seconds = 0.0;
  std::string reason;   // why not closed: "closure off", "max_passes (8) reached", "time budget ..."
};
std::string describe(const EnvelopeClosure& closure);  // "closed after 2 passes" or the reason

// One seed's search and its own envelope.
struct SeedSearch {
  std::uint64_t seed = 1;
  std::vector<BestPoint> best;  // one per grid speed
  EnvelopeClosure closure;
  int first_curve = 0, curves = 0;  // its curve ids: first_curve .. first_curve + curves - 1
  double seconds = 0.0;
};

struct SpeedSweepResult {
  std::vector<ContinuationResult> runs;  // in the order run
  std::vector<BestPoint> best;           // one per grid speed: the best over every seed's search
  std::vector<SeedSearch> searches;      // one per seed, in the order of options.seeds
  // Per grid speed: (max - min) / min of the objective over the seeds' own envelopes, where every
  // search has a point; NaN with one seed or where a search has none.
  std::vector<double> seed_spread;
  std::vector<RecoveryAttempt> recoveries;  // in the order tried
  std::vector<CurveOrigin> origins;      // of curve id 0 .. curves - 1
  int curves = 0;                        // curve ids used: 0 .. curves - 1
  bool stopped = false;                  // the observer's on_point asked to stop: the result holds what was done
  // The closure: of the one search, or of all (passes, solves, seconds summed; closed if every
  // search's envelope is, else the first reason).
  EnvelopeClosure closure;
  int multistart_solves = 0;             // step 1 and R1-R3, solved in this attempt
  int resumed_solves = 0;                // ... taken from the journal instead
  int computed_runs = 0;                 // continuation runs computed in this attempt
  int resumed_runs = 0;                  // ... taken from the journal instead
  double multistart_seconds = 0.0;
  double multistart_cpu_seconds = 0.0;   // process CPU time during them (all threads)
  double recovery_seconds = 0.0;         // R1-R3 with their continuation runs
  double seconds = 0.0;
};

// The observer (speed_sweep_observer.hpp) sees every new point, the progress, and gives the
// journal of an earlier attempt; it may stop the sweep (the result then holds what was done).
SpeedSweepResult speed_sweep(const walker::WalkerModel<double>& model, const walker::GaitProblemOptions& problem,
                             const SpeedSweepOptions& options, SpeedSweepObserver& observer);
// The same with a PointObserver of on_point.
SpeedSweepResult speed_sweep(const walker::WalkerModel<double>& model, const walker::GaitProblemOptions& problem,
                             const SpeedSweepOptions& options, const PointCallback& on_point = {});

}  // namespace cyclopt::studies
