#include "message_bus.hpp"

#include <cstdlib>

namespace cyclopt::wire {

std::string resolved_lcm_url(const std::string& url) {
  if (!url.empty()) return url;
  if (const char* env = std::getenv("LCM_DEFAULT_URL"); env && *env) return env;
  return kDefaultLcmUrl;
}

MessageBus::MessageBus(lcm::LCM& lcm, const std::string& url) : lcm_(lcm) {
  if (url.rfind("udpm://", 0) == 0) receiver_ = std::make_unique<UdpmReceiver>(parse_udpm_url(url));
}

MessageBus::~MessageBus() {
  for (lcm::Subscription* s : subscriptions_) lcm_.unsubscribe(s);
}

void MessageBus::subscribe(const std::string& channel, Handler handler) {
  auto& list = handlers_[channel];
  if (list.empty() && !receiver_) subscriptions_.push_back(lcm_.subscribe(channel, &MessageBus::on_lcm, this));
  list.push_back(std::move(handler));
}

void MessageBus::on_lcm(const lcm::ReceiveBuffer* rbuf, const std::string& channel) {
  dispatch(channel, {static_cast<const std::uint8_t*>(rbuf->data), rbuf->data_size});
}

void MessageBus::dispatch(const std::string& channel, std::span<const std::uint8_t> payload) {
  const auto it = handlers_.find(channel);
  if (it == handlers_.end()) return;
  for (const Handler& h : it->second) h(payload);
}

int MessageBus::handle_timeout(int timeout_ms) {
  if (!receiver_) return lcm_.handleTimeout(timeout_ms) > 0 ? 1 : 0;
  return receiver_->receive(timeout_ms, [&](const LcmMessage& m) {
    source_ = m.source;
    dispatch(m.channel, m.payload);
    source_.clear();
  });
}

void MessageBus::publish(const std::string& channel, std::span<const std::uint8_t> bytes) {
  std::lock_guard lock(publish_mutex_);
  lcm_.publish(channel, bytes.data(), static_cast<unsigned int>(bytes.size()));
}

}  // namespace cyclopt::wire
