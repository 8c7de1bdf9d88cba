// The dashboard's login token (web/web_token.hpp): made from a key, accepted only for that key's
// secret, before its expiry, and in its exact form.
#include "web_token.hpp"

#include <gtest/gtest.h>

using namespace cyclopt;

namespace {

const wire::KeyRing kRing{{{"alice", "alice-secret-0123456789", false}, {"ops.root", "root-secret-0123456789ab", true}}};
constexpr std::int64_t kNow = 1'800'000'000;

}  // namespace

TEST(WebToken, AcceptsTheKeyItWasMadeWithUntilItExpires) {
  for (const wire::AuthKey& key : kRing.keys) {
    const std::string token = web::make_token(key, kNow + 60);
    std::string problem;
    EXPECT_EQ(web::check_token(kRing, token, kNow, problem), kRing.find(key.id)) << problem;
    EXPECT_EQ(web::check_token(kRing, token, kNow + 60, problem), kRing.find(key.id)) << problem;
    EXPECT_EQ(web::check_token(kRing, token, kNow + 61, problem), nullptr);
    EXPECT_EQ(problem, "expired token");
  }
}

TEST(WebToken, RefusesAnotherSecretAChangedExpiryOrKeyAndMalformedText) {
  const std::string token = web::make_token(kRing.keys[0], kNow + 60);
  std::string problem;
  const wire::AuthKey forged{"alice", "not-alice-secret-0123456789", false};
  EXPECT_EQ(web::check_token(kRing, web::make_token(forged, kNow + 60), kNow, problem), nullptr);
  EXPECT_EQ(problem, "bad token");
  std::string later = token;
  later.replace(later.find('.') + 1, 10, std::to_string(kNow + 99));  // a longer life, same MAC
  EXPECT_EQ(web::check_token(kRing, later, kNow, problem), nullptr);
  EXPECT_EQ(problem, "bad token");
  std::string other_key = token;
  other_key.replace(0, 5, "ops.root");  // alice's MAC under root's id
  EXPECT_EQ(web::check_token(kRing, other_key, kNow, problem), nullptr);
  EXPECT_EQ(problem, "bad token");
  EXPECT_EQ(web::check_token(kRing, web::make_token({"mallory", "mallory-secret-0123456789", false}, kNow + 60), kNow, problem),
            nullptr);
  EXPECT_EQ(problem, "unknown key 'mallory'");
  for (const std::string bad : {"", "alice", "alice.123", ".123.ab", "alice..ab", "alice.12x.ab", "alice.-5.ab",
                                "alice.1234567890123456789.ab"}) {
    EXPECT_EQ(web::check_token(kRing, bad, kNow, problem), nullptr) << bad;
    EXPECT_EQ(problem, "malformed token") << bad;
  }
  EXPECT_EQ(web::check_token(kRing, token + "0", kNow, problem), nullptr);
  EXPECT_EQ(problem, "bad token");
}
