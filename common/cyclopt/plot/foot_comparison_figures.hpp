#pragma once
// Figures of a foot_comparison job (jobs/foot/foot_comparison_kind.cpp; seed 001 section 9.2):
//   foot-comparison  f_mech (eq. 5.102) over speed for every foot in one chart, the reference
//                    (point feet) dashed black and the best-foot envelope thick (Fig. 9.14/9.19a)
//   foot-outlines    the outlines of the compared feet side by side, on one scale (Fig. 9.8,
//                    9.13, 9.16), each with its ankle
// read from the job document `cyclopt export` writes.

#include "cyclopt/foot/foot_spec.hpp"
#include "cyclopt/plot/walker_figures.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace cyclopt::plot {

struct ComparedFootCurve {
  std::string name;
  foot::FootSpec spec;
  bool reference = false, best_fitted = false;
  double saving = 0.0;             // against the reference (NaN when unknown)
  std::vector<double> speed, f_mech;  // the speeds with a point
};

struct FootComparisonCurves {
  std::int64_t id = 0;
  std::vector<ComparedFootCurve> feet;             // reference first
  std::vector<double> envelope_speed, envelope_f_mech;
  // Per envelope speed: (max - min) / min of the best foot's f_mech over the seeds' own searches
  // (NaN: one seed, or a search without a point there).
  std::vector<double> envelope_seed_spread;
  double envelope_saving = 0.0;
};

// Throws std::invalid_argument when the document is not a foot_comparison job with its summary.
FootComparisonCurves foot_comparison_curves(const nlohmann::json& document);

LineChart foot_comparison_chart(const FootComparisonCurves& c);
Scene foot_outlines_scene(const FootComparisonCurves& c);
// Both figures (stems foot_comparison, foot_outlines).
std::vector<Figure> foot_comparison_figures(const nlohmann::json& document);

}  // namespace cyclopt::plot
