#pragma once
// Received LCM encodings are checked here before the lcm-gen decoder sees them: that decoder
// trusts length fields (a string length of 0 or less makes it call assign(p, len - 1): an
// exception for 0 and -1, a read far past the buffer for INT_MIN). decode_checked() walks the
// bytes against the type's generated layout first: the fingerprint, every string length within
// [1, bytes left] and at most kMaxStringBytes, each string NUL-terminated without an inner NUL
// and valid UTF-8, booleans 0 or 1, no bytes after the last field. Only then is T decoded.

#include "cyclopt_lcm_layouts.hpp"
#include "wire_layout.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace cyclopt::wire {

inline constexpr std::size_t kMaxStringBytes = 1 << 20;

// The problem with `bytes` as an encoding of the type `type_name` (fingerprint, fields), naming
// the field and byte offset, or "" if it is well-formed.
std::string encoding_problem(std::span<const std::uint8_t> bytes, std::int64_t fingerprint,
                             std::span<const Field> fields, const char* type_name);

// True iff `text` is valid UTF-8 (no overlong forms, surrogates or code points above U+10FFFF).
bool is_utf8(std::string_view text);

// Decodes T from bytes, or returns nullopt with `problem` set.
template <class T>
std::optional<T> decode_checked(std::span<const std::uint8_t> bytes, std::string& problem) {
  problem = encoding_problem(bytes, T::getHash(), LcmLayout<T>::fields, LcmLayout<T>::name);
  if (!problem.empty()) return std::nullopt;
  T msg;
  if (msg.decode(bytes.data(), 0, static_cast<int>(bytes.size())) != static_cast<int>(bytes.size())) {
    problem = std::string("not a well-formed ") + LcmLayout<T>::name;
    return std::nullopt;
  }
  return msg;
}

template <class T>
std::string encode(const T& msg) {
  std::string out(static_cast<std::size_t>(msg.getEncodedSize()), '\0');
  msg.encode(out.data(), 0, static_cast<int>(out.size()));
  return out;
}

inline std::span<const std::uint8_t> as_bytes(std::string_view s) {
  return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

}  // namespace cyclopt::wire
