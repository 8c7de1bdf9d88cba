#include "slurm_executor.hpp"

#include "command.hpp"
#include "unit_spool.hpp"

#include "cyclopt/service/stored_references.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

namespace cyclopt::server::remote {

namespace {

// How long a worker asked to stop (cancel file) may take before scancel ends it.
constexpr double kCancelGraceSeconds = 5.0;

std::string hex64(std::uint64_t v) {
  char s[17];
  std::snprintf(s, sizeof s, "%016llx", static_cast<unsigned long long>(v));
  return s;
}

// FNV-1a: ids of the same job id in two databases that share a spool differ by request id.
std::uint64_t fnv1a(const std::string& s) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
  return h;
}

std::string trim(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ' || s.back() == '\r')) s.pop_back();
  const auto first = s.find_first_not_of(' ');
  return first == std::string::npos ? "" : s.substr(first);
}

bool active(const std::string& state) {
  for (const char* s : {"PENDING", "RUNNING", "CONFIGURING", "COMPLETING", "SUSPENDED", "REQUEUED", "REQUEUE_HOLD",
                        "REQUEUE_FED", "RESIZING", "SIGNALING", "STAGE_OUT", "STOPPED"})
    if (state == s) return true;
  return false;
}

// The Slurm job of this unit still in the controller's memory (any state), by job name.
struct SlurmJob {
  std::string id;
  std::string state;
};

// "id state" lines of squeue into a map.
std::map<std::string, std::string> parse_states(const std::string& output) {
  std::map<std::string, std::string> states;
  std::istringstream lines(output);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream f(line);
    std::string id, state;
    if (f >> id >> state) states[id] = state;
  }
  return states;
}

// squeue -n succeeds with no lines for a name it does not know, so a failure means the controller
// could not be asked: submitting then could start a second copy of a unit that still runs.
std::optional<SlurmJob> find_by_name(const std::string& name) {
  const CommandResult r = run_command({"squeue", "-h", "-t", "all", "-n", name, "-o", "%i %T"});
  if (r.exit_code != 0)
    throw std::runtime_error("squeue failed (exit " + std::to_string(r.exit_code) + ") looking for Slurm unit " + name +
                             ": cannot tell whether it still runs, so it is not submitted again");
  std::optional<SlurmJob> found;
  for (const auto& [id, state] : parse_states(r.output))
    if (!found || active(state)) found = SlurmJob{id, state};  // an active one wins
  return found;
}

// What squeue says of a set of Slurm jobs: the state of each it knows; a job the controller has
// forgotten (MinJobAge after its end) is absent. nullopt: squeue could not ask the controller
// (down, restarting, unreachable), so nothing is known - not even that a job has ended.
using SlurmStates = std::optional<std::map<std::string, std::string>>;

// One squeue call for all of `ids` (a poll of a job's units costs one call, not one per unit).
// `squeue -j ID` fails for a single id the controller has forgotten (several unknown ids just
// give no lines, so a failure with several is the controller's); the list of this user's jobs then
// tells a forgotten job from an unreachable controller.
SlurmStates slurm_states(const std::vector<std::string>& ids) {
  if (ids.empty()) return std::map<std::string, std::string>{};
  std::string list;
  for (const std::string& id : ids) list += (list.empty() ? "" : ",") + id;
  const CommandResult r = run_command({"squeue", "-h", "-t", "all", "-j", list, "-o", "%i %T"});
  if (r.exit_code == 0) return parse_states(r.output);
  if (ids.size() > 1) return std::nullopt;
  const CommandResult mine = run_command({"squeue", "-h", "-t", "all", "--me", "-o", "%i %T"});
  if (mine.exit_code != 0) return std::nullopt;
  std::map<std::string, std::string> states;
  for (const auto& [id, state] : parse_states(mine.output))
    if (std::find(ids.begin(), ids.end(), id) != ids.end()) states[id] = state;
  return states;
}

// The state of one Slurm job: "" once the controller has forgotten it, nullopt if squeue failed.
std::optional<std::string> slurm_state(const SlurmStates& states, const std::string& id) {
  if (!states) return std::nullopt;
  const auto at = states->find(id);
  return at == states->end() ? "" : at->second;
}

std::optional<std::string> slurm_state(const std::string& id) { return slurm_state(slurm_states({id}), id); }

// Still queued or running, or not known to have ended (squeue failed).
bool may_run(const std::optional<std::string>& state) { return !state || active(*state); }

// One Slurm batch job of cyclopt-worker: the whole job, or one of its work units.
class Unit {
 public:
  Unit(const SlurmOptions& options, const storage::JobRecord& job, service::JobContext& ctx,
       std::optional<service::WorkUnit> unit = std::nullopt)
      : options_(options),
        job_(job),
        ctx_(ctx),
        unit_(std::move(unit)),
        name_("cyclopt-" + std::to_string(job.id) + "-" + hex64(fnv1a(job.request_id)).substr(0, 8) +
              (unit_ ? "-" + unit_->id : "")),
        spool_(std::filesystem::path(options.spool) / name_) {}

