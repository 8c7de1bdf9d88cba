#pragma once
// Thread-safe publishing on the server's LCM instance (workers publish progress while the main
// thread handles requests), with the wall time spent publishing accounted to the caller.

#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <mutex>
#include <string>

namespace cyclopt::server {

class LcmPublisher {
 public:
  explicit LcmPublisher(lcm::LCM& lcm) : lcm_(lcm) {}

  // Returns the seconds spent encoding and sending.
  template <class Message>
  double publish(const std::string& channel, const Message& msg) {
    const auto t0 = std::chrono::steady_clock::now();
    {
      std::lock_guard lock(mutex_);
      lcm_.publish(channel, &msg);
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

 private:
  lcm::LCM& lcm_;
  std::mutex mutex_;
};

}  // namespace cyclopt::server
