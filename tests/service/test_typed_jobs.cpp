// Issue 14 item 1: a job's spec is parsed once into its kind's typed spec. Through a server on
// memq:// with a counting kind: an in-process submission is parsed once in all (the worker runs
// the parsed spec), a job queued before the server started is parsed once when it runs, and a
// stored spec that no longer parses fails its job with a message naming the field while the
// server goes on serving.
#include "cyclopt/service/job_spec.hpp"
#include "cyclopt/service/spec_fields.hpp"
#include "memq_server_fixture.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <memory>

namespace cyclopt {
namespace {

struct CountedSpec {
  double value = 1.0;
};

// Task "evaluate" (a task of the schema) with one field, "value" in [0, 10], stored as the
// point's parameter and estimated as that many seconds; every call of its parse is counted.
service::JobKind counting_kind(std::shared_ptr<std::atomic<int>> parses) {
  return service::typed_job_kind<CountedSpec>(
      "evaluate", {"walker"}, {"value"},
      [parses](const nlohmann::json& spec, const service::CommonJobFields&) {
        ++*parses;
        return CountedSpec{service::optional_number(spec, "", "value", 0.0, 10.0).value_or(1.0)};
      },
      [](const CountedSpec& s, service::JobContext& ctx) {
        ctx.announce(1);
        ctx.add_curve(0, "counted", "value");
        storage::SolutionPoint p;
        p.key = {0, 0};
        p.parameter = s.value;
        ctx.store_point(p);
      },
      [](const CountedSpec& s) { return nlohmann::json{{"value", s.value}}; },
      [](const CountedSpec& s) {
        service::JobCost c;
        c.seconds = s.value;
        c.field = "value";
        return c;
      });
}

std::string counted_spec(double value) {
  return nlohmann::json{{"scene", "walker"}, {"task", "evaluate"}, {"value", value}}.dump();
}

class TypedJobs : public testing::MemqServerTest {
 protected:
  void SetUp() override {
    MemqServerTest::SetUp();
    kinds_ = service::JobKindRegistry{};
    kinds_.add(counting_kind(parses_));
  }

  // Adds a job to the database as an earlier server would have queued it.
  std::int64_t queue_directly(const std::string& request_id, const std::string& spec_json) {
    storage::ResultStore store(config_.database);
    return store.submit(request_id, "walker", "evaluate", spec_json).job_id;
  }

  cyclopt_lcm::job_done_t wait_for(std::int64_t job_id) {
    const auto done = client_.watch(job_id, [](const cyclopt_lcm::job_progress_t&) {}, 20.0);
    EXPECT_TRUE(done) << "job " << job_id << " did not end";
    return done.value_or(cyclopt_lcm::job_done_t{});
  }

  double stored_parameter(std::int64_t job_id) {
    const auto page = client_.query(storage::query_for("solutions", job_id), 5.0);
    if (!page || page->rows.size() != 1) return -1.0;
    return page->rows[0]["parameter"].get<double>();
  }

  std::shared_ptr<std::atomic<int>> parses_ = std::make_shared<std::atomic<int>>(0);
};

TEST_F(TypedJobs, ASubmissionIsParsedOnceAndRunsItsTypedSpec) {
  server::Server srv(config_, kinds_, lcm_);
  for (int i = 0; i < 3; ++i) {
    const auto ack = client_.submit("counted-" + std::to_string(i), counted_spec(2.0 + i), 5.0);
    ASSERT_TRUE(ack && ack->accepted) << (ack ? ack->problem : "no ack");
    const cyclopt_lcm::job_done_t done = wait_for(ack->job_id);
    EXPECT_EQ(done.state, "done") << done.error;
    EXPECT_EQ(stored_parameter(ack->job_id), 2.0 + i);
    EXPECT_EQ(*parses_, i + 1) << "submission " << i << ": the worker parsed the spec again";
  }
  const auto rejected = client_.submit("counted-bad", counted_spec(11.0), 5.0);
  ASSERT_TRUE(rejected);
  EXPECT_FALSE(rejected->accepted);
  EXPECT_EQ(rejected->field, "value");
}

TEST_F(TypedJobs, AJobQueuedBeforeTheServerStartedIsParsedOnceWhenItRuns) {
  const std::int64_t id = queue_directly("stored-1", counted_spec(4.0));
  server::Server srv(config_, kinds_, lcm_);
  const cyclopt_lcm::job_done_t done = wait_for(id);
  EXPECT_EQ(done.state, "done") << done.error;
  EXPECT_EQ(stored_parameter(id), 4.0);
  EXPECT_EQ(*parses_, 1);
}

TEST_F(TypedJobs, AStoredSpecThatNoLongerParsesFailsItsJobAndTheServerGoesOn) {
  const std::int64_t malformed = queue_directly("stored-malformed", "{\"scene\": \"walker\", \"task\": ");
  const std::int64_t out_of_range = queue_directly("stored-out-of-range", counted_spec(12.0));
  const std::int64_t unknown_task = queue_directly(
      "stored-unknown-task", nlohmann::json{{"scene", "walker"}, {"task", "optimise"}}.dump());
  server::Server srv(config_, kinds_, lcm_);
  const auto expect_failed = [&](std::int64_t id, const std::string& part) {
    const cyclopt_lcm::job_done_t done = wait_for(id);
    EXPECT_EQ(done.state, "failed") << "job " << id;
    EXPECT_EQ(done.error.rfind("spec_json: the stored spec of job " + std::to_string(id), 0), 0u) << done.error;
    EXPECT_NE(done.error.find(part), std::string::npos) << done.error;
    const auto row = srv.store().job(id);
    ASSERT_TRUE(row);
    EXPECT_EQ(row->state, storage::JobState::failed);
    EXPECT_EQ(row->error, done.error);
  };
  expect_failed(malformed, "(spec_json: malformed JSON");
  expect_failed(out_of_range, "(value: must be in [0, 10], got 12");
  expect_failed(unknown_task, "(task: 'optimise' is not available on this server");
  const auto ack = client_.submit("after-the-bad-ones", counted_spec(3.0), 5.0);
  ASSERT_TRUE(ack && ack->accepted) << (ack ? ack->problem : "no ack");
  EXPECT_EQ(wait_for(ack->job_id).state, "done");
  EXPECT_EQ(stored_parameter(ack->job_id), 3.0);
}

// The one cast of typed_job_kind: a kind given another kind's spec says so instead of misreading it.
TEST(TypedJobKind, RefusesASpecAnotherKindParsed) {
  auto parses = std::make_shared<std::atomic<int>>(0);
  const service::JobKind counting = counting_kind(parses);
  const service::JobKind other = service::typed_job_kind<int>(
      "optimise", {"walker"}, {}, [](const nlohmann::json&, const service::CommonJobFields&) { return 7; },
      [](const int&, service::JobContext&) {}, [](const int&) { return nlohmann::json::object(); });
  const auto foreign = other.parse(nlohmann::json::object(), {});
  const auto own = counting.parse(nlohmann::json{{"value", 2.5}}, {});
  EXPECT_EQ(*parses, 1);
  EXPECT_EQ(counting.estimate(*own).seconds, 2.5);
  try {
    counting.estimate(*foreign);
    ADD_FAILURE() << "estimated another kind's spec";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("job kind 'evaluate' was given a spec that another kind parsed"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace cyclopt
