#pragma once
// The foot comparison of seed 001 section 9.2 (Fig. 9.9, 9.12, 9.14, 9.17, 9.19a): one chapter-9
// speed sweep (speed_sweep.hpp) per foot over the same grid (sweep_foot; independent, so a job
// may run them anywhere: foot_comparison_kind.hpp), then per grid speed the best foot
// (lowest f_mech, eq. 5.102, of the feet being compared, the reference excluded) and per foot its
// mean f_mech and the saving against the reference feet (the seed: point feet, Table D.1):
//   saving = 1 - mean(f_mech of the foot) / mean(f_mech of the reference),
// both means over the grid speeds where both have a point (the seed: "Der Mittelwert ueber den
// gesamten Geschwindigkeitsbereich ist um 64 % geringer", section 9.2.3). The envelope (best foot
// per speed) gets the same saving. Unlike the seed, no solution is excluded by hand (the seed
// drops toe- and heel-walking optima below 0.8 m/s, Fig. 9.10a and 9.15).
// With several seeds (SpeedSweepOptions::seeds) every foot's sweep searches once per seed; its f_mech
// is the best over the seeds, and each seed's own search gives a saving of its own (that seed's
// search of the foot against that seed's search of the reference). The feet are ranked by saving;
// for each foot, order_held says whether it beat the next foot in the ranking with every seed - a
// ranking that the seeds do not all agree on lies within the noise of the search.
#include "cyclopt/studies/speed_sweep.hpp"
#include "cyclopt/walker/gait_problem.hpp"

#include <functional>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace cyclopt::studies {

// One foot's sweep, reduced to its best point per speed.
struct FootSweepSummary {
  std::string name;
  std::vector<BestPoint> best;         // one per grid speed (speed_sweep's best)
  std::vector<double> f_mech;          // per grid speed; NaN where no point was found
  int speeds_found = 0;
  double mean_f_mech = 0.0;            // over the speeds shared with the reference (NaN if none)
  int common_speeds = 0;               // that mean's speed count
  double saving = 0.0;                 // against the reference, over the same speeds (0 for the reference)
  double seconds = 0.0;                // wall time of its sweep
  int curves = 0;
  std::vector<RecoveryAttempt> recoveries;  // the sweep's, in the order tried
  bool stopped = false;                // sweep_foot's on_point asked to stop during its sweep
  std::vector<std::uint64_t> seeds;    // of the sweep's searches, in order
  std::vector<std::vector<double>> seed_f_mech;  // per seed: f_mech per grid speed of its own search (NaN: none)
  // Set by summarise_feet: per seed, the saving of this foot's search against the reference's
  // search with the same seed (over the speeds both reach); the rank by saving (0: best, the
  // reference -1); whether this foot's saving beat the next-ranked foot's with every seed (unset
  // for the last, the reference, a single seed).
  std::vector<double> seed_savings;
  int rank = -1;
  std::optional<bool> order_held;
};

struct FootComparisonResult {
  std::vector<double> speeds;
  std::vector<FootSweepSummary> feet;  // in the order given
  std::size_t reference = 0;
  std::vector<int> best_foot;          // per speed: index of the best compared foot, -1 if none has a point
  std::vector<double> envelope_f_mech; // per speed: its f_mech (NaN where none)
  double envelope_saving = 0.0;        // of the envelope against the reference (common speeds)
  int envelope_common_speeds = 0;
  int best_mean_foot = -1;             // the compared foot with the largest saving among those
                                       // reaching every speed the reference reaches (else among all)
  std::vector<int> ranking;            // compared feet by saving, best first (those without one last)
};

// (max - min) of the values, NaN if fewer than two or any is not finite: the spread of a foot's
// seed savings.
double spread(const std::vector<double>& values);

// Mean f_mech and saving of every foot against feet[reference]; the per-speed winners and the
// envelope. Throws std::invalid_argument if reference is not an index into feet.
FootComparisonResult summarise_feet(std::vector<double> speeds, std::vector<FootSweepSummary> feet, std::size_t reference);

// Reduces one finished sweep: f_mech from the gait at each best point's x (so also for an f_usq
// objective); mean and saving are left to summarise_feet.
FootSweepSummary summarise_sweep(const std::string& name, const walker::WalkerModel<double>& model,
                                 const walker::GaitProblemOptions& problem, const SpeedSweepResult& sweep);

// One foot's sweep, reduced: speed_sweep then summarise_sweep. The observer as speed_sweep's; when
// its on_point returns false the sweep stops and the summary says `stopped` (it holds what was found).
FootSweepSummary sweep_foot(const std::string& name, const walker::WalkerModel<double>& model,
                            const walker::GaitProblemOptions& problem, const SpeedSweepOptions& options,
                            SpeedSweepObserver& observer);
// The same with a PointObserver of on_point.
FootSweepSummary sweep_foot(const std::string& name, const walker::WalkerModel<double>& model,
                            const walker::GaitProblemOptions& problem, const SpeedSweepOptions& options,
                            const PointCallback& on_point = {});

}  // namespace cyclopt::studies
