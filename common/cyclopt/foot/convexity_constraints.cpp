#include "cyclopt/foot/convexity_constraints.hpp"

#include <numbers>

namespace cyclopt::foot {
namespace {

struct Row {
  std::vector<std::pair<int, double>> coefficients;
  double offset;
  std::string name;
};

LinearInequalities assemble(int columns, const std::vector<Row>& rows) {
  LinearInequalities li;
  li.A = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows.size()), columns);
  li.b = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t r = 0; r < rows.size(); ++r) {
    for (const auto& [col, coef] : rows[r].coefficients) li.A(static_cast<Eigen::Index>(r), col) = coef;
    li.b[static_cast<Eigen::Index>(r)] = rows[r].offset;
    li.names.push_back(rows[r].name);
  }
  return li;
}

}  // namespace

LinearInequalities convexity_constraints(FootModel model) {
  switch (model) {
    case FootModel::hm:  // eq. (3.21)
      return assemble(hm::count, {
          {{{hm::h_F, 1.0}}, 0.0, "h_F >= 0"},
          {{{hm::l_HM, 1.0}}, 0.0, "l_HM >= 0"},
          {{{hm::l_HA, 1.0}}, 0.0, "l_HA >= 0"},
          {{{hm::l_HM, 1.0}, {hm::l_HA, -1.0}}, 0.0, "l_HM - l_HA >= 0"},
          {{{hm::k_H, 1.0}}, 0.0, "k_H >= 0"},
          {{{hm::k_HM, 1.0}}, 0.0, "k_HM >= 0"},
          {{{hm::k_M, 1.0}}, 0.0, "k_M >= 0"},
      });
    case FootModel::hmt:  // eq. (3.24)
      return assemble(hmt::count, {
          {{{hmt::h_F, 1.0}}, 0.0, "h_F >= 0"},
          {{{hmt::l_HM, 1.0}}, 0.0, "l_HM >= 0"},
          {{{hmt::l_HA, 1.0}}, 0.0, "l_HA >= 0"},
          {{{hmt::l_HM, 1.0}, {hmt::l_HA, -1.0}}, 0.0, "l_HM - l_HA >= 0"},
          {{{hmt::l_MT, 1.0}}, 0.0, "l_MT >= 0"},
          {{{hmt::gamma_F, 1.0}}, 0.0, "gamma_F >= 0"},
          {{{hmt::gamma_F, -1.0}}, std::numbers::pi / 2, "pi/2 - gamma_F >= 0"},
          {{{hmt::k_H, 1.0}}, 0.0, "k_H >= 0"},
          {{{hmt::k_HM, 1.0}}, 0.0, "k_HM >= 0"},
          {{{hmt::k_MT, 1.0}}, 0.0, "k_MT >= 0"},
          {{{hmt::k_T, 1.0}}, 0.0, "k_T >= 0"},
      });
    case FootModel::point:
      break;
  }
  return {};
}

}  // namespace cyclopt::foot
