#include "udpm_receiver.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <stdexcept>
#include <system_error>

namespace cyclopt::wire {

UdpmAddress parse_udpm_url(const std::string& url) {
  const std::string scheme = "udpm://";
  if (url.rfind(scheme, 0) != 0) throw std::invalid_argument("lcm url '" + url + "': not udpm://");
  UdpmAddress a;
  const std::string rest = url.substr(scheme.size());
  const std::size_t q = rest.find('?');
  const std::string host_port = rest.substr(0, q);
  const std::size_t colon = host_port.find(':');
  if (!host_port.empty()) a.group = host_port.substr(0, colon);
  if (colon != std::string::npos) {
    const std::string port = host_port.substr(colon + 1);
    std::size_t used = 0;
    int p = -1;
    try {
      p = std::stoi(port, &used);
    } catch (const std::exception&) {
    }
    if (used != port.size() || p < 1 || p > 65535)
      throw std::invalid_argument("lcm url '" + url + "': port must be 1..65535");
    a.port = static_cast<std::uint16_t>(p);
  }
  in_addr group{};
  if (inet_pton(AF_INET, a.group.c_str(), &group) != 1 || (ntohl(group.s_addr) >> 28) != 0xe)
    throw std::invalid_argument("lcm url '" + url + "': '" + a.group + "' is not an IPv4 multicast group");
  for (std::size_t at = q; at != std::string::npos && at < rest.size();) {
    const std::size_t end = rest.find('&', at + 1);
    const std::string opt = rest.substr(at + 1, end == std::string::npos ? std::string::npos : end - at - 1);
    at = end;
    if (opt.rfind("recv_buf_size=", 0) == 0) {
      try {
        a.recv_buf_size = std::stoi(opt.substr(14));
      } catch (const std::exception&) {
        throw std::invalid_argument("lcm url '" + url + "': recv_buf_size must be a number of bytes");
      }
    }
  }
  return a;
}

namespace {
[[noreturn]] void fail(const char* what) { throw std::system_error(errno, std::generic_category(), what); }
}  // namespace

UdpmReceiver::UdpmReceiver(const UdpmAddress& address, AssemblerLimits limits)
    : assembler_(limits), buffer_(65536) {
  fd_ = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  if (fd_ < 0) fail("udpm receive socket");
  try {
    const int one = 1;
    if (setsockopt(fd_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one) < 0) fail("SO_REUSEADDR");
    if (setsockopt(fd_, SOL_SOCKET, SO_REUSEPORT, &one, sizeof one) < 0) fail("SO_REUSEPORT");
    if (address.recv_buf_size > 0 &&
        setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &address.recv_buf_size, sizeof address.recv_buf_size) < 0)
      fail("SO_RCVBUF");
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_ANY);
    addr.sin_port = htons(address.port);
    if (bind(fd_, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) < 0) fail("bind udpm port");
    ip_mreq mreq{};
    inet_pton(AF_INET, address.group.c_str(), &mreq.imr_multiaddr);
    mreq.imr_interface.s_addr = htonl(INADDR_ANY);
    if (setsockopt(fd_, IPPROTO_IP, IP_ADD_MEMBERSHIP, &mreq, sizeof mreq) < 0) fail("join multicast group");
  } catch (...) {
    close(fd_);
    throw;
  }
}

UdpmReceiver::~UdpmReceiver() { close(fd_); }

int UdpmReceiver::receive(int timeout_ms, const std::function<void(const LcmMessage&)>& on_message) {
  pollfd p{fd_, POLLIN, 0};
  if (poll(&p, 1, timeout_ms) <= 0) return 0;
  int delivered = 0;
  // Bounded per call, so that a flood cannot keep the caller from its other work.
  for (int i = 0; i < 1000; ++i) {
    sockaddr_in from{};
    socklen_t from_len = sizeof from;
    const ssize_t n = recvfrom(fd_, buffer_.data(), buffer_.size(), MSG_TRUNC, reinterpret_cast<sockaddr*>(&from), &from_len);
    if (n < 0) break;  // EAGAIN: drained (or a transient error: poll again next call)
    if (static_cast<std::size_t>(n) > buffer_.size()) continue;  // cannot be LCM (IPv4 UDP carries < 64 KiB)
    const std::uint64_t sender = std::uint64_t{ntohl(from.sin_addr.s_addr)} << 16 | ntohs(from.sin_port);
    const double now = std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
    if (auto m = assembler_.feed({buffer_.data(), static_cast<std::size_t>(n)}, sender, now)) {
      char host[INET_ADDRSTRLEN] = "";
      inet_ntop(AF_INET, &from.sin_addr, host, sizeof host);
      m->source = host;  // the datagram that completed it: an assembly is one sender's (ip:port)
      on_message(*m);
      ++delivered;
    }
  }
  return delivered;
}

}  // namespace cyclopt::wire
