// renumber_new_curves (solution_curve.hpp): the curves a run jumped to take ids from a new first
// id on, in their order; the run's own curve keeps its id.
#include "cyclopt/continuation/solution_curve.hpp"

#include <gtest/gtest.h>

#include <vector>

using namespace cyclopt::continuation;

namespace {

ContinuationResult run_on(const std::vector<int>& curve_ids, const std::vector<CurveJump>& jumps, int next_curve_id) {
  ContinuationResult r;
  for (int id : curve_ids) {
    CurvePoint p;
    p.curve_id = id;
    r.points.push_back(p);
  }
  r.jumps = jumps;
  r.next_curve_id = next_curve_id;
  return r;
}

}  // namespace

TEST(RenumberNewCurves, JumpedToCurvesTakeTheIdsFromTheNewFirstOn) {
  ContinuationResult r = run_on({3, 3, 100, 100, 101}, {{3, 100, 0.5, 0.45}, {100, 101, 0.42, 0.41}}, 102);
  renumber_new_curves(r, 100, 7);
  std::vector<int> ids;
  for (const CurvePoint& p : r.points) ids.push_back(p.curve_id);
  EXPECT_EQ(ids, (std::vector<int>{3, 3, 7, 7, 8}));
  ASSERT_EQ(r.jumps.size(), 2u);
  EXPECT_EQ(r.jumps[0].from_curve, 3);
  EXPECT_EQ(r.jumps[0].to_curve, 7);
  EXPECT_EQ(r.jumps[1].from_curve, 7);
  EXPECT_EQ(r.jumps[1].to_curve, 8);
  EXPECT_EQ(r.next_curve_id, 9);
}

TEST(RenumberNewCurves, ARunWithoutJumpsOnlyMovesItsNextId) {
  ContinuationResult r = run_on({2, 2, 2}, {}, 100);
  renumber_new_curves(r, 100, 5);
  for (const CurvePoint& p : r.points) EXPECT_EQ(p.curve_id, 2);
  EXPECT_EQ(r.next_curve_id, 5);
}
