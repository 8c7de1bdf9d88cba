#include "message_auth.hpp"

#include <openssl/crypto.h>
#include <openssl/evp.h>
#include <openssl/hmac.h>
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace cyclopt::wire {

namespace {

constexpr char kMagic[4] = {'C', 'Y', 'A', '1'};
constexpr std::size_t kMaxKeyIdBytes = 32;
constexpr std::size_t kMinSecretBytes = 16;

bool printable(const std::string& s) {
  for (unsigned char c : s)
    if (c < 0x21 || c > 0x7e) return false;
  return true;
}

std::array<std::uint8_t, 32> hmac(const AuthKey& key, const std::string& channel, std::span<const std::uint8_t> payload,
                                  const std::string& request_id, std::int64_t timestamp_us) {
  std::string data = channel;
  data += '\0';
  data.append(reinterpret_cast<const char*>(payload.data()), payload.size());
  for (int i = 7; i >= 0; --i) data += static_cast<char>(static_cast<std::uint64_t>(timestamp_us) >> (8 * i) & 0xff);
  data += request_id;
  data += '\0';
  data += key.id;
  std::array<std::uint8_t, 32> mac{};
  unsigned int len = 0;
  HMAC(EVP_sha256(), key.secret.data(), static_cast<int>(key.secret.size()),
       reinterpret_cast<const unsigned char*>(data.data()), data.size(), mac.data(), &len);
  return mac;
}

}  // namespace

const AuthKey* KeyRing::find(const std::string& id) const {
  for (const AuthKey& k : keys)
    if (k.id == id) return &k;
  return nullptr;
}

KeyRing read_key_file(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) throw std::invalid_argument("key file '" + path + "': cannot be read");
  if (st.st_mode & (S_IRWXG | S_IRWXO))
    throw std::invalid_argument("key file '" + path + "': readable by group or others (chmod 600 it)");
  std::ifstream in(path);
  if (!in) throw std::invalid_argument("key file '" + path + "': cannot be read");
  KeyRing ring;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    AuthKey k;
    std::string flag, extra;
    if (!(words >> k.id)) continue;
    const std::string where = "key file '" + path + "' line " + std::to_string(number) + ": ";
    if (!(words >> k.secret)) throw std::invalid_argument(where + "expected `ID SECRET [admin]`");
    if (words >> flag) {
      if (flag != "admin") throw std::invalid_argument(where + "third word must be 'admin', got '" + flag + "'");
      k.admin = true;
    }
    if (words >> extra) throw std::invalid_argument(where + "expected `ID SECRET [admin]`");
    if (k.id.size() > kMaxKeyIdBytes || !printable(k.id))
      throw std::invalid_argument(where + "key id must be 1..32 printable ASCII characters");
    if (k.secret.size() < kMinSecretBytes)
      throw std::invalid_argument(where + "secret must be at least " + std::to_string(kMinSecretBytes) + " characters");
    if (ring.find(k.id)) throw std::invalid_argument(where + "key id '" + k.id + "' appears twice");
    ring.keys.push_back(std::move(k));
  }
  if (ring.keys.empty()) throw std::invalid_argument("key file '" + path + "': holds no key");
  return ring;
}

std::optional<Signature> split_signature(std::span<const std::uint8_t>& bytes) {
  constexpr std::size_t fixed = 1 + 8 + 32 + sizeof kMagic;
  const std::size_t n = bytes.size();
  if (n < fixed + 1 || !std::equal(kMagic, kMagic + 4, bytes.end() - 4)) return std::nullopt;
  const std::size_t id_len = bytes[n - fixed];
  if (id_len < 1 || id_len > kMaxKeyIdBytes || n < fixed + id_len) return std::nullopt;
  Signature s;
  s.key_id.assign(reinterpret_cast<const char*>(bytes.data() + n - fixed - id_len), id_len);
  if (!printable(s.key_id)) return std::nullopt;
  std::uint64_t t = 0;
  for (std::size_t i = 0; i < 8; ++i) t = t << 8 | bytes[n - fixed + 1 + i];
  s.timestamp_us = static_cast<std::int64_t>(t);
  std::copy_n(bytes.begin() + static_cast<std::ptrdiff_t>(n - fixed + 9), 32, s.mac.begin());
  bytes = bytes.first(n - fixed - id_len);
  return s;
}

std::string signature_trailer(const AuthKey& key, const std::string& channel, std::span<const std::uint8_t> payload,
                              const std::string& request_id, std::int64_t timestamp_us) {
  std::string t = key.id;
  t += static_cast<char>(key.id.size());
  for (int i = 7; i >= 0; --i) t += static_cast<char>(static_cast<std::uint64_t>(timestamp_us) >> (8 * i) & 0xff);
  const auto mac = hmac(key, channel, payload, request_id, timestamp_us);
  t.append(reinterpret_cast<const char*>(mac.data()), mac.size());
  t.append(kMagic, sizeof kMagic);
  return t;
}

const AuthKey* verify_signature(const KeyRing& keys, const std::optional<Signature>& sig, const std::string& channel,
                                std::span<const std::uint8_t> payload, const std::string& request_id,
                                std::int64_t now_us, std::string& problem) {
  if (!sig) {
    problem = "unsigned message";
    return nullptr;
  }
  const AuthKey* key = keys.find(sig->key_id);
  if (!key) {
    problem = "unknown key '" + sig->key_id + "'";
    return nullptr;
  }
  const auto mac = hmac(*key, channel, payload, request_id, sig->timestamp_us);
  if (CRYPTO_memcmp(mac.data(), sig->mac.data(), mac.size()) != 0) {
    problem = "bad signature";
    return nullptr;
  }
  const double skew = std::abs(static_cast<double>(now_us) - static_cast<double>(sig->timestamp_us)) * 1e-6;
  if (skew > kMaxClockSkewSeconds) {
    char text[96];
    std::snprintf(text, sizeof text, "stale timestamp, %.1f s from this clock (at most %.0f s)", skew,
                  kMaxClockSkewSeconds);
    problem = text;
    return nullptr;
  }
  return key;
}

std::int64_t unix_now_us() {
  return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace cyclopt::wire
