#pragma once
// Thread-safe publishing on the server's message bus (workers publish progress while the main
// thread handles requests), with the cost of publishing accounted to the caller. With
// authentication on, a message about a job (progress, done) is signed with its submitter's key,
// an answer with the key of the request it answers.

#include "job_owners.hpp"
#include "message_bus.hpp"

#include <ctime>
#include <string>

namespace cyclopt::server {

class LcmPublisher {
 public:
  // owners: nullptr when messages are not authenticated.
  LcmPublisher(wire::MessageBus& bus, JobOwners* owners) : bus_(bus), owners_(owners) {}

  // Returns the CPU seconds the calling thread spent encoding and sending. (CPU, not wall time:
  // on a loaded machine a multicast send wakes every receiver and the sender is often preempted
  // inside the call, which would charge other processes' work to the job.)
  // A message about msg.job_id, signed with the key that submitted it.
  template <class Message>
  double publish(const std::string& channel, const Message& msg) {
    const double t0 = thread_cpu_seconds();
    bus_.publish(channel, msg, owners_ ? owners_->owner(msg.job_id) : nullptr);
    return thread_cpu_seconds() - t0;
  }
  // An answer, signed with `key` (the requester's; nullptr: unsigned).
  template <class Message>
  void publish_signed(const std::string& channel, const Message& msg, const wire::AuthKey* key) {
    bus_.publish(channel, msg, key);
  }

 private:
  static double thread_cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
  }

  wire::MessageBus& bus_;
  JobOwners* owners_;
};

}  // namespace cyclopt::server
