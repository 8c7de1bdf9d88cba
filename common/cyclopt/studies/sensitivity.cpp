#include "cyclopt/studies/sensitivity.hpp"

#include "cyclopt/continuation/continuation_solver.hpp"
#include "cyclopt/studies/walker_family.hpp"
#include "cyclopt/walker/model_parameters.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace cyclopt::studies {

using continuation::ContinuationResult;
using continuation::CurvePoint;

std::vector<SensitivityCurve> sensitivity(const walker::WalkerModel<double>& model, const walker::GaitProblemOptions& problem,
                                          const Eigen::VectorXd& z, const SensitivityOptions& o) {
  if (!(o.relative_range > 0.0 && o.relative_range < 1.0)) throw std::invalid_argument("relative_range: must be in (0, 1)");
  if (o.steps < 1) throw std::invalid_argument("steps: must be >= 1");
  if (!(o.min_step_fraction > 0.0 && o.min_step_fraction <= 1.0)) throw std::invalid_argument("min_step_fraction: must be in (0, 1]");
  std::vector<std::string> names = o.parameters;
  if (names.empty()) {
    const std::vector<std::string> all = walker::model_parameter_names(model);
    const auto first = all.begin() + walker::segment_parameter_count;
    names.assign(first, first + static_cast<long>(model.foot_parameters.size()));
  }
  const Eigen::VectorXd p_mod = walker::model_parameters(model);
  std::vector<SensitivityCurve> out;
  for (const std::string& name : names) {
    SensitivityCurve c;
    c.parameter = name;
    c.base_value = p_mod[walker::model_parameter_index(model, name)];
    if (c.base_value == 0.0) throw std::invalid_argument("parameters: " + name + " is 0, a relative change is undefined");
    const ParametricProblem family = walker_family(model, problem, name);
    ContinuationOptions co = o.continuation;
    co.min_trust_region = o.min_step_fraction * std::abs(c.base_value) * o.relative_range / o.steps;
    double f0 = 0.0;
    for (const double direction : {-1.0, 1.0}) {
      std::vector<double> grid;
      for (int k = 0; k <= o.steps; ++k) grid.push_back(c.base_value * (1.0 + direction * o.relative_range * k / o.steps));
      const ContinuationResult r = continue_solution(family, z, grid, co);
      c.jumps += static_cast<int>(r.jumps.size());
      if (!r.finished) c.message += (direction < 0 ? "decrease: " : "increase: ") + r.message + "; ";
      if (r.points.empty() || !r.points.front().converged) continue;
      f0 = r.points.front().objective;
      for (const CurvePoint& p : r.points)
        if (p.converged && p.on_grid && (direction > 0 || p.parameter != c.base_value))
          c.points.push_back({(p.parameter - c.base_value) / c.base_value, p.objective - f0, p.curve_id});
    }
    std::sort(c.points.begin(), c.points.end(),
              [](const SensitivityPoint& a, const SensitivityPoint& b) { return a.relative_change < b.relative_change; });
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace cyclopt::studies
