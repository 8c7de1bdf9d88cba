// The foot dimension bounds of seed 001 eq. (10.1): rows per model, their values at the seed's
// start foot P2 (taller than h_F,max and with l_MT > h_F), and the projection of a start foot
// onto them in its movable parameters only.
#include "cyclopt/foot/design_bounds.hpp"
#include "cyclopt/foot/foot_presets.hpp"

#include <gtest/gtest.h>

namespace cyclopt::foot {
namespace {

TEST(DesignBounds, RowsPerModelWithTheSeedsDefaults) {
  EXPECT_EQ(design_constraints(FootModel::point, {}).b.size(), 0);
  EXPECT_EQ(design_constraints(FootModel::hm, {}).b.size(), 3);   // no toe: l_HM, h_F, k_HM
  EXPECT_EQ(design_constraints(FootModel::hmt, {}).b.size(), 5);  // eq. (10.1) in full
  DesignBounds no_toe_row;
  no_toe_row.toe_within_height = false;
  EXPECT_EQ(design_constraints(FootModel::hmt, no_toe_row).b.size(), 4);
  EXPECT_EQ(design_bound_fields(FootModel::hm).size(), 3u);
  EXPECT_EQ(design_bound_fields(FootModel::hmt).size(), 4u);
}

TEST(DesignBounds, TheSeedsStartFootViolatesHeightAndToeRows) {
  const FootSpec p2 = foot_preset("P2-shoes-left-HMT").spec;
  const LinearInequalities li = design_constraints(FootModel::hmt, {});
  const Eigen::VectorXd margin = li.A * p2.parameters + li.b;
  // Independent arithmetic from Table B.9: 400 - 248.6, 100 - 106.5, 0.5 - 0.054, 106.5 - 112.4, 0.5 - 0.1.
  const std::vector<std::pair<std::string, double>> expected = {{"l_HM_max - l_HM >= 0", 0.1514},
                                                                {"h_F_max - h_F >= 0", -0.0065},
                                                                {"k_HM_max - k_HM >= 0", 0.446},
                                                                {"h_F - l_MT >= 0", -0.0059},
                                                                {"k_MT_max - k_MT >= 0", 0.4}};
  ASSERT_EQ(margin.size(), static_cast<Eigen::Index>(expected.size()));
  for (std::size_t r = 0; r < expected.size(); ++r) {
    EXPECT_EQ(li.names[r], expected[r].first);
    EXPECT_NEAR(margin(static_cast<Eigen::Index>(r)), expected[r].second, 1e-12) << li.names[r];
  }
  const auto violated = violated_design_bounds(FootModel::hmt, p2.parameters, {});
  EXPECT_EQ(violated, (std::vector<std::string>{"h_F_max - h_F >= 0", "h_F - l_MT >= 0"}));
}

TEST(DesignBounds, ProjectionMovesOnlyMovableParameters) {
  const FootSpec p2 = foot_preset("P2-shoes-left-HMT").spec;
  const FootParameters<double> all = project_into_design_bounds(FootModel::hmt, p2.parameters, {}, {"h_F", "l_MT"});
  EXPECT_DOUBLE_EQ(all[hmt::h_F], 0.1);
  EXPECT_DOUBLE_EQ(all[hmt::l_MT], 0.1);
  EXPECT_TRUE(violated_design_bounds(FootModel::hmt, all, {}).empty());
  const FootParameters<double> toe_only = project_into_design_bounds(FootModel::hmt, p2.parameters, {}, {"l_MT"});
  EXPECT_DOUBLE_EQ(toe_only[hmt::h_F], p2.parameters[hmt::h_F]);
  EXPECT_DOUBLE_EQ(toe_only[hmt::l_MT], p2.parameters[hmt::h_F]);
  EXPECT_EQ(violated_design_bounds(FootModel::hmt, toe_only, {}), (std::vector<std::string>{"h_F_max - h_F >= 0"}));
}

}  // namespace
}  // namespace cyclopt::foot
