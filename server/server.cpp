#include "server.hpp"

#include "remote/slurm_executor.hpp"

namespace cyclopt::server {

namespace {

std::unique_ptr<JobExecutor> make_executor(const ServerConfig& config) {
  if (config.executor == "slurm") return std::make_unique<remote::SlurmExecutor>(config.slurm);
  return std::make_unique<LocalExecutor>(effective_workers(config));
}

}  // namespace

Server::Server(const ServerConfig& config, const service::JobKindRegistry& kinds, lcm::LCM& lcm)
    : config_(config),
      bus_(lcm, config_.lcm_url),
      keys_(config_.auth_secret_file.empty() ? std::nullopt
                                             : std::optional(wire::read_key_file(config_.auth_secret_file))),
      store_(config_.database),
      recovery_(store_.recover_interrupted()),
      owners_(keys_ ? std::optional<JobOwners>(std::in_place, *keys_, store_) : std::nullopt),
      publisher_(bus_, owners_ ? &*owners_ : nullptr),
      executor_(make_executor(config_)),
      pool_(config_, kinds, *executor_, store_, publisher_),
      handler_(config_, kinds, store_, publisher_, pool_, keys_ ? &*keys_ : nullptr, owners_ ? &*owners_ : nullptr) {
  handler_.subscribe(bus_);
}

Server::~Server() { pool_.stop(); }

void Server::serve(const std::atomic<bool>& stop) {
  while (!stop) bus_.handle_timeout(100);
}

}  // namespace cyclopt::server
