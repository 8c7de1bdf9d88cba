// A job its limit stops (service::JobLimits): judged by the points it announced, not by how many it
// stored. Through a server on memq:// with a kind that announces two points, stores three
// intermediate (not required) points and then counts iterations until the server stops it; its
// reason names the limit first, then what the stored points achieved.
#include "cyclopt/service/job_spec.hpp"
#include "memq_server_fixture.hpp"

#include <gtest/gtest.h>

namespace cyclopt {
namespace {

struct NoFields {};

service::JobKind runaway_kind() {
  return service::typed_job_kind<NoFields>(
      "evaluate", {"walker"}, {},
      [](const nlohmann::json&, const service::CommonJobFields&) { return NoFields{}; },
      [](const NoFields&, service::JobContext& ctx) {
        ctx.announce(2);
        ctx.add_curve(0, "required", "value");
        ctx.add_curve(1, "intermediate", "value");
        for (int k = 0; k < 3; ++k) {
          storage::SolutionPoint p;
          p.key = {1, k};
          p.parameter = k;
          p.required = false;
          ctx.store_point(p);
        }
        while (ctx.stop_reason() == service::StopReason::none) ctx.count_iterations(1);
      },
      [](const NoFields&) { return nlohmann::json::object(); },
      [](const NoFields&) { return service::JobCost{}; });
}

class JobLimits : public testing::MemqServerTest {
 protected:
  void SetUp() override {
    MemqServerTest::SetUp();
    kinds_ = service::JobKindRegistry{};
    kinds_.add(runaway_kind());
  }
};

TEST_F(JobLimits, AJobStoppedByItsIterationLimitFailsNamingTheLimitAlthoughItStoredMorePointsThanItAnnounced) {
  server::Server srv(config_, kinds_, lcm_);
  const nlohmann::json spec = {{"scene", "walker"}, {"task", "evaluate"}, {"limits", {{"max_iterations", 50}}}};
  const auto ack = client_.submit("runaway-1", spec.dump(), 5.0);
  ASSERT_TRUE(ack && ack->accepted) << (ack ? ack->problem : "no ack");
  const auto done = client_.watch(ack->job_id, [](const cyclopt_lcm::job_progress_t&) {}, 20.0);
  ASSERT_TRUE(done);
  EXPECT_EQ(done->points_stored, 3);
  EXPECT_EQ(done->state, "failed");
  EXPECT_EQ(done->error, "limits.max_iterations: exceeded 50; 0 of 2 points converged; 2 not stored");
}

}  // namespace
}  // namespace cyclopt
