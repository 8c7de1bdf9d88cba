#pragma once
// Figures of a foot_design job (jobs/foot/foot_design_kind.cpp; seed 001 section 10.2), read from
// the job document `cyclopt export` writes through records/foot_design_records.hpp:
//   foot-design-outlines  the design of every density with an admissible one (solid) and its
//                         low-speed design (dashed), over the start foot, ankles at one point
//                         (Fig. 10.5/10.6)
//   foot-design-cost      f_mech over speed of both (their fixed-foot sweeps), with the start foot
//                         and point feet (Fig. 10.7)
//   foot-design-gait      the stroboscope of the best answer's gait at the design speed (Fig. 10.4)
// Densities without an admissible design, and sweeps without a point, are left out and named.

#include "cyclopt/foot/foot_spec.hpp"
#include "cyclopt/plot/walker_figures.hpp"
#include "cyclopt/records/foot_design_records.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace cyclopt::plot {

struct SweptCurve {
  std::string name;
  std::vector<double> speed, f_mech;  // the grid speeds with a point
};

struct DesignedDensity {
  records::DesignedFootRecord record;
  // When record.admissible: the start foot's model with the parameters and density of the design
  // (optimal at the design speed) and of the low-speed design (optimal at record.low_speed).
  foot::FootSpec design, low_design;
  SweptCurve sweep, low_sweep;  // their fixed-foot sweeps
  bool low_is_answer() const { return record.answer == "low-speed design"; }
  const foot::FootSpec& answer() const { return low_is_answer() ? low_design : design; }
  const SweptCurve& answer_sweep() const { return low_is_answer() ? low_sweep : sweep; }
  double answer_saving_vs_start() const { return low_is_answer() ? record.low_saving_vs_start : record.saving_vs_start; }
  double answer_saving_vs_point() const { return low_is_answer() ? record.low_saving_vs_point : record.saving_vs_point; }
};

struct FootDesignCurves {
  std::int64_t id = 0;
  foot::FootSpec start;   // the start foot (its own masses)
  SweptCurve start_foot, point_feet;
  std::vector<DesignedDensity> densities;  // in the order of the spec's densities
  int best = -1;          // index into densities: the admissible one whose answer saves most vs the start foot
  std::vector<GaitPoint> best_gaits;  // the fixed-foot sweep of the best density's answer (when best >= 0)
  nlohmann::json spec;    // as stored (the resolved spec where the job has one)
  StoredWalker walker;    // its setup record: the start foot, the walker constants
  double design_speed = 0.0;
};

// Throws std::invalid_argument when the document is not a foot_design job or has no density
// stored yet, records::RecordError when a stored point does not follow the contract.
FootDesignCurves foot_design_curves(const nlohmann::json& document);

LineChart foot_design_cost_chart(const FootDesignCurves& c);
Scene foot_design_outlines_scene(const FootDesignCurves& c);

// Every figure that can be drawn; with `not_drawn`, what was left out and why.
std::vector<Figure> foot_design_figures(const FootDesignCurves& curves, std::vector<std::string>* not_drawn = nullptr);
std::vector<Figure> foot_design_figures(const nlohmann::json& document, std::vector<std::string>* not_drawn = nullptr);

}  // namespace cyclopt::plot
