#include "web_token.hpp"

#include <openssl/crypto.h>
#include <openssl/evp.h>
#include <openssl/hmac.h>

#include <array>
#include <cstdio>

namespace cyclopt::web {

namespace {

std::string mac_hex(const wire::AuthKey& key, const std::string& expiry) {
  const std::string text = "cyclopt-web " + key.id + " " + expiry;
  std::array<unsigned char, EVP_MAX_MD_SIZE> mac{};
  unsigned int length = 0;
  HMAC(EVP_sha256(), key.secret.data(), static_cast<int>(key.secret.size()),
       reinterpret_cast<const unsigned char*>(text.data()), text.size(), mac.data(), &length);
  std::string hex;
  char digit[3];
  for (unsigned int i = 0; i < length; ++i) {
    std::snprintf(digit, sizeof digit, "%02x", mac[i]);
    hex += digit;
  }
  return hex;
}

}  // namespace

std::string make_token(const wire::AuthKey& key, std::int64_t expires_unix) {
  const std::string expiry = std::to_string(expires_unix);
  return key.id + "." + expiry + "." + mac_hex(key, expiry);
}

const wire::AuthKey* check_token(const wire::KeyRing& keys, const std::string& token, std::int64_t now_unix,
                                 std::string& problem) {
  const std::size_t mac_dot = token.rfind('.');
  const std::size_t expiry_dot = mac_dot == std::string::npos || mac_dot == 0 ? std::string::npos : token.rfind('.', mac_dot - 1);
  if (expiry_dot == std::string::npos || expiry_dot == 0 || mac_dot == expiry_dot + 1) {
    problem = "malformed token";
    return nullptr;
  }
  const std::string id = token.substr(0, expiry_dot), expiry = token.substr(expiry_dot + 1, mac_dot - expiry_dot - 1);
  if (expiry.size() > 18 || expiry.find_first_not_of("0123456789") != std::string::npos) {
    problem = "malformed token";
    return nullptr;
  }
  const wire::AuthKey* key = keys.find(id);
  if (!key) {
    problem = "unknown key '" + id + "'";
    return nullptr;
  }
  const std::string expected = mac_hex(*key, expiry), given = token.substr(mac_dot + 1);
  if (given.size() != expected.size() || CRYPTO_memcmp(given.data(), expected.data(), expected.size()) != 0) {
    problem = "bad token";
    return nullptr;
  }
  if (std::stoll(expiry) < now_unix) {
    problem = "expired token";
    return nullptr;
  }
  return key;
}

}  // namespace cyclopt::web
