// What cyclopt-web reads from a request (web/web_request.hpp) and the message page it answers with
// (web/message_page.hpp).
#include "message_page.hpp"
#include "web_request.hpp"

#include <gtest/gtest.h>

using namespace cyclopt::web;

TEST(WebRequest, JobIdIsAPositiveDecimalInRange) {
  EXPECT_EQ(job_id_of("17"), 17);
  EXPECT_EQ(job_id_of("9223372036854775807"), 9223372036854775807LL);
  for (const char* bad : {"", "0", "-3", "+3", "1e3", " 1", "1 ", "0x10", "9223372036854775808", "99999999999999999999"})
    EXPECT_EQ(job_id_of(bad), std::nullopt) << bad;
}

TEST(WebRequest, CookieValueByExactName) {
  EXPECT_EQ(cookie_value("cyclopt_token=a.1.ff", "cyclopt_token"), "a.1.ff");
  EXPECT_EQ(cookie_value("theme=dark; cyclopt_token=a.1.ff; x=y", "cyclopt_token"), "a.1.ff");
  EXPECT_EQ(cookie_value("my_cyclopt_token=evil; cyclopt_token_old=old", "cyclopt_token"), "");
  EXPECT_EQ(cookie_value("", "cyclopt_token"), "");
  EXPECT_EQ(cookie_value("cyclopt_token=", "cyclopt_token"), "");
}

TEST(WebRequest, SameOriginNamesThisHost) {
  EXPECT_TRUE(same_origin("", "127.0.0.1:8080"));  // same-origin requests may come without Origin
  EXPECT_TRUE(same_origin("http://127.0.0.1:8080", "127.0.0.1:8080"));
  EXPECT_FALSE(same_origin("http://evil.example", "127.0.0.1:8080"));
  EXPECT_FALSE(same_origin("http://127.0.0.1:8081", "127.0.0.1:8080"));
  EXPECT_FALSE(same_origin("null", "127.0.0.1:8080"));
}

TEST(MessagePage, JobTextStaysText) {
  const std::string page = message_page("No job <script>alert(1)</script> & \"more\"");
  EXPECT_EQ(page.find("<script>"), std::string::npos);
  EXPECT_NE(page.find("&lt;script&gt;alert(1)&lt;/script&gt; &amp;"), std::string::npos);
}
