#include "cyclopt/foot/design_bounds.hpp"

#include <algorithm>

namespace cyclopt::foot {

namespace {

int index_of(FootModel model, const std::string& parameter) {
  const auto layout = parameter_layout(model);
  for (std::size_t i = 0; i < layout.size(); ++i)
    if (layout[i].name == parameter) return static_cast<int>(i);
  return -1;
}

DesignBoundField field(FootModel model, std::string name, std::string parameter, double DesignBounds::*value) {
  const ParameterInfo& info = parameter_layout(model)[static_cast<std::size_t>(index_of(model, parameter))];
  return {std::move(name), std::move(parameter), info.min, info.max, value};
}

}  // namespace

std::vector<DesignBoundField> design_bound_fields(FootModel model) {
  if (model == FootModel::point) return {};
  std::vector<DesignBoundField> f = {field(model, "l_HM_max", "l_HM", &DesignBounds::l_HM_max),
                                     field(model, "h_F_max", "h_F", &DesignBounds::h_F_max),
                                     field(model, "k_HM_max", "k_HM", &DesignBounds::k_HM_max)};
  if (model == FootModel::hmt) f.push_back(field(model, "k_MT_max", "k_MT", &DesignBounds::k_MT_max));
  return f;
}

LinearInequalities design_constraints(FootModel model, const DesignBounds& bounds) {
  LinearInequalities li;
  if (model == FootModel::point) return li;
  struct Row {
    int plus, minus;  // A row: +1 at plus (or none), -1 at minus
    double offset;
    std::string name;
  };
  const int h_f = index_of(model, "h_F"), l_hm = index_of(model, "l_HM"), k_hm = index_of(model, "k_HM");
  std::vector<Row> rows = {{-1, l_hm, bounds.l_HM_max, "l_HM_max - l_HM >= 0"},
                           {-1, h_f, bounds.h_F_max, "h_F_max - h_F >= 0"},
                           {-1, k_hm, bounds.k_HM_max, "k_HM_max - k_HM >= 0"}};
  if (model == FootModel::hmt) {
    if (bounds.toe_within_height) rows.push_back({h_f, hmt::l_MT, 0.0, "h_F - l_MT >= 0"});
    rows.push_back({-1, hmt::k_MT, bounds.k_MT_max, "k_MT_max - k_MT >= 0"});
  }
  const int columns = static_cast<int>(parameter_layout(model).size());
  li.A = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows.size()), columns);
  li.b.resize(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const auto i = static_cast<Eigen::Index>(r);
    if (rows[r].plus >= 0) li.A(i, rows[r].plus) = 1.0;
    li.A(i, rows[r].minus) = -1.0;
    li.b(i) = rows[r].offset;
    li.names.push_back(rows[r].name);
  }
  return li;
}

std::vector<std::string> violated_design_bounds(FootModel model, const FootParameters<double>& p,
                                                const DesignBounds& bounds, double tolerance) {
  const LinearInequalities li = design_constraints(model, bounds);
  std::vector<std::string> out;
  if (li.b.size() == 0) return out;
  const Eigen::VectorXd margin = li.A * p + li.b;
  for (Eigen::Index r = 0; r < margin.size(); ++r)
    if (margin(r) < -tolerance) out.push_back(li.names[static_cast<std::size_t>(r)]);
  return out;
}

FootParameters<double> project_into_design_bounds(FootModel model, FootParameters<double> p, const DesignBounds& bounds,
                                                  const std::vector<std::string>& movable) {
  auto is_movable = [&](const std::string& n) { return std::find(movable.begin(), movable.end(), n) != movable.end(); };
  for (const DesignBoundField& f : design_bound_fields(model)) {
    const int i = index_of(model, f.parameter);
    if (is_movable(f.parameter)) p[i] = std::min(p[i], bounds.*f.value);
  }
  if (model == FootModel::hmt && bounds.toe_within_height && is_movable("l_MT"))
    p[hmt::l_MT] = std::min(p[hmt::l_MT], p[hmt::h_F]);
  return p;
}

}  // namespace cyclopt::foot
