#include "cyclopt/walker/model_parameters.hpp"

#include <stdexcept>

namespace cyclopt::walker {

int model_parameter_count(const WalkerModel<double>& m) {
  return segment_parameter_count + static_cast<int>(m.foot_parameters.size()) + (m.has_feet() ? 1 : 0);
}

std::vector<std::string> model_parameter_names(const WalkerModel<double>& m) {
  std::vector<std::string> names;
  for (int i = 0; i < segment_parameter_count; ++i) names.emplace_back(segment_parameter_info(i).name);
  for (const foot::ParameterInfo& info : foot::parameter_layout(m.foot_model)) names.emplace_back(info.name);
  if (m.has_feet()) names.emplace_back("theta_F0");
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

Eigen::VectorXd model_parameters(const WalkerModel<double>& m) {
  Eigen::VectorXd p(model_parameter_count(m));
  for (int i = 0; i < segment_parameter_count; ++i) p(i) = m.segments[i];
  const int nf = static_cast<int>(m.foot_parameters.size());
  for (int i = 0; i < nf; ++i) p(segment_parameter_count + i) = m.foot_parameters(i);
  if (m.has_feet()) p(segment_parameter_count + nf) = m.foot_zero_angle;
  return p;
}

}  // namespace cyclopt::walker
