// cyclopt-worker: computes one work unit that cycloptd handed out through a spool directory
// (remote/unit_spool.hpp), e.g. as a Slurm batch job. It runs the unit's job kind exactly as a
// server worker thread would (the whole job, or the one work unit of it the unit names:
// JobKind::run_unit) and leaves every point, curve and progress report in the spool.
//
//   cyclopt-worker --unit DIR
//
// Exit codes (cli/exit_codes.hpp): 0 the kind returned (done.json says whether it stopped early
// or failed), 1 bad usage, 4 the unit could not be read or written.
#include "cyclopt/cli/exit_codes.hpp"
#include "cyclopt/cli/usage_text.hpp"
#include "cyclopt/cli/version.hpp"
#include "cyclopt/jobs/builtin_job_kinds.hpp"
#include "cyclopt/service/job_spec.hpp"
#include "cyclopt/service/spec_fields.hpp"
#include "remote/file_job_context.hpp"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

int main(int argc, char** argv) {
  using namespace cyclopt;
  constexpr const char* kUsage = "usage: cyclopt-worker --unit DIR | --version\n";
  if (argc == 2 && std::strcmp(argv[1], "--version") == 0) {
    std::printf("%s\n", cli::version_text("cyclopt-worker").c_str());
    return cli::kExitOk;
  }
  if (argc == 2 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
    std::printf("%s%s", kUsage, cli::kExitCodeTable);
    return cli::kExitOk;
  }
  if (argc != 3 || std::strcmp(argv[1], "--unit") != 0) {
    std::fputs(cli::short_usage("cyclopt-worker", "expected --unit DIR", kUsage).c_str(), stderr);
    return cli::kExitUsage;
  }
  const server::remote::UnitSpool spool(argv[2]);
  try {
    spool.write_started(std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count());
    const server::remote::UnitSpec unit = spool.read_spec();
    const service::JobKindRegistry kinds = jobs::builtin_job_kinds();
    server::remote::FileJobContext ctx(spool, unit, 2.0);
    server::remote::UnitOutcome outcome;
    try {
      // The stored spec, parsed once in this process; one this worker does not accept fails the job.
      service::ValidatedJobSpec spec;
      try {
        spec = service::validate_job_spec_text(unit.spec_json, kinds);
      } catch (const SpecError& e) {
        throw std::runtime_error("spec_json: the job spec is not valid in this cyclopt-worker (" + std::string(e.what()) +
                                 ")");
      }
      if (spec.task != unit.task)
        throw std::runtime_error("unit.json: task '" + unit.task + "' but its spec's task is '" + spec.task + "'");
      if (!unit.unit) {
        spec.run(ctx);
      } else if (!spec.kind->run_unit) {
        throw std::runtime_error("unit.json: work unit '" + unit.unit->id + "' of task '" + spec.task +
                                 "', which does not split into units");
      } else {
        spec.kind->run_unit(*spec.spec, *unit.unit, ctx);
      }
    } catch (const std::exception& e) {
      outcome.error = e.what();
    }
    outcome.stop = ctx.stop_reason();
    spool.write_outcome(outcome);
    std::fprintf(stderr, "cyclopt-worker: job %lld unit %s: %s\n", static_cast<long long>(unit.job_id), argv[2],
                 outcome.error.empty() ? service::to_string(outcome.stop) : outcome.error.c_str());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cyclopt-worker: %s\n", e.what());
    return cli::kExitResource;
  }
}
