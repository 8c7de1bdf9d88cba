#include "server.hpp"

namespace cyclopt::server {

Server::Server(const ServerConfig& config, const service::JobKindRegistry& kinds, lcm::LCM& lcm)
    : config_(config),
      lcm_(lcm),
      store_(config_.database),
      recovery_(store_.recover_interrupted()),
      publisher_(lcm_),
      pool_(config_, kinds, store_, publisher_),
      handler_(config_, kinds, store_, publisher_, pool_) {
  handler_.subscribe(lcm_);
}

Server::~Server() { pool_.stop(); }

void Server::serve(const std::atomic<bool>& stop) {
  while (!stop) lcm_.handleTimeout(100);
}

}  // namespace cyclopt::server
