#pragma once
// Hostile inputs for the wire fuzz tests (test_wire_fuzz, cyclopt-wire-fuzz): mutations of a
// valid LCM encoding field by field (every string length set to 0, -1, INT_MIN, INT_MAX, huge,
// one off; numbers set to extremes; booleans out of range; invalid UTF-8 and NUL bytes in
// strings; the fingerprint broken; truncation at every byte; bytes appended; random bytes
// flipped), and LC02/LC03 datagrams with lying headers.
#include "lcm_datagrams.hpp"
#include "wire_check.hpp"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace cyclopt::testing {

// Where each field of a well-formed encoding lies: for a string, `at` is its length field.
struct FieldSpan {
  wire::FieldKind kind;
  std::size_t at, size;
};

inline std::int64_t read_be(const std::string& b, std::size_t at, std::size_t n) {
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < n; ++i) v = v << 8 | static_cast<std::uint8_t>(b[at + i]);
  if (n == 4) return static_cast<std::int32_t>(static_cast<std::uint32_t>(v));
  return static_cast<std::int64_t>(v);
}

inline void write_be(std::string& b, std::size_t at, std::size_t n, std::uint64_t v) {
  for (std::size_t i = 0; i < n; ++i) b[at + n - 1 - i] = static_cast<char>(v >> (8 * i) & 0xff);
}

inline std::vector<FieldSpan> field_spans(const std::string& b, std::span<const wire::Field> fields) {
  std::vector<FieldSpan> out;
  std::size_t pos = 8;
  for (const wire::Field& f : fields) {
    std::size_t n = f.kind == wire::FieldKind::int32 ? 4 : f.kind == wire::FieldKind::boolean ? 1 : 8;
    if (f.kind == wire::FieldKind::string) n = 4 + static_cast<std::size_t>(read_be(b, pos, 4));
    out.push_back({f.kind, pos, n});
    pos += n;
  }
  return out;
}

// All structural mutations of `base` plus `random_flips` random multi-byte corruptions.
inline std::vector<std::string> mutations(const std::string& base, std::span<const wire::Field> fields,
                                          std::mt19937_64& rng, int random_flips) {
  std::vector<std::string> out;
  for (std::size_t k = 0; k < base.size(); ++k) out.push_back(base.substr(0, k));  // truncation at every byte
  for (int i = 0; i < 8; ++i)
    for (unsigned x : {0x01u, 0x80u, 0xffu}) {
      std::string m = base;
      m[static_cast<std::size_t>(i)] = static_cast<char>(m[static_cast<std::size_t>(i)] ^ x);
      out.push_back(m);
    }
  for (const std::string& tail : {std::string(1, '\0'), std::string("junk"), std::string(100, '\xff')})
    out.push_back(base + tail);
  for (const FieldSpan& f : field_spans(base, fields)) {
    if (f.kind == wire::FieldKind::string) {
      const std::int64_t len = read_be(base, f.at, 4);
      const std::int64_t left = static_cast<std::int64_t>(base.size() - f.at - 4);
      for (std::int64_t v : {std::int64_t{0}, std::int64_t{-1}, std::int64_t{-2}, std::int64_t{INT_MIN},
                             std::int64_t{INT_MIN} + 1, std::int64_t{INT_MAX}, std::int64_t{1} << 30,
                             std::int64_t{0x7fff0000}, len - 1, len + 1, len + 2, left, left + 1, std::int64_t{1}}) {
        std::string m = base;
        write_be(m, f.at, 4, static_cast<std::uint64_t>(v));
        out.push_back(m);
      }
      // Bad contents, the length adjusted to them.
      for (const std::string& bad : {std::string("\xc0\xaf"), std::string("\xed\xa0\x80"), std::string("\x80"),
                                     std::string("\xff\xfe"), std::string("\xe2\x82"), std::string("a\0b", 3),
                                     std::string("\xf4\x90\x80\x80")}) {
        std::string m = base.substr(0, f.at);
        std::string len_field(4, '\0');
        write_be(len_field, 0, 4, bad.size() + 1);
        m += len_field + bad + std::string(1, '\0') + base.substr(f.at + f.size);
        out.push_back(m);
      }
      std::string unterminated = base;
      unterminated[f.at + f.size - 1] = 'x';
      out.push_back(unterminated);
    } else {
      const std::size_t n = f.size;
      for (std::uint64_t v : {std::uint64_t{0}, ~std::uint64_t{0}, std::uint64_t{1} << (8 * n - 1),
                              (std::uint64_t{1} << (8 * n - 1)) - 1, std::uint64_t{2}, std::uint64_t{0x7ff8000000000000},
                              std::uint64_t{0x7ff0000000000000}, std::uint64_t{0x80}}) {
        std::string m = base;
        write_be(m, f.at, n, n == 8 ? v : v & ((std::uint64_t{1} << (8 * n)) - 1));
        out.push_back(m);
      }
    }
  }
  for (int i = 0; i < random_flips && !base.empty(); ++i) {
    std::string m = base;
    const int flips = 1 + static_cast<int>(rng() % 4);
    for (int k = 0; k < flips; ++k) m[rng() % m.size()] = static_cast<char>(rng());
    out.push_back(m);
  }
  // The fingerprint followed by random bytes.
  for (int i = 0; i < 8; ++i) {
    std::string m = base.substr(0, 8);
    m.resize(8 + rng() % 200);
    for (std::size_t k = 8; k < m.size(); ++k) m[k] = static_cast<char>(rng());
    out.push_back(m);
  }
  return out;
}

