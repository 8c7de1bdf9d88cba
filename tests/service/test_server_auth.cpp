// Authentication (issue 19, acceptance 2) over memq://: with a key file, unsigned, stale and
// forged requests are rejected and counted, a job can be cancelled only by its submitter's key
// or an admin key, replayed requests stay idempotent, and a client believes no ack, progress or
// done message that is not signed with its key.
#include "cyclopt_channels.hpp"
#include "memq_server_fixture.hpp"
#include "message_auth.hpp"

#include <cyclopt_lcm/job_submit_t.hpp>

#include <gtest/gtest.h>

#include <fstream>

namespace cyclopt {
namespace {

std::string sweep(int points, int delay_ms) {
  return nlohmann::json{{"scene", "walker"},
                        {"task", "foot_sweep"},
                        {"foot", "P2-shoes-left-HMT"},
                        {"point_delay_ms", delay_ms},
                        {"sweep", {{"parameter", "density"}, {"values", "1:1:" + std::to_string(points)}}}}
      .dump();
}

class ServerAuth : public testing::MemqServerTest {
 protected:
  void SetUp() override {
    MemqServerTest::SetUp();
    const auto path = dir_ / "keys";
    std::ofstream(path) << "# id secret [admin]\nalice alice-secret-0123456789\nbob bob-secret-0123456789abc\n"
                           "root root-secret-0123456789ab admin\n";
    std::filesystem::permissions(path, std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);
    config_.auth_secret_file = path.string();
    ring_ = wire::read_key_file(path.string());
  }
  const wire::AuthKey& key(const std::string& id) { return *ring_.find(id); }
  wire::KeyRing ring_;
};

TEST_F(ServerAuth, KeyFilesAreCheckedLineByLine) {
  const auto path = dir_ / "bad";
  std::ofstream(path) << "alice short\n";
  std::filesystem::permissions(path, std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);
  EXPECT_THROW(wire::read_key_file(path.string()), std::invalid_argument);
  std::filesystem::permissions(path, std::filesystem::perms::others_read, std::filesystem::perm_options::add);
  try {
    wire::read_key_file(path.string());
    ADD_FAILURE() << "a world-readable key file was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("chmod 600"), std::string::npos) << e.what();
  }
}

TEST_F(ServerAuth, UnsignedStaleAndForeignRequestsAreRejected) {
  server::Server srv(config_, kinds_, lcm_);
  ASSERT_TRUE(srv.authenticates());
  client::ServiceClient alice(lcm_, "", key("alice")), bob(lcm_, "", key("bob")), root(lcm_, "", key("root"));

  // Unsigned (the fixture's client has no key): the fixed signature rejection.
  EXPECT_THROW(client_.submit("anon-1", sweep(3, 0), 5.0), client::SignatureRejected);

  // Signed by alice: accepted; bob may not cancel it, an admin key may.
  const auto ack = alice.submit("alice-1", sweep(200, 20), 5.0);
  ASSERT_TRUE(ack && ack->accepted) << (ack ? ack->problem : "no ack");
  const auto by_bob = bob.cancel(ack->job_id, 5.0);
  ASSERT_TRUE(by_bob);
  EXPECT_FALSE(by_bob->accepted);
  EXPECT_EQ(by_bob->field, "job_id");
  EXPECT_NE(by_bob->problem.find("only its submitter's key or an admin key"), std::string::npos) << by_bob->problem;
  const auto by_root = root.cancel(ack->job_id, 5.0);
  ASSERT_TRUE(by_root);
  EXPECT_TRUE(by_root->accepted) << by_root->problem;
  const auto second = alice.submit("alice-2", sweep(200, 20), 5.0);
  ASSERT_TRUE(second && second->accepted);
  const auto by_alice = alice.cancel(second->job_id, 5.0);
  ASSERT_TRUE(by_alice);
  EXPECT_TRUE(by_alice->accepted) << by_alice->problem;

  // A correctly signed request two minutes old is stale; a replayed fresh one is idempotent.
  cyclopt_lcm::job_submit_t m;
  m.request_id = "alice-3";
  m.spec_json = sweep(3, 0);
  const std::string payload = wire::encode(m);
  const std::string stale = payload + wire::signature_trailer(key("alice"), channels::kSubmit, wire::as_bytes(payload),
                                                               m.request_id, wire::unix_now_us() - 120'000'000);
  const auto stale_ack = client_.send_raw(channels::kSubmit, stale, "alice-3", 5.0);
  ASSERT_TRUE(stale_ack);
  EXPECT_FALSE(stale_ack->accepted);
  EXPECT_EQ(stale_ack->problem, channels::kSignatureRejected);
  const std::string fresh = payload + wire::signature_trailer(key("alice"), channels::kSubmit, wire::as_bytes(payload),
                                                               m.request_id, wire::unix_now_us());
  const auto first = client_.send_raw(channels::kSubmit, fresh, "alice-3", 5.0);
  const auto replay = client_.send_raw(channels::kSubmit, fresh, "alice-3", 5.0);
  ASSERT_TRUE(first && replay);
  EXPECT_TRUE(first->accepted && !first->duplicate) << first->problem;
  EXPECT_TRUE(replay->accepted && replay->duplicate) << replay->problem;
  EXPECT_EQ(replay->job_id, first->job_id);
  // The same bytes with the signature of another key's secret: forged.
  wire::AuthKey forger = key("alice");
  forger.secret = "not-alices-secret-at-all";
  const std::string forged = payload + wire::signature_trailer(forger, channels::kSubmit, wire::as_bytes(payload),
                                                                "alice-4", wire::unix_now_us());
  const auto forged_ack = client_.send_raw(channels::kSubmit, forged, "alice-3", 5.0);
  ASSERT_TRUE(forged_ack);
  EXPECT_EQ(forged_ack->problem, channels::kSignatureRejected);
  EXPECT_EQ(srv.counters().unauthenticated, 3);
}

TEST_F(ServerAuth, ClientsBelieveOnlyMessagesSignedWithTheirKey) {
  server::Server srv(config_, kinds_, lcm_);
  client::ServiceClient alice(lcm_, "", key("alice"));
  wire::MessageBus rogue(lcm_, "");  // a stranger on the network, or another client's key
  // Forged acks for alice's next request, queued before it: a rejection unsigned, one signed by bob.
  cyclopt_lcm::job_ack_t fake{"alice-w", false, -1, false, "", "spec_json", "forged rejection"};
  rogue.publish(channels::kAck, fake);
  rogue.publish(channels::kAck, fake, &key("bob"));
  const auto ack = alice.submit("alice-w", sweep(30, 20), 5.0);
  ASSERT_TRUE(ack);
  EXPECT_TRUE(ack->accepted) << "believed: " << ack->problem;
  // Forged done messages for the watched job: the watch ends with the server's real one.
  cyclopt_lcm::job_done_t fake_done{ack->job_id, "alice-w", "failed", 0, 0.0, 0.0, "forged", -1, -1};
  rogue.publish(channels::kDone, fake_done);
  rogue.publish(channels::kDone, fake_done, &key("bob"));
  cyclopt_lcm::job_progress_t fake_progress{ack->job_id, "alice-w", "foot_sweep", 0, 0, 0, 0, 0, 0, 99, 100, 99.0, false, 0,
                                            "forged", "", -1, -1, 0, 0};
  rogue.publish(channels::kProgress, fake_progress);
  int forged_progress = 0, real_progress = 0;
  const auto done = alice.watch(ack->job_id, [&](const cyclopt_lcm::job_progress_t& p) {
    ++(p.message == "forged" ? forged_progress : real_progress);
  }, 30.0);
  ASSERT_TRUE(done);
  EXPECT_EQ(done->state, "done") << done->error;
  EXPECT_EQ(done->points_stored, 30);
  EXPECT_EQ(forged_progress, 0);
  EXPECT_GT(real_progress, 0);
  EXPECT_GE(alice.unverified_received(), 5);
}

// A client whose key the server does not know, or whose secret is wrong, is told so (the fixed,
// unsigned rejection) instead of waiting for an answer that never comes - for submissions and
// for reads alike; the rejection carries nothing but its fixed text.
TEST_F(ServerAuth, WrongKeyOrSecretIsToldSignatureRejected) {
  server::Server srv(config_, kinds_, lcm_);
  client::ServiceClient stranger(lcm_, "", wire::AuthKey{"mallory", "mallory-secret-0123456789", false});
  wire::AuthKey wrong = key("alice");
  wrong.secret = "not-alices-secret-at-all";
  client::ServiceClient misconfigured(lcm_, "", wrong);
  for (client::ServiceClient* c : {&stranger, &misconfigured}) {
    try {
      c->submit(client::new_request_id(), sweep(3, 0), 5.0);
      ADD_FAILURE() << "a submission with a wrong key or secret was not rejected";
    } catch (const client::SignatureRejected& e) {
      EXPECT_STREQ(e.what(), "signature rejected (unknown key or wrong secret)");
    }
    EXPECT_THROW(c->query(storage::query_for("jobs"), 5.0), client::SignatureRejected);
  }
  EXPECT_EQ(srv.store().count_jobs(std::nullopt), 0);
}

// Under authentication a key reads its own jobs and an admin key every job; "auth_reads": "any"
// lets every key read every job. Cancel stays the owner's either way.
TEST_F(ServerAuth, ReadsAreTheOwnersUnlessConfiguredForAnyKey) {
  for (const server::AuthReads reads : {server::AuthReads::owner, server::AuthReads::any}) {
    config_.auth_reads = reads;
    std::filesystem::remove(config_.database);
    server::Server srv(config_, kinds_, lcm_);
    client::ServiceClient alice(lcm_, "", key("alice")), bob(lcm_, "", key("bob")), root(lcm_, "", key("root"));
    const auto a = alice.submit(client::new_request_id(), sweep(3, 0), 5.0);
    const auto b = bob.submit(client::new_request_id(), sweep(3, 0), 5.0);
    ASSERT_TRUE(a && a->accepted && b && b->accepted);
    ASSERT_TRUE(alice.watch(a->job_id, [](const auto&) {}, 30.0));
    EXPECT_EQ(alice.query(storage::query_for("jobs"), 5.0)->total, reads == server::AuthReads::owner ? 1 : 2);
    EXPECT_EQ(root.query(storage::query_for("jobs"), 5.0)->total, 2);
    EXPECT_EQ(alice.query(storage::query_for("solutions", a->job_id), 5.0)->rows.size(), 3u);
    EXPECT_EQ(root.query(storage::query_for("solutions", a->job_id), 5.0)->rows.size(), 3u);
    for (const char* what : {"job", "solutions", "events", "curves", "trajectories"}) {
      if (reads == server::AuthReads::owner) {
        try {
          bob.query(storage::query_for(what, a->job_id), 5.0);
          ADD_FAILURE() << "bob read alice's " << what;
        } catch (const client::QueryError& e) {
          EXPECT_NE(std::string(e.what()).find("only its submitter's key or an admin key may read it"), std::string::npos)
              << e.what();
        }
      } else {
        EXPECT_TRUE(bob.query(storage::query_for(what, a->job_id), 5.0)) << what;
      }
    }
    const auto by_bob = bob.cancel(a->job_id, 5.0);
    ASSERT_TRUE(by_bob);
    EXPECT_FALSE(by_bob->accepted);
  }
}

}  // namespace
}  // namespace cyclopt
