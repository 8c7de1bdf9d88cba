// Issue 17 item 7, reproducible results: every job the server accepts is stored with the git
// revision of the server, the random seeds it uses and its spec with every default filled in
// (service/resolved_spec.hpp), and that resolved spec, submitted again, is the same job.
#include "cyclopt/cli/version.hpp"
#include "cyclopt/service/job_spec.hpp"
#include "cyclopt/service/resolved_spec.hpp"
#include "memq_server_fixture.hpp"

#include <gtest/gtest.h>

namespace cyclopt {
namespace {

using ReproducibleJobs = testing::MemqServerTest;

nlohmann::json job_row(client::ServiceClient& client, std::int64_t id) {
  const auto page = client.query(storage::query_for("job", id), 5.0);
  EXPECT_TRUE(page);
  return page ? page->rows.at(0) : nlohmann::json();
}

TEST_F(ReproducibleJobs, AStoredJobRecordsTheVersionTheSeedsAndTheResolvedSpec) {
  server::Server srv(config_, kinds_, lcm_);
  const nlohmann::json spec = {{"scene", "walker"}, {"task", "multistart"}, {"foot", "P1-barefoot-left-HM"},
                               {"speed", 1.0}, {"points", 50}, {"solver", {{"max_iterations", 30}}},
                               {"multistart", {{"starts", 2}, {"seed", 42}}}};
  const auto ack = client_.submit("repro-multistart", spec.dump(), 5.0);
  ASSERT_TRUE(ack && ack->accepted) << (ack ? ack->problem : "no ack");
  const nlohmann::json job = job_row(client_, ack->job_id);
  EXPECT_EQ(job["program_version"], cli::git_revision());
  EXPECT_NE(job["program_version"], "");
  EXPECT_EQ(job["seeds"], (nlohmann::json{{"multistart.seed", 42}}));
  const nlohmann::json& r = job["resolved_spec"];
  std::printf("resolved sweep spec: %s\n", r.dump().c_str());
  EXPECT_EQ(r["speed"], 1.0);
  EXPECT_EQ(r["foot"]["model"], "HM");                   // the preset as its full parameters
  EXPECT_TRUE(r["foot"].contains("l_HM"));
  EXPECT_EQ(r["solver"]["solver"], "sqp");               // the seed's Table 6.2 defaults
  EXPECT_EQ(r["solver"]["max_iterations"], 30);
  EXPECT_EQ(r["solver"]["optimality_tolerance"], 1e-5);
  EXPECT_EQ(r["points"], 50);
  EXPECT_EQ(r["bezier_degree"], 6);
  EXPECT_EQ(r["objective"], "f_mech");
  EXPECT_EQ(r["multistart"], (nlohmann::json{{"starts", 2}, {"seed", 42}, {"scale", 0.05}}));
  const auto done = client_.watch(ack->job_id, [](const cyclopt_lcm::job_progress_t&) {}, 120.0);
  ASSERT_TRUE(done);
}

// The resolved spec of each walker kind is itself a valid spec that resolves to itself: the
// defaults it spells out are the ones the job ran with.
TEST(ResolvedSpec, TheResolvedSpecOfAWalkerJobIsTheSameJob) {
  const service::JobKindRegistry kinds = service::builtin_job_kinds();
  const std::vector<nlohmann::json> specs = {
      {{"scene", "walker"}, {"task", "evaluate"}, {"foot", "point"}, {"speed", 1.0}},
      {{"scene", "walker"}, {"task", "optimise"}, {"foot", "P1-barefoot-left-HM"}, {"speed", 1.3},
       {"objective", "f_usq"}, {"solver", {{"solver", "ipopt"}}}, {"free_parameters", {"l_HM", "h_F"}},
       {"design_bounds", {{"l_HM_max", 0.3}}}},
      {{"scene", "walker"}, {"task", "multistart"}, {"foot", "P1-barefoot-left-HM"}, {"speed", 1.3},
       {"multistart", {{"starts", 4}}}, {"name", "four starts"}, {"limits", {{"max_wall_seconds", 60}}}},
      {{"scene", "walker"}, {"task", "continuation"}, {"foot", "point"}, {"speeds", "0.5:0.5:1.5"},
       {"continuation", {{"predictor", "trivial"}, {"fixed_step", 0.2}}}},
      {{"scene", "walker"}, {"task", "continuation"}, {"foot", "P1-barefoot-left-HM"}, {"speeds", 1.0},
       {"continuation", {{"parameter", "l_HM"}, {"values", "0.1:0.05:0.2"}}}},
      {{"scene", "walker"}, {"task", "sweep"}, {"foot", "point"}, {"speeds", {0.5, 1.0}},
       {"multistart", {{"seed", 9}}}, {"continuation", {{"seed_speeds", 1.0}}}},
  };
  for (const nlohmann::json& spec : specs) {
    const nlohmann::json first = service::resolved_spec(service::validate_job_spec(spec, kinds), spec);
    EXPECT_FALSE(first.contains("resolved")) << first.dump();
    if (spec.contains("design_bounds")) {
      EXPECT_EQ(first["design_bounds"]["l_HM_max"], 0.3) << first.dump();
    }
    nlohmann::json again;
    ASSERT_NO_THROW(again = service::resolved_spec(service::validate_job_spec(first, kinds), first)) << first.dump();
    EXPECT_EQ(again, first);
  }
}

TEST(ResolvedSpec, SeedsAreTheFieldsNamedSeed) {
  EXPECT_EQ(service::random_seeds({{"multistart", {{"seed", 7}, {"starts", 3}}}, {"seed_speeds", {1}}}),
            (nlohmann::json{{"multistart.seed", 7}}));
  EXPECT_EQ(service::random_seeds({{"speed", 1.0}}), nlohmann::json::object());
}

// A kind without a resolver stores its fields as submitted and says that they are not resolved.
TEST(ResolvedSpec, AKindWithoutAResolverSaysSo) {
  const service::JobKindRegistry kinds = service::builtin_job_kinds();
  const nlohmann::json spec = {{"scene", "walker"}, {"task", "foot_sweep"}, {"foot", "P2-shoes-left-HMT"},
                               {"sweep", {{"parameter", "density"}, {"values", "20:20:60"}}}};
  const nlohmann::json r = service::resolved_spec(service::validate_job_spec(spec, kinds), spec);
  EXPECT_EQ(r["resolved"], false);
  EXPECT_EQ(r["sweep"], spec["sweep"]);
}

}  // namespace
}  // namespace cyclopt
