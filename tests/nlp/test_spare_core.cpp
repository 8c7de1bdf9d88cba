// split_on_spare_core: who runs which part of the range, and that a helper's failure reaches the
// caller. (Whether the split gives the same numbers is tested on the walker's Jacobian and
// difference Hessian, tests/walker/test_gait_jacobian_paths.cpp.)
#include "cyclopt/nlp/spare_core.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <tuple>
#include <vector>

namespace cyclopt::nlp {
namespace {

struct Call {
  int begin, end;
  bool helper;
  std::thread::id thread;
};

std::vector<Call> calls_with(SpareCoreRule rule, int n, int min_split) {
  set_spare_core_rule(rule);
  std::vector<Call> calls;
  std::mutex m;
  split_on_spare_core(n, min_split, [&](int begin, int end, bool helper) {
    const std::lock_guard lock(m);
    calls.push_back({begin, end, helper, std::this_thread::get_id()});
  });
  set_spare_core_rule(SpareCoreRule::measured);
  std::sort(calls.begin(), calls.end(), [](const Call& a, const Call& b) { return a.begin < b.begin; });
  return calls;
}

TEST(SpareCore, WithoutASpareCoreTheWholeRangeRunsInTheCallingThread) {
  const std::vector<Call> calls = calls_with(SpareCoreRule::never, 10, 2);
  ASSERT_EQ(calls.size(), 1u);
  EXPECT_EQ(std::tie(calls[0].begin, calls[0].end, calls[0].helper), std::make_tuple(0, 10, false));
  EXPECT_EQ(calls[0].thread, std::this_thread::get_id());
}

TEST(SpareCore, WithASpareCoreTheUpperHalfRunsInAHelperThread) {
  const std::vector<Call> calls = calls_with(SpareCoreRule::always, 7, 2);
  ASSERT_EQ(calls.size(), 2u);
  EXPECT_EQ(std::tie(calls[0].begin, calls[0].end, calls[0].helper), std::make_tuple(0, 3, false));
  EXPECT_EQ(std::tie(calls[1].begin, calls[1].end, calls[1].helper), std::make_tuple(3, 7, true));
  EXPECT_EQ(calls[0].thread, std::this_thread::get_id());
  EXPECT_NE(calls[1].thread, std::this_thread::get_id());
}

TEST(SpareCore, ARangeShorterThanTheMinimalSplitIsNotSplit) {
  const std::vector<Call> calls = calls_with(SpareCoreRule::always, 3, 4);
  ASSERT_EQ(calls.size(), 1u);
  EXPECT_EQ(std::tie(calls[0].begin, calls[0].end, calls[0].helper), std::make_tuple(0, 3, false));
}

TEST(SpareCore, AnExceptionInTheHelperReachesTheCallerAfterBothHalvesEnded) {
  set_spare_core_rule(SpareCoreRule::always);
  bool own_half_done = false;
  EXPECT_THROW(split_on_spare_core(4, 2,
                                   [&](int, int, bool helper) {
                                     if (helper) throw std::runtime_error("helper failed");
                                     own_half_done = true;
                                   }),
               std::runtime_error);
  set_spare_core_rule(SpareCoreRule::measured);
  EXPECT_TRUE(own_half_done);
}

}  // namespace
}  // namespace cyclopt::nlp
