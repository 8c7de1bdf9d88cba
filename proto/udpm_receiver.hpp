#pragma once
// Receives LCM's UDP multicast datagrams without liblcm (whose 1.3.1 receiver can be brought
// down by one datagram, see lcm_datagrams.hpp): a socket bound like liblcm's (SO_REUSEADDR and
// SO_REUSEPORT on the group's port, so it coexists with LCM programs such as lcm-logger), every
// datagram through a DatagramAssembler. Publishing still goes through liblcm.

#include "lcm_datagrams.hpp"

#include <cstdint>
#include <functional>
#include <string>

namespace cyclopt::wire {

struct UdpmAddress {
  std::string group = "239.255.76.67";
  std::uint16_t port = 7667;
  int recv_buf_size = 0;  // 0: the kernel's default
};

// Parses udpm://GROUP:PORT?opt=value&...; throws std::invalid_argument naming the bad part.
UdpmAddress parse_udpm_url(const std::string& url);

class UdpmReceiver {
 public:
  explicit UdpmReceiver(const UdpmAddress& address, AssemblerLimits limits = {});  // throws std::system_error
  ~UdpmReceiver();
  UdpmReceiver(const UdpmReceiver&) = delete;
  UdpmReceiver& operator=(const UdpmReceiver&) = delete;

  // Waits up to timeout_ms for a datagram, then reads all that are queued and calls on_message
  // for every message they complete. Returns the number of messages delivered.
  int receive(int timeout_ms, const std::function<void(const LcmMessage&)>& on_message);
  const AssemblerCounters& counters() const { return assembler_.counters(); }

 private:
  int fd_ = -1;
  DatagramAssembler assembler_;
  std::vector<std::uint8_t> buffer_;
};

}  // namespace cyclopt::wire
