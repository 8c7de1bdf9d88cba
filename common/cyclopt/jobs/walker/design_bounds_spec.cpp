#include "cyclopt/jobs/walker/design_bounds_spec.hpp"

#include "cyclopt/foot/design_bounds.hpp"
#include "cyclopt/service/spec_fields.hpp"

#include <algorithm>
#include <sstream>

namespace cyclopt::jobs {

using namespace service;  // the job-kind infrastructure: JobKind, JobContext, the spec fields

namespace {

std::string number(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

bool contains(const std::vector<std::string>& v, const std::string& x) { return std::find(v.begin(), v.end(), x) != v.end(); }

int parameter_index(foot::FootModel model, const std::string& name) {
  const auto layout = foot::parameter_layout(model);
  for (std::size_t i = 0; i < layout.size(); ++i)
    if (layout[i].name == name) return static_cast<int>(i);
  return -1;
}

}  // namespace

void apply_design_bounds(const nlohmann::json& v, const std::string& path, WalkerJob& job) {
  const nlohmann::json& j = object_value(v, path);
  const foot::FootModel model = job.foot.model;
  if (model == foot::FootModel::point) throw SpecError(path, "needs a rolling foot (HM or HMT); point feet have no dimensions");
  const auto& free = job.problem.free_parameters;
  const auto layout = foot::parameter_layout(model);
  if (std::none_of(layout.begin(), layout.end(), [&](const foot::ParameterInfo& p) { return contains(free, std::string(p.name)); }))
    throw SpecError(path, "bounds the foot's dimensions and needs foot parameters in free_parameters");
  const std::vector<foot::DesignBoundField> fields = design_bound_fields(model);
  std::vector<std::string> known;
  for (const auto& f : fields) known.push_back(f.name);
  if (model == foot::FootModel::hmt) known.emplace_back("toe_within_height");
  reject_unknown_keys(j, path, known);

  foot::DesignBounds bounds;
  for (const auto& f : fields) bounds.*f.value = optional_number(j, path, f.name, f.min, f.max).value_or(bounds.*f.value);
  if (j.contains("toe_within_height")) {
    if (!j["toe_within_height"].is_boolean()) throw SpecError(path + ".toe_within_height", "must be true or false");
    bounds.toe_within_height = j["toe_within_height"].get<bool>();
  }
  // A bound on a fixed parameter must hold at the start foot: nothing can move it there.
  const foot::FootParameters<double>& p = job.foot.parameters;
  for (const auto& f : fields) {
    const double start = p[parameter_index(model, f.parameter)];
    if (!contains(free, f.parameter) && start > bounds.*f.value)
      throw SpecError(path + "." + f.name, "= " + number(bounds.*f.value) + " excludes the start foot, whose " + f.parameter +
                                               " = " + number(start) + " is not free; admissible: [" + number(start) +
                                               ", " + number(f.max) + "] (or free " + f.parameter + ")");
  }
  if (model == foot::FootModel::hmt && bounds.toe_within_height && p[foot::hmt::l_MT] > p[foot::hmt::h_F] &&
      !contains(free, "l_MT"))
    throw SpecError(path + ".toe_within_height",
                    "= true excludes the start foot (l_MT = " + number(p[foot::hmt::l_MT]) + " m > h_F = " +
                        number(p[foot::hmt::h_F]) + " m) with l_MT not free; admissible: false (or free l_MT)");
  foot::FootSpec moved = job.foot;
  moved.parameters = project_into_design_bounds(model, p, bounds, free);
  try {
    foot::validate(moved, "foot");
  } catch (const SpecError& e) {
    throw SpecError(path, std::string("moves the start foot out of the admissible set (") + e.what() +
                              "); raise the bounds or start from a smaller foot");
  }
  job.foot = moved;
  job.problem.design_bounds = bounds;
}

}  // namespace cyclopt::jobs
