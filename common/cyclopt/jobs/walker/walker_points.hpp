#pragma once
// Stored points of the walker job kinds: a gait (and the solve that produced it) as a WalkerPoint,
// the row of a storage::SolutionPoint with its values a records::WalkerPointRecord (gait scalars,
// solver summary, start, continuation step, x) and its trajectory a records::GaitTrajectoryRecord,
// beside which a kind stores records of its own (a multistart's optimum, a sweep's best row, a
// compared foot's speed).
#include "cyclopt/continuation/continuation_solver.hpp"
#include "cyclopt/records/gait_records.hpp"
#include "cyclopt/records/sensitivity_records.hpp"
#include "cyclopt/records/walker_point_record.hpp"
#include "cyclopt/service/job_context.hpp"
#include "cyclopt/storage_read/solution_point.hpp"
#include "cyclopt/walker/gait_optimisation.hpp"
#include "cyclopt/walker/starting_gait.hpp"

#include <map>
#include <optional>

namespace cyclopt::jobs {

struct WalkerPoint {
  storage::SolutionPoint row;  // its key, parameter, objective, constraint violation, iterations, status
  records::WalkerPointRecord values;
  std::optional<records::GaitTrajectoryRecord> trajectory;

  // The point to store: the row with the values and, beside them, the kind's own records.
  template <records::PointValues... Extra>
  storage::SolutionPoint stored(const Extra&... extra) const {
    storage::SolutionPoint p = row;
    p.set_values(values, extra...);
    if (trajectory) p.set_trajectory(*trajectory);
    return p;
  }
};

// An evaluated gait and the start it was evaluated at.
WalkerPoint walker_point(const walker::PeriodicGait<double>& gait, const walker::GaitStart& start, storage::PointKey key,
                         double parameter);
// sensitivities: the optimum's KKT sensitivities (walker_records.hpp), stored with it.
WalkerPoint walker_point(const walker::GaitOptimum& opt, storage::PointKey key, double parameter,
                         std::optional<records::KktSensitivitiesRecord> sensitivities = std::nullopt);
// A continuation point of the walker family `family` (studies::walker_family) with its gait and
// the continuation's own figures (curve id, predictor attempts, kappa, trust region, x).
WalkerPoint walker_point(const continuation::ParametricProblem& family, const continuation::CurvePoint& c,
                         storage::PointKey key);

// The same points to store as they are.
storage::SolutionPoint point_of(const walker::PeriodicGait<double>& gait, const walker::GaitStart& start,
                                storage::PointKey key, double parameter);
storage::SolutionPoint point_of(const walker::GaitOptimum& opt, storage::PointKey key, double parameter,
                                std::optional<records::KktSensitivitiesRecord> sensitivities = std::nullopt);

// Stores curve points as a continuation finds them: curve_index = curve id + offset, numbered along
// the curve. grid_points_required: the points on the requested grid are what the job was asked
// for (a continuation job), rather than a by-product (a sweep's runs, whose best rows are).
class CurveStore {
 public:
  CurveStore(service::JobContext& ctx, const continuation::ParametricProblem& family, int offset, bool grid_points_required)
      : ctx_(ctx), family_(family), offset_(offset), grid_points_required_(grid_points_required) {}

  // For continuation::PointCallback: stores the point and returns false once the job should stop;
  // a point whose solve the job stopped is not stored.
  bool operator()(const continuation::CurvePoint& c);
  // A point of the family, as the store would hold it at `key`.
  WalkerPoint point(const continuation::CurvePoint& c, storage::PointKey key) const { return walker_point(family_, c, key); }

 private:
  service::JobContext& ctx_;
  const continuation::ParametricProblem& family_;
  const int offset_;
  const bool grid_points_required_;
  std::map<int, int> counts_;
};

}  // namespace cyclopt::jobs
