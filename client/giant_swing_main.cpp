// cyclopt-giant-swing: runs one of the giant-swing tasks of seed 000 (ch. 5) with the seed's method
// (piecewise-linear hip torque, multistage Nelder-Mead) and prints the result as JSON.
#include "cyclopt/cli/exit_codes.hpp"
#include "cyclopt/cli/usage_text.hpp"
#include "cyclopt/cli/version.hpp"
#include "cyclopt/io/seed_method_json.hpp"
#include "cyclopt/io/task_spec_json.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

namespace {

constexpr const char* kUsage = R"(usage: cyclopt-giant-swing (--task FILE.json | --preset KIND) [--print-spec]

Optimises the hip torque M_alpha(phi) of the two-segment gymnast on the high bar
for one task of seed 000, chapter 5, and prints the result JSON (end-of-round
values in degrees as in the seed's tables, integrals, support values, model
integrations, wall time).

  --task FILE     a JSON task spec (fields:
                  common/cyclopt/io/task_spec_json.hpp)
  --preset KIND   single_swing, periodic_sequence, accelerating or decelerating
                  with the seed's settings
  --print-spec    print the validated spec (with defaults filled in) and exit
  --version       print the version and git revision
)";

int usage_error(const std::string& message) {
  std::fputs(cyclopt::cli::short_usage("cyclopt-giant-swing", message, kUsage).c_str(), stderr);
  return cyclopt::cli::kExitUsage;
}

int invalid_input(const std::string& message) {
  std::fprintf(stderr, "cyclopt-giant-swing: %s\n", message.c_str());
  return cyclopt::cli::kExitRejected;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace cyclopt::giant_swing;
  using namespace cyclopt::io;
  std::string task_file, preset;
  bool print_spec = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if ((arg == "--task" || arg == "--preset") && i + 1 < argc) {
      (arg == "--task" ? task_file : preset) = argv[++i];
    } else if (arg == "--print-spec") {
      print_spec = true;
    } else if (arg == "--help" || arg == "-h") {
      std::fputs(kUsage, stdout);
      std::fputs(cyclopt::cli::kExitCodeTable, stdout);
      return 0;
    } else if (arg == "--version") {
      std::printf("%s\n", cyclopt::cli::version_text("cyclopt-giant-swing").c_str());
      return 0;
    } else {
      return usage_error("unknown or incomplete argument '" + arg + "'");
    }
  }
  if (task_file.empty() == preset.empty()) return usage_error("give exactly one of --task and --preset");
  nlohmann::json j;
  if (!task_file.empty()) {
    std::ifstream in(task_file);
    if (!in) {
      std::fprintf(stderr, "cyclopt-giant-swing: cannot read %s\n", task_file.c_str());
      return cyclopt::cli::kExitResource;
    }
    try {
      j = nlohmann::json::parse(in);
    } catch (const nlohmann::json::parse_error& e) {
      return invalid_input(task_file + " is not valid JSON: " + e.what());
    }
  } else {
    j = {{"task", preset}};
  }
  TaskSpec spec;
  try {
    spec = task_spec_from_json(j);
  } catch (const cyclopt::SpecError& e) {
    return invalid_input(std::string("invalid task spec: ") + e.what());
  }
  if (print_spec) {
    std::cout << to_json(spec).dump(2) << "\n";
    return 0;
  }
  const SeedMethodResult result = optimise_seed_method(appendix_b_gymnast(), spec);
  std::cout << to_json(result, spec).dump(2) << "\n";
  return 0;
}
