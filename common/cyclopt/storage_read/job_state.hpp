#pragma once
// Life cycle of a job in the durable queue: queued -> running -> done | incomplete | failed |
// cancelled. A running job interrupted by a crash or a shutdown goes back to queued and resumes.
// done: every required point stored and converged; incomplete: some converged, others did not or
// are missing; failed: an error, a limit hit, or no required point converged (job_outcome.hpp).

#include <optional>
#include <string_view>

namespace cyclopt::storage {

enum class JobState { queued, running, done, failed, cancelled, incomplete };

std::string_view to_string(JobState s);
std::optional<JobState> job_state_from_string(std::string_view s);
inline bool is_final(JobState s) { return s != JobState::queued && s != JobState::running; }

}  // namespace cyclopt::storage
