// The foot-design study's option checks (studies/foot_design.hpp): each bad option is refused
// before anything is solved, naming the option.
#include "cyclopt/studies/foot_design.hpp"
#include "cyclopt/foot/foot_presets.hpp"

#include <gtest/gtest.h>

#include <string>

using namespace cyclopt;
using namespace cyclopt::studies;

namespace {

std::string refusal(const foot::FootSpec& start, const FootDesignOptions& o) {
  try {
    design_feet(start, {}, o);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "accepted";
}

FootDesignOptions small() {
  FootDesignOptions o;
  o.densities = {10};
  o.sweep.speeds = {2.2, 2.3};
  o.design_speed = 2.3;
  return o;
}

const foot::FootSpec& p2() { return foot::foot_preset("P2-shoes-left-HMT").spec; }

}  // namespace

TEST(FootDesign, RefusesBadOptionsNamingThem) {
  FootDesignOptions o = small();
  o.densities = {10, -5};
  EXPECT_EQ(refusal(p2(), o).rfind("densities:", 0), 0u) << refusal(p2(), o);
  o = small();
  o.design_speed = 1.0;
  EXPECT_EQ(refusal(p2(), o).rfind("design_speed:", 0), 0u) << refusal(p2(), o);
  o = small();
  o.free_parameters = {"l_HM", "k_X"};
  EXPECT_NE(refusal(p2(), o).find("free_parameters: 'k_X'"), std::string::npos) << refusal(p2(), o);
  o = small();
  o.starts = 0;
  EXPECT_EQ(refusal(p2(), o).rfind("starts:", 0), 0u);
  EXPECT_EQ(refusal(foot::foot_preset("point").spec, small()).rfind("foot:", 0), 0u);
}

TEST(FootDesign, RefusesBoundsThatExcludeTheStartFootInAFixedParameter) {
  // P2's h_F is 106.5 mm, above h_F,max = 100 mm: with h_F free it is moved onto the bound, with
  // h_F fixed the bounds exclude the start foot.
  FootDesignOptions o = small();
  o.free_parameters = {"l_HM", "k_HM"};
  EXPECT_EQ(refusal(p2(), o).rfind("design_bounds:", 0), 0u) << refusal(p2(), o);
}
