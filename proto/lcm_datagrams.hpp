#pragma once
// LCM's UDP multicast framing (lcm_udpm.c of LCM 1.3.1), parsed defensively. A datagram is
//   LC02 short message:  magic "LC02", seqno (u32), channel (NUL-terminated), payload
//   LC03 fragment:       magic "LC03", seqno (u32), message size (u32), fragment offset (u32),
//                        fragment number (u16), fragment count (u16), [channel NUL in fragment 0],
//                        payload bytes [offset, offset + n) of the message
// all big-endian. liblcm 1.3.1 trusts these fields: a fragment shorter than its 20-byte header
// or with offset + length past 2^32 makes it memcpy outside its buffer (SIGSEGV from one
// datagram). Here every field is range-checked in 64-bit arithmetic, a message in assembly is
// bounded in size, in number per sender and in total, and stale assemblies are dropped.

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace cyclopt::wire {

inline constexpr std::uint32_t kMagicShort = 0x4c433032;  // "LC02"
inline constexpr std::uint32_t kMagicFragment = 0x4c433033;  // "LC03"
inline constexpr std::size_t kFragmentHeaderBytes = 20;
inline constexpr std::size_t kMaxChannelBytes = 63;  // LCM_MAX_CHANNEL_NAME_LENGTH

struct LcmMessage {
  std::string channel;
  std::vector<std::uint8_t> payload;
  std::string source;  // the sending host's address as the receiver saw it ("" where unknown)
};

struct AssemblerLimits {
  std::size_t max_message_bytes = 1 << 20;  // larger fragmented messages are dropped
  std::size_t max_pending_bytes = 8 << 20;  // all assemblies together; the oldest is evicted
  double stale_seconds = 2.0;               // an assembly without a fragment for this long is dropped
};

struct AssemblerCounters {
  long datagrams = 0;
  long messages = 0;   // complete messages delivered
  long malformed = 0;  // datagrams dropped for a bad magic, header, channel or fragment range
  long oversize = 0;   // fragmented messages above max_message_bytes
  long dropped_assemblies = 0;  // incomplete assemblies dropped (stale, evicted, superseded)
};

class DatagramAssembler {
 public:
  explicit DatagramAssembler(AssemblerLimits limits = {}) : limits_(limits) {}

  // Feeds one datagram from `sender` (any key naming the source address) received at `now`
  // (seconds, monotonic); returns the message this datagram completed, if any.
  std::optional<LcmMessage> feed(std::span<const std::uint8_t> datagram, std::uint64_t sender, double now);

  const AssemblerCounters& counters() const { return counters_; }
  std::size_t pending_bytes() const { return pending_bytes_; }

 private:
  struct Assembly {
    std::string channel;
    std::uint32_t seqno = 0;
    std::vector<std::uint8_t> data;
    std::vector<bool> have;  // per fragment number
    std::size_t fragments_left = 0;
    double last_seen = 0.0;
  };
  std::optional<LcmMessage> feed_fragment(std::span<const std::uint8_t> d, std::uint64_t sender, double now);
  void drop(std::map<std::uint64_t, Assembly>::iterator it);
  void expire(double now);

  AssemblerLimits limits_;
  AssemblerCounters counters_;
  std::map<std::uint64_t, Assembly> pending_;  // one message in assembly per sender, as in liblcm
  std::size_t pending_bytes_ = 0;
};

// The channel name at the start of `bytes` (NUL-terminated, 1..63 printable ASCII characters),
// or nullopt.
std::optional<std::string> channel_at(std::span<const std::uint8_t> bytes);

}  // namespace cyclopt::wire
