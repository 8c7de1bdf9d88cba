#pragma once
// Optional authentication of every message (issue 19): with shared secrets configured, each
// message carries a trailer after its LCM encoding,
//   key id (1..32 printable ASCII) | key id length (u8) | timestamp (i64 µs, Unix) | HMAC (32) | "CYA1"
// whose HMAC-SHA256 (OpenSSL libcrypto), keyed by the secret of that key id, covers the channel,
// the payload (the LCM encoding), the timestamp, the message's request id and the key id.
// Receivers check the key, the HMAC and the timestamp's distance from their clock
// (kMaxClockSkewSeconds) and drop or reject the message otherwise. Requests are signed by the
// client's key; the server signs an answer with the requester's key and progress and done
// messages with the submitter's, so one client cannot forge them for another.
//
// Key files (the path goes in a config file or environment variable, never a secret on a
// command line): one key a line, `ID SECRET [admin]`, # starts a comment; SECRET at least 16
// characters; the file must not be readable by group or others (chmod 600). The server's file
// holds every client's key; a client's file holds its own (the first line is used).

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace cyclopt::wire {

inline constexpr double kMaxClockSkewSeconds = 30.0;

struct AuthKey {
  std::string id;
  std::string secret;
  bool admin = false;  // may cancel every job
};

struct KeyRing {
  std::vector<AuthKey> keys;
  const AuthKey* find(const std::string& id) const;
};

// Throws std::invalid_argument naming the file, the line and what is wrong.
KeyRing read_key_file(const std::string& path);

struct Signature {
  std::string key_id;
  std::int64_t timestamp_us = 0;
  std::array<std::uint8_t, 32> mac{};
};

// Removes a well-formed trailer from the end of `bytes` and returns it (nullopt: unsigned).
std::optional<Signature> split_signature(std::span<const std::uint8_t>& bytes);

// The trailer that signs `payload` on `channel` for `request_id` with `key` at `timestamp_us`.
std::string signature_trailer(const AuthKey& key, const std::string& channel, std::span<const std::uint8_t> payload,
                              const std::string& request_id, std::int64_t timestamp_us);

// The key that signed, or nullptr with `problem` set ("unsigned message", "unknown key 'x'",
// "stale timestamp, 75.2 s from this clock", "bad signature").
const AuthKey* verify_signature(const KeyRing& keys, const std::optional<Signature>& sig, const std::string& channel,
                                std::span<const std::uint8_t> payload, const std::string& request_id,
                                std::int64_t now_us, std::string& problem);

std::int64_t unix_now_us();

}  // namespace cyclopt::wire
