#include "cyclopt/walker/model_parameters.hpp"

#include <numbers>
#include <stdexcept>

namespace cyclopt::walker {

int model_parameter_count(const WalkerModel<double>& m) {
  return segment_parameter_count + static_cast<int>(m.foot_parameters.size()) + (m.has_feet() ? 1 : 0) +
         (m.foot_density.active() ? 1 : 0);
}

std::vector<std::string> model_parameter_names(const WalkerModel<double>& m) {
  std::vector<std::string> names;
  for (int i = 0; i < segment_parameter_count; ++i) names.emplace_back(segment_parameter_info(i).name);
  for (const foot::ParameterInfo& info : foot::parameter_layout(m.foot_model)) names.emplace_back(info.name);
  if (m.has_feet()) names.emplace_back("theta_F0");
  if (m.foot_density.active()) names.emplace_back("density");
  return names;
}

int model_parameter_index(const WalkerModel<double>& m, const std::string& name) {
  const std::vector<std::string> names = model_parameter_names(m);
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<int>(i);
  std::string known;
  for (const std::string& n : names) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("model parameter '" + name + "' unknown for this scene; valid: " + known);
}

int density_index(const WalkerModel<double>& m) {
  return m.foot_density.active() ? model_parameter_count(m) - 1 : -1;
}

bool follows_foot_geometry(const WalkerModel<double>& m, int index) {
  if (!m.foot_density.active() || !m.has_feet()) return false;
  if (index == m_F || index == r_F || index == J_F) return true;
  const int zero_angle = segment_parameter_count + static_cast<int>(m.foot_parameters.size());
  return index == zero_angle && m.foot_density.zero_angle_from_geometry;
}

std::pair<double, double> model_parameter_range(const WalkerModel<double>& m, int index) {
  if (index == density_index(m)) return {foot::kMinDensity, foot::kMaxDensity};
  if (index < segment_parameter_count) {
    const SegmentParameterInfo& info = segment_parameter_info(index);
    return {info.min, info.max};
  }
  const auto layout = foot::parameter_layout(m.foot_model);
  const int f = index - segment_parameter_count;
  if (f < static_cast<int>(layout.size())) return {layout[f].min, layout[f].max};
  return {0.0, 2.0 * std::numbers::pi};
}

Eigen::VectorXd model_parameters(const WalkerModel<double>& m) {
  Eigen::VectorXd p(model_parameter_count(m));
  for (int i = 0; i < segment_parameter_count; ++i) p(i) = m.segments[i];
  const int nf = static_cast<int>(m.foot_parameters.size());
  for (int i = 0; i < nf; ++i) p(segment_parameter_count + i) = m.foot_parameters(i);
  if (m.has_feet()) p(segment_parameter_count + nf) = m.foot_zero_angle;
  if (m.foot_density.active()) p(density_index(m)) = *m.foot_density.rho;
  return p;
}

}  // namespace cyclopt::walker
