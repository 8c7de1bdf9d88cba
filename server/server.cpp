#include "server.hpp"

#include "remote/slurm_executor.hpp"

namespace cyclopt::server {

namespace {

std::unique_ptr<JobExecutor> make_executor(const ServerConfig& config, const service::JobKindRegistry& kinds) {
  if (config.executor == "slurm") return std::make_unique<remote::SlurmExecutor>(config.slurm);
  return std::make_unique<LocalExecutor>(kinds);
}

}  // namespace

Server::Server(const ServerConfig& config, const service::JobKindRegistry& kinds, lcm::LCM& lcm)
    : config_(config),
      lcm_(lcm),
      store_(config_.database),
      recovery_(store_.recover_interrupted()),
      publisher_(lcm_),
      executor_(make_executor(config_, kinds)),
      pool_(config_, *executor_, store_, publisher_),
      handler_(config_, kinds, store_, publisher_, pool_) {
  handler_.subscribe(lcm_);
}

Server::~Server() { pool_.stop(); }

void Server::serve(const std::atomic<bool>& stop) {
  while (!stop) lcm_.handleTimeout(100);
}

}  // namespace cyclopt::server
