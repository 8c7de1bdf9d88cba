#include "server.hpp"

namespace cyclopt::server {

Server::Server(const ServerConfig& config, const service::JobKindRegistry& kinds, lcm::LCM& lcm)
    : config_(config),
      bus_(lcm, config_.lcm_url),
      store_(config_.database),
      recovery_(store_.recover_interrupted()),
      publisher_(bus_),
      pool_(config_, kinds, store_, publisher_),
      handler_(kinds, store_, publisher_, pool_) {
  handler_.subscribe(bus_);
}

Server::~Server() { pool_.stop(); }

void Server::serve(const std::atomic<bool>& stop) {
  while (!stop) bus_.handle_timeout(100);
}

}  // namespace cyclopt::server
