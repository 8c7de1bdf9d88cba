#include "cyclopt/service/job_kind.hpp"

#include <stdexcept>

namespace cyclopt::service {

const char* to_string(StopReason r) {
  switch (r) {
    case StopReason::none: return "none";
    case StopReason::cancelled: return "cancelled";
    case StopReason::time_limit: return "time limit";
    case StopReason::iteration_limit: return "iteration limit";
    case StopReason::shutdown: return "shutdown";
  }
  return "?";
}

void JobKindRegistry::add(JobKind kind) {
  const std::string task = kind.task;
  if (!kind.resolve) throw std::logic_error("job kind '" + task + "' has no resolve (job_kind.hpp)");
  if (!kinds_.emplace(task, std::move(kind)).second) throw std::logic_error("job kind '" + task + "' registered twice");
}

const JobKind* JobKindRegistry::find(const std::string& task) const {
  const auto it = kinds_.find(task);
  return it == kinds_.end() ? nullptr : &it->second;
}

std::vector<std::string> JobKindRegistry::tasks() const {
  std::vector<std::string> out;
  for (const auto& [task, kind] : kinds_) out.push_back(task);
  return out;
}

}  // namespace cyclopt::service
