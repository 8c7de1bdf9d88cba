#pragma once
// Thread-safe publishing on the server's message bus (workers publish progress while the main
// thread handles requests), with the cost of publishing accounted to the caller.

#include "message_bus.hpp"

#include <ctime>
#include <string>

namespace cyclopt::server {

class LcmPublisher {
 public:
  explicit LcmPublisher(wire::MessageBus& bus) : bus_(bus) {}

  // Returns the CPU seconds the calling thread spent encoding and sending. (CPU, not wall time:
  // on a loaded machine a multicast send wakes every receiver and the sender is often preempted
  // inside the call, which would charge other processes' work to the job.)
  template <class Message>
  double publish(const std::string& channel, const Message& msg) {
    const double t0 = thread_cpu_seconds();
    bus_.publish(channel, msg);
    return thread_cpu_seconds() - t0;
  }

 private:
  static double thread_cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
  }

  wire::MessageBus& bus_;
};

}  // namespace cyclopt::server
