#pragma once
// Life cycle of a job in the durable queue: queued -> running -> done | failed | cancelled.
// A running job interrupted by a crash or a shutdown goes back to queued and resumes.

#include <optional>
#include <string_view>

namespace cyclopt::storage {

enum class JobState { queued, running, done, failed, cancelled };

std::string_view to_string(JobState s);
std::optional<JobState> job_state_from_string(std::string_view s);
inline bool is_final(JobState s) { return s == JobState::done || s == JobState::failed || s == JobState::cancelled; }

}  // namespace cyclopt::storage