  // Re-attaches to the Slurm job still queued or running from before a server restart, takes the
  // result of one that ended while the server was down, or submits. True: the unit has ended.
  bool start() {
    spool_.create();
    if (const auto existing = find_by_name(name_); existing && active(existing->state)) {
      slurm_id_ = existing->id;
      std::fprintf(stderr, "cycloptd: job %lld: %s re-attached to Slurm job %s (%s)\n", static_cast<long long>(job_.id),
                   name_.c_str(), slurm_id_.c_str(), existing->state.c_str());
      return false;
    }
    ingest();
    if (const auto outcome = spool_.read_outcome()) return finish(*outcome);
    submit();
    return false;
  }

  // The unit's progress no longer counts (JobContext::unit_ended); nothing for a whole job.
  void ended() {
    if (unit_) ctx_.unit_ended(unit_->id);
  }

  // One look at the unit, whose Slurm job was in `state` ("" if the controller no longer knows
  // it, nullopt if squeue could not say): ingests what it wrote, forwards its progress, stops it
  // when the job stops, resubmits it when it left the queue without a result. True: the unit has
  // ended (or the server is shutting down and leaves it running, re-attached at the next start).
  bool poll(const std::optional<std::string>& state) {
    ingest();
    if (const auto p = spool_.read_progress()) ctx_.report_progress(*p);
    const service::StopReason stop = ctx_.stop_reason();
    if (stop == service::StopReason::shutdown) return true;
    if (stop != service::StopReason::none) return stop_unit();
    if (!state) {  // the worker may still run: its result counts, nothing is resubmitted
      if (const auto outcome = spool_.read_outcome()) return finish(*outcome);
      return false;
    }
    if (active(*state)) return false;
    ingest();
    if (const auto outcome = spool_.read_outcome()) return finish(*outcome);
    if (submissions_ >= options_.max_submissions)
      throw std::runtime_error("Slurm unit " + name_ + " (Slurm job " + slurm_id_ + ") ended " +
                               (state->empty() ? "with an unknown state" : *state) + " without a result after " +
                               std::to_string(submissions_) + " submission(s)");
    std::fprintf(stderr, "cycloptd: job %lld: Slurm job %s ended %s without a result; resubmitting\n",
                 static_cast<long long>(job_.id), slurm_id_.c_str(), state->c_str());
    submit();
    return false;
  }

  const std::string& slurm_id() const { return slurm_id_; }

  // Asks the worker to stop, gives it a grace period, then scancel. True (the unit has ended).
  bool stop_unit() {
    spool_.request_cancel();
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(kCancelGraceSeconds);
    while (std::chrono::steady_clock::now() < deadline && may_run(slurm_state(slurm_id_)))
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    if (may_run(slurm_state(slurm_id_))) run_command({"scancel", slurm_id_});
    ingest();
    return true;
  }

 private:
  void submit() {
    UnitSpec spec;
    spec.job_id = job_.id;
    spec.task = job_.task;
    spec.spec_json = service::runnable_spec_text(job_);  // the worker has no database to resolve a stored start
    spec.limits = ctx_.limits();
    spec.run_seconds_before = job_.run_seconds;
    spec.submitted_at = std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
    spec.unit = unit_;
    spool_.write_spec(spec);
    spool_.write_stored_keys(ctx_.already_stored_points());
    spool_.write_checkpoints(ctx_.stored_checkpoints());
    spool_.clear_run_state();
    const double remaining = std::max(1.0, spec.limits.max_wall_seconds - spec.run_seconds_before);
    int minutes = static_cast<int>(std::ceil(remaining / 60.0)) + 1;
    if (options_.time_limit_minutes > 0) minutes = std::min(minutes, options_.time_limit_minutes);
    std::vector<std::string> argv{"sbatch",
                                  "--parsable",
                                  "--job-name=" + name_,
                                  "--output=" + (spool_.dir() / "slurm-%j.out").string(),
                                  "--cpus-per-task=" + std::to_string(options_.cpus_per_unit),
                                  "--time=" + std::to_string(minutes),
                                  "--export=ALL"};
    if (!options_.partition.empty()) argv.push_back("--partition=" + options_.partition);
    if (!options_.account.empty()) argv.push_back("--account=" + options_.account);
    argv.push_back("--wrap=exec '" + options_.worker + "' --unit '" + spool_.dir().string() + "'");
    const CommandResult r = run_command(argv);
    const std::string id = trim(r.output.substr(0, r.output.find(';')));
    if (r.exit_code != 0 || id.empty())
      throw std::runtime_error("sbatch failed for Slurm unit " + name_ + " (exit " + std::to_string(r.exit_code) + ")");
    slurm_id_ = id;
    ++submissions_;
  }

