#include "cyclopt/storage_read/job_state.hpp"

#include <array>

namespace cyclopt::storage {

namespace {
constexpr std::array<std::string_view, 6> kNames = {"queued", "running", "done", "failed", "cancelled", "incomplete"};
}

std::string_view to_string(JobState s) { return kNames[static_cast<std::size_t>(s)]; }

std::optional<JobState> job_state_from_string(std::string_view s) {
  for (std::size_t i = 0; i < kNames.size(); ++i)
    if (kNames[i] == s) return static_cast<JobState>(i);
  return std::nullopt;
}

}  // namespace cyclopt::storage
