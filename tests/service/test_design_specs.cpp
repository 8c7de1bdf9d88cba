// Foot-design fields of walker jobs (issue 15, acceptance 6): a negative density, bounds of eq.
// (10.1) that exclude the start foot, a free parameter the foot model lacks and a derived mass
// property set free are rejected naming the field and the admissible range; the seed's own set-up
// (P2 start, default bounds, foot and density free) is accepted with the start foot moved onto the
// bounds.
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/io/foot_spec_json.hpp"
#include "cyclopt/jobs/builtin_job_kinds.hpp"
#include "cyclopt/service/job_spec.hpp"
#include "cyclopt/service/spec_fields.hpp"
#include "cyclopt/jobs/walker/walker_job_spec.hpp"
#include "spec_rejection.hpp"

#include <gtest/gtest.h>

namespace cyclopt::service {
namespace {

using cyclopt::testing::rejection;
using namespace cyclopt::jobs;

// The seed's section 10.2 problem at one speed: P2 with a density, HM-relevant parameters free.
nlohmann::json design_spec() {
  nlohmann::json foot = io::to_json(foot::foot_preset("P2-shoes-left-HMT").spec);
  foot["density"] = 10.0;
  return {{"scene", "walker"},
          {"task", "optimise"},
          {"foot", foot},
          {"speed", 2.3},
          {"free_parameters", {"h_F", "l_HA", "l_HM", "l_MT", "k_HM", "k_MT"}},
          {"design_bounds", nlohmann::json::object()}};
}

bool mentions(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(DesignSpecs, TheSeedsSetUpIsAcceptedWithTheStartFootMovedOntoTheBounds) {
  EXPECT_EQ(rejection(design_spec()), "accepted");
  const WalkerJob job = parse_walker_job(design_spec(), parse_common_job_fields(design_spec()), false);
  ASSERT_TRUE(job.problem.design_bounds);
  EXPECT_DOUBLE_EQ(job.problem.design_bounds->h_F_max, 0.1);
  EXPECT_DOUBLE_EQ(job.problem.design_bounds->l_HM_max, 0.4);
  EXPECT_DOUBLE_EQ(job.foot.parameters[foot::hmt::h_F], 0.1);   // P2: 106.5 mm > h_F,max
  EXPECT_DOUBLE_EQ(job.foot.parameters[foot::hmt::l_MT], 0.1);  // P2: 112.4 mm > h_F
  EXPECT_DOUBLE_EQ(job.foot.parameters[foot::hmt::l_HM], foot::foot_preset("P2-shoes-left-HMT").spec.parameters[foot::hmt::l_HM]);
  nlohmann::json s = design_spec();
  s["design_bounds"] = {{"h_F_max", 0.12}, {"k_HM_max", 0.3}, {"toe_within_height", false}};
  const WalkerJob overridden = parse_walker_job(s, parse_common_job_fields(s), false);
  EXPECT_DOUBLE_EQ(overridden.problem.design_bounds->h_F_max, 0.12);
  EXPECT_DOUBLE_EQ(overridden.problem.design_bounds->k_HM_max, 0.3);
  EXPECT_FALSE(overridden.problem.design_bounds->toe_within_height);
  s["free_parameters"].push_back("density");
  EXPECT_EQ(rejection(s), "accepted");
}

TEST(DesignSpecs, NegativeDensityIsRejectedWithItsRange) {
  nlohmann::json s = design_spec();
  s["foot"]["density"] = -5.0;
  const std::string r = rejection(s);
  EXPECT_TRUE(r.rfind("foot.density: ", 0) == 0) << r;
  EXPECT_TRUE(mentions(r, "1e-06") || mentions(r, "0.000001")) << r;
  EXPECT_TRUE(mentions(r, "1000")) << r;
}

TEST(DesignSpecs, BoundsThatExcludeTheStartFootAreRejectedWithTheAdmissibleRange) {
  nlohmann::json s = design_spec();
  s["free_parameters"] = {"l_HA", "l_HM", "k_HM", "k_MT"};  // h_F fixed at 106.5 mm
  s["design_bounds"] = {{"toe_within_height", false}};
  std::string r = rejection(s);
  EXPECT_TRUE(r.rfind("design_bounds.h_F_max: ", 0) == 0) << r;
  EXPECT_TRUE(mentions(r, "0.1065")) << r;
  EXPECT_TRUE(mentions(r, "admissible")) << r;
  s["design_bounds"] = {{"h_F_max", 0.11}};  // holds, but l_MT = 112.4 mm > h_F and l_MT is fixed
  r = rejection(s);
  EXPECT_TRUE(r.rfind("design_bounds.toe_within_height: ", 0) == 0) << r;
  s = design_spec();
  s["design_bounds"] = {{"l_HM_max", 0.05}};  // below l_HA = 76.5 mm: no convex start foot
  r = rejection(s);
  EXPECT_TRUE(r.rfind("design_bounds: ", 0) == 0) << r;
  EXPECT_TRUE(mentions(r, "l_HA")) << r;
  s["design_bounds"] = {{"h_F_max", -0.1}};
  r = rejection(s);
  EXPECT_TRUE(r.rfind("design_bounds.h_F_max: ", 0) == 0) << r;
  EXPECT_TRUE(mentions(r, "0.5")) << r;
  s["design_bounds"] = {{"l_MT_max", 0.1}};
  EXPECT_TRUE(rejection(s).rfind("design_bounds.l_MT_max: ", 0) == 0) << rejection(s);  // unknown key, lists the known
  EXPECT_TRUE(mentions(rejection(s), "k_MT_max")) << rejection(s);
}

TEST(DesignSpecs, FreeParametersTheModelLacksOrThatFollowTheGeometryAreRejected) {
  nlohmann::json s = design_spec();
  s["foot"] = io::to_json(foot::foot_preset("P1-barefoot-left-HM").spec);
  s["foot"]["density"] = 20.0;
  s["free_parameters"] = {"h_F", "l_MT"};  // HM has no toe
  std::string r = rejection(s);
  EXPECT_TRUE(r.rfind("free_parameters[1]: ", 0) == 0) << r;
  EXPECT_TRUE(mentions(r, "k_HM")) << r;  // the admissible names are listed
  s["free_parameters"] = {"h_F", "m_F"};
  r = rejection(s);
  EXPECT_TRUE(r.rfind("free_parameters[1]: ", 0) == 0) << r;
  EXPECT_TRUE(mentions(r, "density")) << r;
  s["free_parameters"] = {"m_T"};  // bounds without a free foot parameter
  r = rejection(s);
  EXPECT_TRUE(r.rfind("design_bounds: ", 0) == 0) << r;
  s["foot"] = "point";
  s["free_parameters"] = nlohmann::json::array();
  EXPECT_TRUE(rejection(s).rfind("design_bounds: ", 0) == 0) << rejection(s);
}

}  // namespace
}  // namespace cyclopt::service