  // Events are ingested in order; a re-read from 0 after a restart changes nothing (keyed).
  void ingest() {
    for (auto& [n, e] : spool_.read_events(next_event_)) {
      switch (e.type) {
        case UnitEvent::Type::announce: ctx_.announce(e.points_total); break;
        case UnitEvent::Type::curve: ctx_.add_curve(e.curve_index, e.curve_name, e.parameter_name); break;
        case UnitEvent::Type::point: ctx_.store_point(e.point); break;
        case UnitEvent::Type::checkpoint: ctx_.store_checkpoint(e.checkpoint_key, e.checkpoint_value); break;
      }
      next_event_ = n + 1;
    }
  }

  bool finish(const UnitOutcome& outcome) {
    if (!outcome.error.empty()) throw std::runtime_error(unit_ ? "work unit " + unit_->id + ": " + outcome.error : outcome.error);
    return true;
  }

  const SlurmOptions& options_;
  const storage::JobRecord& job_;
  service::JobContext& ctx_;
  std::optional<service::WorkUnit> unit_;
  std::string name_;
  UnitSpool spool_;
  std::string slurm_id_;
  int submissions_ = 0;
  int next_event_ = 0;
};

// Starts the units and polls them until each has ended. When one fails for good, the others
// are stopped and its failure is rethrown (the failed one has already left the queue).
void run_to_end(const std::vector<Unit*>& units, double poll_seconds, std::int64_t job_id) {
  std::vector<bool> ended(units.size(), false);
  bool controller_lost = false;
  std::size_t at = 0;  // the unit being started or polled
  try {
    for (at = 0; at < units.size(); ++at)
      if ((ended[at] = units[at]->start())) units[at]->ended();
    while (std::find(ended.begin(), ended.end(), false) != ended.end()) {
      std::this_thread::sleep_for(std::chrono::duration<double>(poll_seconds));
      std::vector<std::string> ids;
      for (std::size_t i = 0; i < units.size(); ++i)
        if (!ended[i]) ids.push_back(units[i]->slurm_id());
      const SlurmStates states = slurm_states(ids);
      if (states.has_value() == controller_lost) {  // log the start and the end of an outage once
        controller_lost = !controller_lost;
        std::fprintf(stderr, "cycloptd: job %lld: %s\n", static_cast<long long>(job_id),
                     controller_lost ? "squeue cannot reach the Slurm controller; waiting for it (units keep running)"
                                     : "squeue answers again");
      }
      for (at = 0; at < units.size(); ++at)
        if (!ended[at] && (ended[at] = units[at]->poll(slurm_state(states, units[at]->slurm_id())))) units[at]->ended();
    }
  } catch (...) {
    if (at < units.size()) ended[at] = true;  // the unit that threw has ended
    for (std::size_t i = 0; i < units.size(); ++i)
      if (!ended[i]) try {
          units[i]->stop_unit();
        } catch (const std::exception& e) {
          std::fprintf(stderr, "cycloptd: job %lld: could not stop a unit: %s\n", static_cast<long long>(job_id), e.what());
        }
    throw;
  }
}

}  // namespace

SlurmExecutor::SlurmExecutor(SlurmOptions options) : options_(std::move(options)) {
  if (options_.spool.empty()) throw std::invalid_argument("slurm.spool: a directory every node sees is required");
  if (run_command({"sinfo", "-h", "-o", "%P"}).exit_code != 0)
    throw std::runtime_error("executor slurm: sinfo cannot reach a Slurm controller (is Slurm installed and SLURM_CONF set?)");
  if (!std::filesystem::exists(options_.worker))
    throw std::runtime_error("slurm.worker: no program at '" + options_.worker + "'");
  std::filesystem::create_directories(options_.spool);
  options_.spool = std::filesystem::absolute(options_.spool).string();
}

void SlurmExecutor::run(const storage::JobRecord& job, const service::ValidatedJobSpec& spec, service::JobContext& ctx) const {
  if (spec.kind->run_unit) return spec.run(ctx);  // the job runs here; its units come back through run_units
  Unit unit(options_, job, ctx);
  run_to_end({&unit}, options_.poll_seconds, job.id);
}

void SlurmExecutor::run_units(const storage::JobRecord& job, const std::vector<service::WorkUnit>& units,
                              const service::UnitRun&, service::JobContext& ctx) const {
  std::vector<std::unique_ptr<service::UnitJobContext>> views;
  std::vector<std::unique_ptr<Unit>> running;
  std::vector<Unit*> all;
  for (const service::WorkUnit& u : units) {
    views.push_back(std::make_unique<service::UnitJobContext>(ctx, u));
    running.push_back(std::make_unique<Unit>(options_, job, *views.back(), u));
    all.push_back(running.back().get());
  }
  run_to_end(all, options_.poll_seconds, job.id);
}

}  // namespace cyclopt::server::remote
