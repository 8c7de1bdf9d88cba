#pragma once
// Where the service's messages go out and come in, for the server and the clients alike.
// Out: liblcm's publish. In: on udpm:// URLs a UdpmReceiver of our own (liblcm 1.3.1's receiver
// can be brought down by a single datagram, lcm_datagrams.hpp), on other providers (memq:// in
// tests, file://) liblcm's raw subscriptions. Either way a handler receives the raw payload, to be
// checked by wire::decode_checked() before anything trusts it. Handlers run inside
// handle_timeout(), on the calling thread; publish() may be called from any thread.

#include "message_auth.hpp"
#include "udpm_receiver.hpp"
#include "wire_check.hpp"

#include <lcm/lcm-cpp.hpp>

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

namespace cyclopt::wire {

inline constexpr const char* kDefaultLcmUrl = "udpm://239.255.76.67:7667?ttl=0";

// The URL liblcm would use for `url`: itself, else $LCM_DEFAULT_URL, else kDefaultLcmUrl.
std::string resolved_lcm_url(const std::string& url);

class MessageBus {
 public:
  using Handler = std::function<void(std::span<const std::uint8_t> payload)>;

  // `url` is the one `lcm` was opened with (resolved_lcm_url()): udpm:// selects the own receiver.
  MessageBus(lcm::LCM& lcm, const std::string& url);
  ~MessageBus();
  MessageBus(const MessageBus&) = delete;
  MessageBus& operator=(const MessageBus&) = delete;

  void subscribe(const std::string& channel, Handler handler);
  // Waits up to timeout_ms and dispatches what arrived; returns the number of messages handled.
  int handle_timeout(int timeout_ms);

  void publish(const std::string& channel, std::span<const std::uint8_t> bytes);
  // Publishes msg, signed with `key` (message_auth.hpp) unless it is null.
  template <class T>
  void publish(const std::string& channel, const T& msg, const AuthKey* key = nullptr) {
    std::string bytes = encode(msg);
    if (key) bytes += signature_trailer(*key, channel, as_bytes(bytes), msg.request_id, unix_now_us());
    publish(channel, as_bytes(bytes));
  }

  // The sending host of the message being dispatched, for its handlers: the IPv4 source address
  // of its datagrams on udpm:// (our own receiver reads it); "" on other providers, since
  // liblcm 1.3.1 passes no source address to its subscribers (lcm_recv_buf_t has none).
  const std::string& current_source() const { return source_; }

  // Datagram statistics of the own receiver (nullptr on non-udpm providers).
  const AssemblerCounters* datagram_counters() const { return receiver_ ? &receiver_->counters() : nullptr; }

 private:
  void on_lcm(const lcm::ReceiveBuffer* rbuf, const std::string& channel);
  void dispatch(const std::string& channel, std::span<const std::uint8_t> payload);

  lcm::LCM& lcm_;
  std::unique_ptr<UdpmReceiver> receiver_;
  std::map<std::string, std::vector<Handler>> handlers_;
  std::vector<lcm::Subscription*> subscriptions_;
  std::mutex publish_mutex_;
  std::string source_;  // of the message being dispatched
};

}  // namespace cyclopt::wire