// An LCM LC02 datagram carrying `payload` on `channel`.
inline std::string short_datagram(const std::string& channel, const std::string& payload, std::uint32_t seqno) {
  std::string d(8, '\0');
  write_be(d, 0, 4, wire::kMagicShort);
  write_be(d, 4, 4, seqno);
  return d + channel + std::string(1, '\0') + payload;
}

struct FragmentHeader {
  std::uint32_t seqno, size, offset;
  std::uint16_t number, count;
};

inline std::string fragment_datagram(const FragmentHeader& h, const std::string& body) {
  std::string d(wire::kFragmentHeaderBytes, '\0');
  write_be(d, 0, 4, wire::kMagicFragment);
  write_be(d, 4, 4, h.seqno);
  write_be(d, 8, 4, h.size);
  write_be(d, 12, 4, h.offset);
  write_be(d, 16, 2, h.number);
  write_be(d, 18, 2, h.count);
  return d + body;
}

// `payload` on `channel` as liblcm fragments it (fragment 0 carries the channel), `chunk` bytes
// of payload per fragment.
inline std::vector<std::string> fragments(const std::string& channel, const std::string& payload, std::uint32_t seqno,
                                          std::size_t chunk) {
  const auto count = static_cast<std::uint16_t>((payload.size() + chunk - 1) / chunk);
  std::vector<std::string> out;
  for (std::uint16_t i = 0; i < count; ++i) {
    const std::size_t off = i * chunk;
    std::string body = payload.substr(off, chunk);
    if (i == 0) body = channel + std::string(1, '\0') + body;
    out.push_back(fragment_datagram({seqno, static_cast<std::uint32_t>(payload.size()), static_cast<std::uint32_t>(off), i, count}, body));
  }
  return out;
}

// Lying fragment sequences built from a valid fragmentation of payload: every header field of
// one fragment replaced by an extreme or off-by-one value, datagrams shorter than the header,
// channels without NUL or too long, fragments repeated, missing or out of order.
inline std::vector<std::vector<std::string>> lying_fragments(const std::string& channel, const std::string& payload,
                                                             std::uint32_t seqno, std::mt19937_64& rng) {
  const std::size_t chunk = 1 + payload.size() / 3;
  const std::vector<std::string> good = fragments(channel, payload, seqno, chunk);
  std::vector<std::vector<std::string>> out;
  const auto size = static_cast<std::uint32_t>(payload.size());
  for (std::size_t victim = 0; victim < good.size(); ++victim) {
    // header field byte offsets: size 8, offset 12, number 16, count 18
    const std::vector<std::pair<std::size_t, std::vector<std::uint64_t>>> fields = {
        {8, {0, 1, size - 1, size + 1, 0xffffffff, 0x7fffffff, 1u << 28, 1u << 30}},
        {12, {0xffffffff, 0xfffffff0, 0x80000000, size, size - 1, size + 1, 0xffffffff - chunk + 1}},
        {16, {0xffff, good.size(), good.size() + 1, 0}},
        {18, {0, 1, 0xffff, good.size() - 1, good.size() + 1}}};
    for (const auto& [at, values] : fields)
      for (std::uint64_t v : values) {
        std::vector<std::string> seq = good;
        write_be(seq[victim], at, at >= 16 ? 2 : 4, v);
        out.push_back(seq);
      }
    for (std::size_t cut : {std::size_t{8}, std::size_t{12}, std::size_t{19}, std::size_t{20}, std::size_t{21}}) {
      std::vector<std::string> seq = good;
      seq[victim] = seq[victim].substr(0, cut);
      out.push_back(seq);
    }
    std::vector<std::string> missing = good;
    missing.erase(missing.begin() + static_cast<std::ptrdiff_t>(victim));
    out.push_back(missing);
    std::vector<std::string> repeated = good;
    repeated.insert(repeated.begin() + static_cast<std::ptrdiff_t>(victim), good[victim]);
    out.push_back(repeated);
  }
  std::vector<std::string> shuffled = good;
  std::shuffle(shuffled.begin(), shuffled.end(), rng);
  out.push_back(shuffled);
  std::string no_nul = good[0];
  std::memset(no_nul.data() + wire::kFragmentHeaderBytes, 'A', no_nul.size() - wire::kFragmentHeaderBytes);
  out.push_back({no_nul});
  std::string long_channel = fragment_datagram({seqno, size, 0, 0, 2}, std::string(200, 'C') + std::string(1, '\0'));
  out.push_back({long_channel});
  // The datagram that brings down liblcm 1.3.1: fragment 0 whose offset + length wraps past 2^32.
  out.push_back({fragment_datagram({seqno, 100, 0xfffffff0, 0, 2}, channel + std::string(1, '\0') + std::string(20, 'x'))});
  return out;
}

}  // namespace cyclopt::testing
