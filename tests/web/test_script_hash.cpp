// The CSP hash-source of an inline script (web/script_hash.hpp) against SHA-256 test vectors
// (FIPS 180-2 "abc", the empty message) in base64; dashboard_browser checks in chromium that the
// report's script runs under the policy built from it.
#include "script_hash.hpp"

#include <gtest/gtest.h>

namespace cyclopt::testing {
namespace {

TEST(ScriptHash, IsTheBase64OfTheSha256InQuotes) {
  EXPECT_EQ(web::script_hash_source("abc"), "'sha256-ungWv48Bz+pBQUDeXa4iI7ADYaOWF3qctBD/YfIAFa0='");
  EXPECT_EQ(web::script_hash_source(""), "'sha256-47DEQpj8HBSa+/TImW+5JCeuQeRkm5NMpJWZG3hSuFU='");
}

}  // namespace
}  // namespace cyclopt::testing
