// cyclopt: command-line client of the cyclopt job server (see kUsage).
#include "cyclopt/cli/closest_name.hpp"
#include "cyclopt/cli/exit_codes.hpp"
#include "cyclopt/cli/usage_text.hpp"
#include "cyclopt/cli/version.hpp"
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/foot_fit/ankle_track.hpp"
#include "cyclopt/foot_fit/gait_trial_file.hpp"
#include "cyclopt/giant_swing/model.hpp"
#include "cyclopt/io/foot_fit_json.hpp"
#include "cyclopt/plot/foot_comparison_figures.hpp"
#include "cyclopt/plot/foot_design_figures.hpp"
#include "cyclopt/plot/foot_fit_figures.hpp"
#include "cyclopt/plot/giant_swing_stroboscope.hpp"
#include "cyclopt/plot/job_report.hpp"
#include "cyclopt/plot/pdf_report.hpp"
#include "cyclopt/plot/rich_text.hpp"
#include "cyclopt/plot/sensitivity_figures.hpp"
#include "cyclopt/plot/walker_figures.hpp"
#include "cyclopt/records/foot_comparison_records.hpp"
#include "cyclopt/records/foot_design_records.hpp"
#include "cyclopt/io/foot_spec_json.hpp"
#include "cyclopt/service/common_job_fields.hpp"
#include "cyclopt/service/job_schema.hpp"
#include "cyclopt/service/spec_fields.hpp"
#include "cyclopt/service/stored_references.hpp"
#include "cyclopt/storage_read/result_queries.hpp"
#include "cyclopt_channels.hpp"
#include "fleet_table.hpp"
#include "point_table.hpp"
#include "progress_line.hpp"
#include "row_table.hpp"
#include "result_source.hpp"
#include "service_client.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <sys/ioctl.h>
#include <unistd.h>

namespace {

constexpr const char* kUsage = R"(usage: cyclopt [--lcm-url URL] [--timeout S] COMMAND [ARGS]

Client of the cycloptd job server. Remote commands talk LCM (default URL: LCM's,
i.e. LCM_DEFAULT_URL or UDP multicast); status, list, query, export, plot and
report read a results database file directly (read-only) when given --db FILE.

  submit --spec FILE.json [--request-id ID] [--watch]
  submit --foot FILE.json|PRESET --sweep PARAM --values LO:STEP:HI
         [--point-delay-ms N] [--name TEXT] [--request-id ID] [--watch]
  submit --foot FILE.json|PRESET --speeds LO:STEP:HI [--task TASK]
         [--name TEXT] ...
  submit --task foot_comparison --speeds LO:STEP:HI [--feet PRESET,PRESET,...]
         [--reference PRESET] [--starts N] ...
  submit --task foot_fit --trials FILE.trc|FILE.csv,... [--name TEXT] ...
  submit --task foot_design [--foot FILE.json|PRESET]
         [--densities LIST|LO:STEP:HI] [--design-speed V]
         [--speeds LO:STEP:HI] [--starts N] [--sweep-starts N]
         [--foot-scale S] ...
  submit --task sensitivity --foot FILE.json|PRESET --speed V
         [--parameters P,P,...]
         [--relative-range R] [--steps N] ...
                     queue a job (spec: cyclopt schema); --sweep builds a
                     foot_sweep spec, --speeds a walker job of TASK (default
                     sweep); foot_comparison sweeps --feet (default: the 16 of
                     seed 001 section 9.2) and --reference (default point) with
                     --starts starts per seed speed; foot_fit fits HM and HMT
                     feet to the trials' ankle tracks (markers LMAL and MMAL, z
                     up; other layouts: cyclopt-foot fit --job-spec FILE);
                     foot_design designs a foot per density from --foot (default
                     P2-shoes-left-HMT) with --starts design starts at
                     --design-speed (seed 001 section 10.2; defaults 10:10:70
                     kg/m^2, 20 starts, 2.3 m/s of 0.3:0.1:2.3); sensitivity
                     optimises at --speed and compares d f_mech / d p from the
                     KKT point with a +-R continuation of each parameter (seed
                     001 section 10.1; defaults: every parameter, R 0.1, 5 steps
                     each way). Resent every 0.5 s until the server answers
                     (same request id, so never queued twice). Prints the job
                     id.
  watch JOB          live progress bar until the job ends (--watch-timeout S,
                     default 3600)
  status JOB         one job's state, counts, timings and last progress (times
                     ISO 8601, local)
  list [--state S]   jobs, one line each: id, name, kind, foot, state, progress,
                     best objective, run time, submitted/started/finished (ISO
                     8601, local); fits the terminal (default 120 columns);
                     --wide every column (request ids, raw numbers). S: queued,
                     running, done, incomplete, failed, cancelled
  top [--state S] [--interval S] [--once]
                     every job live, one line each, refreshed in place every S s
                     (default 2; a log gets the table again each time; --once:
                     print once and exit); fits the terminal (default 80
                     columns) by dropping columns from the right, never state,
                     progress or best objective (docs/watching-jobs.md)
  query JOB [--what solutions|events|curves|trajectories]
                     [--wide | --csv | --json]
                     a job's solved points (default): for walker jobs one line
                     per point (speed, f_mech, step length, period, cadence,
                     Floquet multiplier, impact loss, status, curve); for a
                     foot_design job one line per density (its design, masses,
                     active bounds, mean f_mech, savings); for a sensitivity job
                     one line per parameter (KKT df/dp, relative, Delta f
                     predicted and by continuation at both ends, verdict);
                     --wide / --csv every scalar, --json everything
  export JOB [--out FILE]
                     everything about a job as JSON: spec, events, curves,
                     points, trajectories
  cancel JOB         cancel a queued or running job
  plot KIND (--job JOB ... | --from FILE.json ...) [--speed V] [--out DIR]
                     write DIR/NAME.png and DIR/NAME.svg (default DIR: .) for
                     walker jobs (from the server, --db FILE, or files `export`
                     wrote; several jobs give one curve each). KIND:
                     cost-of-transport (Fig. 9.19a), torques (9.4), step-length
                     (9.6a), floquet (9.6b), impact-loss (9.5b), stroboscope
                     (9.2; gait nearest --speed, first job), foot (3.5a), all;
                     foot-comparison (a foot_comparison job: f_mech of every
                     foot with the best envelope, Fig. 9.19a, and the foot
                     outlines, Fig. 9.8); foot-fit (a foot_fit job: measured
                     against model ankle and the fitted outline per converged
                     fit, Fig. 4.3/4.4); foot-design (a foot_design job: the
                     designs over the start foot, Fig. 10.5/10.6, f_mech per
                     density with the start foot and point feet, Fig. 10.7, the
                     best design's gait, Fig. 10.4); sensitivity (a sensitivity
                     job: Delta f_mech over the relative change of each
                     parameter, continuation and KKT tangent, Fig. 10.1); or
                     giant-swing --result FILE (a cyclopt-giant-swing result,
                     seed 000 Fig. 5.5)
  report JOB [--out FILE.html|FILE.pdf] [--speed V]
                     one self-contained HTML page: provenance (version, build,
                     seeds, dates, resolved and submitted spec), solved points
                     (per density for a foot_design job), solver diagnostics per
                     stored point, all figures; --speed: the gait shown within
                     its step (default: the middle speed); FILE.pdf: the same as
                     a PDF (figures as vector pages, no animations) (default
                     FILE: jobJOB.html)
  schema [FILE]      print the job spec's JSON schema, every task's rules
                     included (for an editor or a validator of your own), or
                     FILE: foot.schema.json or giant_swing_task.schema.json, to
                     which it refers

Output of status, list, query: aligned table (times in ISO 8601: query's UTC,
list's and status' local), or --wide / --csv / --json (Unix seconds).
Options: --lcm-url URL, --timeout S (answer timeout, default 10), --db FILE,
--key-file FILE (sign requests and believe only answers signed with this key;
default $CYCLOPT_KEY_FILE; docs/service.md, Authentication), --version.
A spec is checked locally (JSON, then the server's own validation) before it is
sent.
)";

namespace cli = cyclopt::cli;
constexpr int kOk = cli::kExitOk, kRejected = cli::kExitRejected, kNoAnswer = cli::kExitNoAnswer;

const std::vector<std::string> kCommands = {"submit", "watch", "status", "list", "top", "query", "export", "cancel", "plot", "report", "schema"};

struct Options {
  std::string command;
  std::vector<std::string> positional;
  std::string lcm_url, key_file, db, spec_file, foot, sweep, values, speeds, task = "sweep", name, request_id, state, out,
      what = "solutions", result, feet, reference, trials, densities, parameters;
  std::vector<std::int64_t> jobs;
  std::vector<std::string> from;
  double timeout = 10.0, watch_timeout = 3600.0, speed = std::nan(""), design_speed = std::nan(""), foot_scale = std::nan(""),
         relative_range = std::nan("");
  int point_delay_ms = -1, starts = -1, sweep_starts = -1, steps = -1;
  double interval = 2.0;  // top's refresh
  bool watch = false, once = false;
  cyclopt::client::RowFormat format = cyclopt::client::RowFormat::table;
};

struct UsageError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};
// A spec file or value that is not what the server would accept: found before sending (exit 2).
struct LocalRejection : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// A positive integer job id; `what` names where it came from.
std::int64_t job_id(const std::string& what, const std::string& text) {
  try {
    std::size_t used = 0;
    const long long id = std::stoll(text, &used);
    if (used == text.size() && id > 0) return id;
  } catch (const std::exception&) {
  }
  throw UsageError(what + " must be a positive integer job id, got '" + text + "'");
}

// Every option parse_args() knows, for "did you mean" on a misspelled one.
const std::vector<std::string> kOptionNames = {
    "--lcm-url", "--key-file", "--timeout", "--watch-timeout", "--db", "--spec", "--foot", "--sweep",
    "--values", "--speeds", "--task", "--feet", "--reference", "--trials", "--densities", "--design-speed", "--starts", "--sweep-starts", "--foot-scale", "--parameters", "--relative-range", "--steps", "--name", "--point-delay-ms", "--request-id", "--state", "--what",
    "--out", "--job", "--from", "--result", "--speed", "--watch", "--json", "--csv", "--wide", "--once", "--interval", "--help", "--version"};

Options parse_args(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) throw UsageError(a + " needs a value");
      return argv[++i];
    };
    auto number = [&](const std::string& text) {
      try {
        return std::stod(text);
      } catch (const std::exception&) {
        throw UsageError(a + ": '" + text + "' is not a number");
      }
    };
    if (a == "--lcm-url") o.lcm_url = next();
    else if (a == "--key-file") o.key_file = next();
    else if (a == "--timeout") o.timeout = number(next());
    else if (a == "--watch-timeout") o.watch_timeout = number(next());
    else if (a == "--db") o.db = next();
    else if (a == "--spec") o.spec_file = next();
    else if (a == "--foot") o.foot = next();
    else if (a == "--sweep") o.sweep = next();
    else if (a == "--values") o.values = next();
    else if (a == "--speeds") o.speeds = next();
    else if (a == "--task") o.task = next();
    else if (a == "--feet") o.feet = next();
    else if (a == "--reference") o.reference = next();
    else if (a == "--trials") o.trials = next();
    else if (a == "--densities") o.densities = next();
    else if (a == "--design-speed") o.design_speed = number(next());
    else if (a == "--starts") o.starts = static_cast<int>(number(next()));
    else if (a == "--sweep-starts") o.sweep_starts = static_cast<int>(number(next()));
    else if (a == "--foot-scale") o.foot_scale = number(next());
    else if (a == "--parameters") o.parameters = next();
    else if (a == "--relative-range") o.relative_range = number(next());
    else if (a == "--steps") o.steps = static_cast<int>(number(next()));
    else if (a == "--name") o.name = next();
    else if (a == "--point-delay-ms") o.point_delay_ms = static_cast<int>(number(next()));
    else if (a == "--request-id") o.request_id = next();
    else if (a == "--state") o.state = next();
    else if (a == "--what") o.what = next();
    else if (a == "--out") o.out = next();
    else if (a == "--job") o.jobs.push_back(job_id(a, next()));
    else if (a == "--from") o.from.push_back(next());
    else if (a == "--result") o.result = next();
    else if (a == "--speed") o.speed = number(next());
    else if (a == "--watch") o.watch = true;
    else if (a == "--once") o.once = true;
    else if (a == "--interval") o.interval = number(next());
    else if (a == "--json") o.format = cyclopt::client::RowFormat::json;
    else if (a == "--csv") o.format = cyclopt::client::RowFormat::csv;
    else if (a == "--wide") o.format = cyclopt::client::RowFormat::wide;
    else if (a.rfind("--", 0) == 0) throw UsageError("unknown option " + a + cli::did_you_mean(a, kOptionNames));
    else if (o.command.empty()) o.command = a;
    else o.positional.push_back(a);
  }
  if (!(o.timeout > 0) || !(o.watch_timeout > 0)) throw UsageError("--timeout and --watch-timeout must be > 0");
  if (!(o.interval >= 0.2)) throw UsageError("--interval must be >= 0.2 s");
  return o;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read '" + path + "'");
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::int64_t job_argument(const Options& o) {
  if (o.positional.size() != 1) throw UsageError(o.command + " needs exactly one JOB id");
  return job_id("JOB", o.positional[0]);
}

// A foot given on the command line: a JSON file's spec or a preset name.
nlohmann::json foot_argument(const std::string& flag, const std::string& foot) {
  std::ifstream file(foot);
  if (!file) return foot;
  nlohmann::json j = nlohmann::json::parse(read_file(foot), nullptr, false);
  if (j.is_discarded()) throw LocalRejection(flag + " " + foot + ": not valid JSON");
  return j;
}

// foot_comparison from flags: --feet (comma-separated), --reference, --starts.
std::string foot_comparison_spec_text(const Options& o) {
  if (o.speeds.empty()) throw UsageError("submit --task foot_comparison needs --speeds LO:STEP:HI");
  if (!o.foot.empty()) throw UsageError("submit --task foot_comparison takes --feet and --reference, not --foot");
  nlohmann::json spec = {{"scene", "walker"}, {"task", "foot_comparison"}, {"speeds", o.speeds}};
  if (!o.feet.empty()) {
    spec["feet"] = nlohmann::json::array();
    std::stringstream ss(o.feet);
    for (std::string foot; std::getline(ss, foot, ',');) spec["feet"].push_back(foot_argument("--feet", foot));
  }
  if (!o.reference.empty()) spec["reference"] = foot_argument("--reference", o.reference);
  if (o.starts > 0) spec["multistart"] = {{"starts", o.starts}};
  if (!o.name.empty()) spec["name"] = o.name;
  return spec.dump();
}

// foot_fit from flags: --trials (comma-separated .trc / CSV files), read here (a malformed file is
// rejected naming file, line and column) and sent as their ankle tracks.
std::string foot_fit_spec_text(const Options& o) {
  if (o.trials.empty()) throw UsageError("submit --task foot_fit needs --trials FILE,FILE,...");
  std::vector<cyclopt::foot_fit::AnkleTrack> tracks;
  std::stringstream ss(o.trials);
  try {
    std::vector<cyclopt::foot_fit::GaitTrial> trials;
    for (std::string file; std::getline(ss, file, ',');) trials.push_back(cyclopt::foot_fit::read_gait_trial(file));
    tracks = cyclopt::foot_fit::stance_tracks(trials);  // complete stances only
    if (tracks.empty()) throw std::runtime_error("no complete stance (see cyclopt-foot fit for the reasons)");
  } catch (const std::exception& e) {
    throw LocalRejection(std::string("--trials ") + e.what() + "; nothing was sent");
  }
  nlohmann::json spec = cyclopt::io::foot_fit_job_spec(tracks);
  if (!o.name.empty()) spec["name"] = o.name;
  const std::string text = spec.dump();
  if (text.size() > cyclopt::channels::kMaxSpecBytes)
    throw LocalRejection("--trials: the spec of these trials is " + std::to_string(text.size()) + " bytes, a job spec may be " +
                         std::to_string(cyclopt::channels::kMaxSpecBytes) +
                         " (about 1000 ankle samples); fit them locally with cyclopt-foot fit");
  return text;
}

// foot_design from flags: --foot (the start foot), --densities ("10:10:70" or "10,30,50"),
// --design-speed, --speeds, --starts (design multistart), --sweep-starts, --foot-scale; the rest defaults
// (service/foot_design_kind.hpp).
std::string foot_design_spec_text(const Options& o) {
  nlohmann::json spec = {{"scene", "walker"}, {"task", "foot_design"}};
  if (!o.foot.empty()) spec["foot"] = foot_argument("--foot", o.foot);
  if (o.densities.find(':') != std::string::npos) {
    spec["densities"] = o.densities;  // "lo:step:hi", read by the server's value_range
  } else if (!o.densities.empty()) {
    spec["densities"] = nlohmann::json::array();
    std::stringstream ss(o.densities);
    for (std::string rho; std::getline(ss, rho, ',');) try {
        spec["densities"].push_back(std::stod(rho));
      } catch (const std::exception&) {
        throw UsageError("--densities: '" + rho + "' is not a number");
      }
  }
  if (std::isfinite(o.design_speed)) spec["design_speed"] = o.design_speed;
  if (!o.speeds.empty()) spec["speeds"] = o.speeds;
  if (o.starts > 0) spec["multistart"] = {{"starts", o.starts}};
  if (o.sweep_starts > 0) spec["sweep_starts"] = o.sweep_starts;
  if (std::isfinite(o.foot_scale)) spec["foot_scale"] = o.foot_scale;
  if (!o.name.empty()) spec["name"] = o.name;
  return spec.dump();
}

// sensitivity from flags: --foot, --speed, --parameters (comma-separated), --relative-range,
// --steps; the rest defaults (service/walker_sensitivity_kind.hpp).
std::string sensitivity_spec_text(const Options& o) {
  if (o.foot.empty() || !std::isfinite(o.speed)) throw UsageError("submit --task sensitivity needs --foot and --speed V");
  nlohmann::json spec = {{"scene", "walker"}, {"task", "sensitivity"}, {"foot", foot_argument("--foot", o.foot)}, {"speed", o.speed}};
  if (!o.parameters.empty()) {
    spec["parameters"] = nlohmann::json::array();
    std::stringstream ss(o.parameters);
    for (std::string name; std::getline(ss, name, ',');) spec["parameters"].push_back(name);
  }
  if (std::isfinite(o.relative_range)) spec["relative_range"] = o.relative_range;
  if (o.steps >= 0) spec["steps"] = o.steps;
  if (!o.name.empty()) spec["name"] = o.name;
  return spec.dump();
}

// The spec text of `submit`: the file's, or a foot_sweep / walker job / foot_comparison /
// foot_fit / foot_design from flags.
std::string spec_text(const Options& o) {
  if (!o.spec_file.empty()) {
    const std::string text = read_file(o.spec_file);
    try {
      return nlohmann::json::parse(text).dump();
    } catch (const nlohmann::json::parse_error& e) {
      throw LocalRejection(o.spec_file + " is not valid JSON (" + e.what() + "); nothing was sent");
    }
  }
  if (o.task == "foot_comparison") return foot_comparison_spec_text(o);
  if (o.task == "foot_fit") return foot_fit_spec_text(o);
  if (o.task == "foot_design") return foot_design_spec_text(o);
  if (o.task == "sensitivity") return sensitivity_spec_text(o);
  if (!o.parameters.empty() || std::isfinite(o.relative_range) || o.steps >= 0)
    throw UsageError("--parameters, --relative-range and --steps need --task sensitivity");
  if (!o.densities.empty() || std::isfinite(o.design_speed) || o.sweep_starts > 0 || std::isfinite(o.foot_scale))
    throw UsageError("--densities, --design-speed, --sweep-starts and --foot-scale need --task foot_design");
  if (!o.trials.empty()) throw UsageError("--trials needs --task foot_fit");
  if (!o.feet.empty() || !o.reference.empty()) throw UsageError("--feet and --reference need --task foot_comparison");
  const bool foot_sweep = !o.sweep.empty() && !o.values.empty();
  if (o.foot.empty() || (!foot_sweep && o.speeds.empty()))
    throw UsageError("submit needs --spec FILE, or --foot with --sweep and --values, or --foot with --speeds");
  nlohmann::json spec = {{"scene", "walker"}, {"task", foot_sweep ? "foot_sweep" : o.task}};
  spec["foot"] = foot_argument("--foot", o.foot);
  if (foot_sweep)
    spec["sweep"] = {{"parameter", o.sweep}, {"values", o.values}};
  else
    spec["speeds"] = o.speeds;
  if (o.point_delay_ms >= 0) spec["point_delay_ms"] = o.point_delay_ms;
  if (o.starts > 0) spec["multistart"] = {{"starts", o.starts}};
  if (!o.name.empty()) spec["name"] = o.name;
  return spec.dump();
}

int exit_for_state(const std::string& state) {
  if (state == "done") return kOk;
  return state == "incomplete" ? cyclopt::cli::kExitIncomplete : kRejected;
}

// Terminal width (COLUMNS, else the terminal's on `stream`, else `fallback`).
std::size_t terminal_width(FILE* stream, std::size_t fallback) {
  if (const char* columns = std::getenv("COLUMNS"); columns && std::atoi(columns) > 20) return std::atoi(columns);
  winsize w{};
  if (ioctl(fileno(stream), TIOCGWINSZ, &w) == 0 && w.ws_col > 20) return w.ws_col;
  return fallback;
}

// Lines of stdout's terminal (LINES, else the terminal's; 0: not known).
std::size_t terminal_height() {
  if (const char* lines = std::getenv("LINES"); lines && std::atoi(lines) > 2) return std::atoi(lines);
  winsize w{};
  if (ioctl(fileno(stdout), TIOCGWINSZ, &w) == 0 && w.ws_row > 2) return w.ws_row;
  return 0;
}

int watch(cyclopt::client::ResultSource& s, const Options& o, std::int64_t job_id) {
  const bool tty = isatty(fileno(stderr));
  const std::size_t width = tty ? terminal_width(stderr, 100) - 1 : 400;
  cyclopt::client::LogThrottle log(std::chrono::seconds(5));
  std::size_t shown = 0;  // characters of the line on the terminal
  auto bar = [&](const cyclopt_lcm::job_progress_t& p) {
    if (!tty && !log.due(p, std::chrono::steady_clock::now())) return;
    const std::string line = cyclopt::client::progress_line(p, width);
    if (tty) {
      std::fprintf(stderr, "\r%s%s", line.c_str(), std::string(shown > line.size() ? shown - line.size() : 0, ' ').c_str());
      shown = line.size();
    } else {
      std::fprintf(stderr, "%s\n", line.c_str());
    }
  };
  const auto done = s.remote().watch(job_id, bar, o.watch_timeout);
  if (tty) std::fputc('\n', stderr);
  if (!done) {
    std::fprintf(stderr, "cyclopt: job %lld did not finish within %.0f s\n", static_cast<long long>(job_id), o.watch_timeout);
    return kNoAnswer;
  }
  std::string converged;
  if (done->points_converged >= 0)
    converged = ", " + std::to_string(done->points_converged) + " of " + std::to_string(done->points_expected) + " converged";
  std::printf("job %lld %s: %d points stored%s, %.3f s (progress publication %.6f s)%s%s\n",
              static_cast<long long>(job_id), done->state.c_str(), done->points_stored, converged.c_str(),
              done->run_seconds, done->publish_seconds, done->error.empty() ? "" : "; ", done->error.c_str());
  return exit_for_state(done->state);
}

// The feet a spec gives as a preset name or a foot spec ("foot", "reference", "feet"), with their fields.
std::vector<std::pair<std::string, nlohmann::json>> given_feet(const nlohmann::json& spec) {
  std::vector<std::pair<std::string, nlohmann::json>> feet;
  const auto given = [](const nlohmann::json& f) { return f.is_string() || (f.is_object() && !f.contains("fit")); };
  for (const char* key : {"foot", "reference"})
    if (spec.contains(key) && given(spec[key])) feet.emplace_back(key, spec[key]);
  if (spec.contains("feet") && spec["feet"].is_array())
    for (std::size_t i = 0; i < spec["feet"].size(); ++i)
      if (given(spec["feet"][i])) feet.emplace_back("feet[" + std::to_string(i) + "]", spec["feet"][i]);
  return feet;
}

// Checked before sending, without the job kinds (the server, which has them, checks the rest): the
// fields every spec shares, the form of references to stored results (resolved by the server,
// which has the database), every foot given by preset or spec, then the job schema
// (service/job_schema.hpp). A bad spec is rejected naming the field even when no server is reachable; a
// misspelled foot preset gets a suggestion.
void validate_locally(const std::string& spec_json) {
  const nlohmann::json spec = nlohmann::json::parse(spec_json);
  try {
    cyclopt::service::parse_common_job_fields(spec);
    cyclopt::service::stored_point_reference(spec);
    cyclopt::service::stored_fit_references(spec);
    for (const auto& [field, foot] : given_feet(spec)) cyclopt::io::foot_value(foot, field);
    cyclopt::service::check_job_schema(spec);
  } catch (const cyclopt::SpecError& e) {
    std::string hint;
    if (e.field().rfind("foot", 0) == 0 && spec.contains("foot") && spec["foot"].is_string()) {
      std::vector<std::string> presets;
      for (const cyclopt::foot::FootPreset& p : cyclopt::foot::foot_presets()) {
        presets.push_back(p.name);
        if (!p.alias.empty()) presets.push_back(p.alias);
      }
      hint = cli::did_you_mean(spec["foot"].get<std::string>(), presets);
    }
    throw LocalRejection("rejected before sending (field " + e.field() + "): " + e.what() + hint);
  }
}

int submit(cyclopt::client::ResultSource& s, const Options& o) {
  const std::string spec = spec_text(o);
  validate_locally(spec);
  const std::string id = o.request_id.empty() ? cyclopt::client::new_request_id() : o.request_id;
  const auto ack = s.remote().submit(id, spec, o.timeout);
  if (!ack) {
    std::fprintf(stderr, "cyclopt: no answer from cycloptd within %.1f s (request %s)\n", o.timeout, id.c_str());
    return kNoAnswer;
  }
  if (!ack->accepted) {
    std::fprintf(stderr, "cyclopt: rejected (field %s): %s\n", ack->field.c_str(), ack->problem.c_str());
    // The server's own failure (its database, say) is no fault of the spec.
    return ack->field == "server" ? cli::kExitResource : kRejected;
  }
  std::printf("job %lld %s (request %s, state %s)\n", static_cast<long long>(ack->job_id),
              ack->duplicate ? "already submitted" : "queued", id.c_str(), ack->state.c_str());
  std::fflush(stdout);
  return o.watch ? watch(s, o, ack->job_id) : kOk;
}

int status(cyclopt::client::ResultSource& s, const Options& o) {
  const auto page = s.fetch(cyclopt::storage::query_for("job", job_argument(o)));
  nlohmann::json job = page.rows.at(0);
  if (o.format != cyclopt::client::RowFormat::table) {
    cyclopt::client::print_rows(std::cout, nlohmann::json::array({job}), o.format);
    return kOk;
  }
  // The job's last recorded progress as one line, times as ISO 8601 (local, with the offset).
  const cyclopt::client::FleetJob f = cyclopt::client::fleet_job(job);
  if (f.state != "queued" && std::isfinite(f.percent)) {
    std::string line = cyclopt::client::percent_text(f.percent, f.percent_lower_bound);
    if (f.state == "running") line += ", ETA " + cyclopt::client::duration_text(f.eta_seconds);
    if (!f.phase.empty()) line += ", " + f.phase;
    if (std::isfinite(f.best_objective)) line += ", best " + std::to_string(f.best_objective);
    if (job["progress_at"].is_number()) line += " (at " + cyclopt::client::local_iso_time(job["progress_at"].get<double>()) + ")";
    job["progress"] = line;
  }
  for (const char* raw : {"progress_percent", "phase", "eta_seconds", "best_objective", "progress_at"}) job.erase(raw);
  for (const auto& [k, v] : job.items()) {
    std::string text = v.is_string() ? v.get<std::string>() : v.dump();
    if (k.size() > 3 && k.compare(k.size() - 3, 3, "_at") == 0) text = v.is_number() ? cyclopt::client::local_iso_time(v.get<double>()) : "-";
    std::printf("%-17s %s\n", k.c_str(), text.c_str());
  }
  return kOk;
}

// The jobs as a table fitting the terminal (120 columns when not a terminal); --wide / --csv /
// --json every column.
int list(cyclopt::client::ResultSource& s, const Options& o) {
  const nlohmann::json rows = s.fetch(cyclopt::storage::query_for("jobs", 0, o.state)).rows;
  if (o.format != cyclopt::client::RowFormat::table) {
    cyclopt::client::print_rows(std::cout, rows, o.format);
    return kOk;
  }
  std::vector<cyclopt::client::FleetJob> jobs;
  for (const nlohmann::json& row : rows) jobs.push_back(cyclopt::client::fleet_job(row));
  for (const std::string& line : cyclopt::client::fleet_table(jobs, cyclopt::client::FleetView::list, terminal_width(stdout, 120)))
    std::printf("%s\n", line.c_str());
  return kOk;
}

// The fleet live (docs/watching-jobs.md): the job list from the server every --interval, the
// progress messages of every job in between. Running and queued jobs first, then the others,
// newest first; on a terminal as many as fit its height, redrawn in place.
int top(cyclopt::client::ResultSource& s, const Options& o) {
  const bool tty = isatty(fileno(stdout));
  std::map<std::int64_t, cyclopt_lcm::job_progress_t> live;  // the last message of each job
  const auto on_progress = [&](const cyclopt_lcm::job_progress_t& p) { live[p.job_id] = p; };
  while (true) {
    std::vector<cyclopt::client::FleetJob> jobs;
    for (const nlohmann::json& row : s.fetch(cyclopt::storage::query_for("jobs", 0, o.state)).rows) {
      jobs.push_back(cyclopt::client::fleet_job(row));
      cyclopt::client::FleetJob& j = jobs.back();
      if (const auto it = live.find(j.id); it != live.end() && j.state == "running") apply_progress(j, it->second);
    }
    // A moment of live messages before the first frame, the interval between frames.
    s.remote().listen([&](const cyclopt_lcm::job_progress_t& p) {
      on_progress(p);
      for (cyclopt::client::FleetJob& j : jobs)
        if (j.id == p.job_id && j.state == "running") apply_progress(j, p);
    }, o.once ? std::min(o.interval, 1.0) : 0.0);
    const auto active = [](const cyclopt::client::FleetJob& j) { return j.state == "running" || j.state == "queued"; };
    std::stable_sort(jobs.begin(), jobs.end(), [&](const auto& a, const auto& b) {
      return active(a) != active(b) ? active(a) : active(a) ? a.id < b.id : a.id > b.id;
    });
    const std::size_t width = terminal_width(stdout, 80), height = tty ? terminal_height() : 0;
    if (height > 0 && jobs.size() + 3 > height) jobs.resize(height - 3);
    std::string frame = tty ? "\x1b[H\x1b[2J" : "";
    char head[96];
    const std::time_t now = std::time(nullptr);
    std::snprintf(head, sizeof head, "cyclopt top  %s  %zu jobs\n", cyclopt::client::local_iso_time(static_cast<double>(now)).c_str(),
                  jobs.size());
    frame += std::string(head).substr(0, width) + (std::string(head).size() > width ? "\n" : "");
    for (const std::string& line : cyclopt::client::fleet_table(jobs, cyclopt::client::FleetView::top, width)) frame += line + "\n";
    std::fputs(frame.c_str(), stdout);
    if (!tty) std::fputc('\n', stdout);
    std::fflush(stdout);
    if (o.once) return kOk;
    s.remote().listen(on_progress, o.interval);
  }
}

int cancel(cyclopt::client::ResultSource& s, const Options& o) {
  const std::int64_t id = job_argument(o);
  const auto ack = s.remote().cancel(id, o.timeout);
  if (!ack) return kNoAnswer;
  if (!ack->accepted) {
    std::fprintf(stderr, "cyclopt: %s\n", ack->problem.c_str());
    return kRejected;
  }
  std::printf("job %lld %s\n", static_cast<long long>(id), ack->state == "cancelled" ? "cancelled" : "cancel requested");
  return kOk;
}

// Everything about a job: the job row with its spec and the rows of every part (kJobParts).
nlohmann::json job_document(cyclopt::client::ResultSource& s, std::int64_t id) {
  nlohmann::json j = s.fetch(cyclopt::storage::query_for("job", id)).rows.at(0);
  for (const char* what : cyclopt::storage::kJobParts) j[what] = s.fetch(cyclopt::storage::query_for(what, id)).rows;
  return j;
}

int export_job(cyclopt::client::ResultSource& s, const Options& o) {
  const std::int64_t id = job_argument(o);
  const nlohmann::json j = job_document(s, id);
  if (o.out.empty()) {
    std::cout << j.dump(2) << "\n";
    return kOk;
  }
  std::ofstream out(o.out);
  out << j.dump(2) << "\n";
  if (!out) throw std::runtime_error("cannot write '" + o.out + "'");
  std::fprintf(stderr, "cyclopt: wrote job %lld to %s\n", static_cast<long long>(id), o.out.c_str());
  return kOk;
}

int plot(cyclopt::client::ResultSource& s, const Options& o) {
  if (o.positional.size() != 1) throw UsageError("plot needs exactly one KIND");
  const std::string& kind = o.positional[0];
  const std::string dir = o.out.empty() ? "." : o.out;
  std::vector<cyclopt::plot::Figure> figures;
  std::vector<std::string> not_drawn;  // what the kind left out, and why
  if (kind == "giant-swing") {
    if (o.result.empty()) throw UsageError("plot giant-swing needs --result FILE (cyclopt-giant-swing output)");
    cyclopt::plot::Scene scene = cyclopt::plot::giant_swing_stroboscope(cyclopt::giant_swing::appendix_b_gymnast(),
                                                                        nlohmann::json::parse(read_file(o.result)));
    const cyclopt::plot::RenderOptions size = cyclopt::plot::fitted_options(scene, 800);
    figures.push_back({"giant_swing_stroboscope", "Giant swing stroboscope (seed 000 Fig. 5.5)", std::move(scene), size});
  } else if (kind == "foot-fit" || kind == "foot-design" || kind == "foot-comparison" || kind == "sensitivity") {
    if (o.jobs.size() + o.from.size() != 1) throw UsageError("plot " + kind + " needs one --job JOB or --from FILE.json");
    const nlohmann::json doc = o.jobs.empty() ? nlohmann::json::parse(read_file(o.from.front())) : job_document(s, o.jobs.front());
    if (kind == "foot-fit") figures = cyclopt::plot::foot_fit_job_figures(doc, &not_drawn);
    else if (kind == "foot-design") figures = cyclopt::plot::foot_design_figures(doc, &not_drawn);
    else if (kind == "sensitivity") figures.push_back(cyclopt::plot::sensitivity_figure(cyclopt::plot::sensitivity_parameters(doc)));
    else figures = cyclopt::plot::foot_comparison_figures(doc);
  } else {
    if (o.jobs.empty() && o.from.empty()) throw UsageError("plot " + kind + " needs --job JOB or --from FILE.json");
    std::vector<cyclopt::plot::WalkerJobResults> jobs;
    for (std::int64_t id : o.jobs) jobs.push_back(cyclopt::plot::walker_job_results(job_document(s, id)));
    for (const std::string& f : o.from) jobs.push_back(cyclopt::plot::walker_job_results(nlohmann::json::parse(read_file(f))));
    if (kind == "all") figures = cyclopt::plot::walker_figures(jobs, o.speed, &not_drawn);
    else figures.push_back(cyclopt::plot::walker_figure(kind, jobs, o.speed));
  }
  for (const std::string& why : not_drawn) std::fprintf(stderr, "cyclopt: not drawn: %s\n", why.c_str());
  if (figures.empty()) throw std::invalid_argument("plot " + kind + ": nothing to draw");
  for (const cyclopt::plot::Figure& f : figures) {
    const std::vector<std::string> paths = cyclopt::plot::write_figure(f, dir);
    std::printf("%s: %s %s\n", cyclopt::plot::rich_text_plain(f.caption).c_str(), paths[0].c_str(), paths[1].c_str());
  }
  return kOk;
}

int report(cyclopt::client::ResultSource& s, const Options& o) {
  const std::int64_t id = job_argument(o);
  const std::string path = o.out.empty() ? "job" + std::to_string(id) + ".html" : o.out;
  const nlohmann::json doc = job_document(s, id);
  const cyclopt::plot::Report r = cyclopt::plot::job_report(doc, o.speed);
  const bool pdf = path.size() > 4 && path.compare(path.size() - 4, 4, ".pdf") == 0;
  if (pdf) cyclopt::plot::write_pdf(r, path);
  else cyclopt::plot::write_html(r, path);
  std::printf("report of job %lld: %s\n", static_cast<long long>(id), path.c_str());
  return kOk;
}

int run(const Options& o) {
  if (o.command == "schema") {
    const std::string file = o.positional.empty() ? "job.schema.json" : o.positional.front();
    const nlohmann::json schema = file == "job.schema.json" ? cyclopt::service::job_schema().schema()
                                                            : nlohmann::json::parse(cyclopt::service::job_schema_file(file));
    std::printf("%s\n", schema.dump(2).c_str());
    return kOk;
  }
  cyclopt::client::ResultSource s({.database = o.db, .lcm_url = o.lcm_url, .key_file = o.key_file, .timeout = o.timeout});
  if (o.command == "submit") return submit(s, o);
  if (o.command == "watch") return watch(s, o, job_argument(o));
  if (o.command == "status") return status(s, o);
  if (o.command == "cancel") return cancel(s, o);
  if (o.command == "export") return export_job(s, o);
  if (o.command == "plot") return plot(s, o);
  if (o.command == "report") return report(s, o);
  if (o.command == "list") return list(s, o);
  if (o.command == "top") return top(s, o);
  if (o.command == "query") {
    const nlohmann::json rows = s.fetch(cyclopt::storage::query_for(o.what, job_argument(o))).rows;
    // A foot_design job's table is its designs, one line per density, a sensitivity job's its
    // summaries, one line per parameter, a foot_comparison's its feet, one line per foot; --wide
    // shows every point.
    nlohmann::json designs = nlohmann::json::array(), summaries = nlohmann::json::array(),
                   feet = nlohmann::json::array();
    if (o.what == "solutions" && o.format == cyclopt::client::RowFormat::table)
      for (const nlohmann::json& row : rows) {
        const nlohmann::json values = row.value("values", nlohmann::json());
        if (cyclopt::records::is_designed_foot(values)) designs.push_back(row);
        if (cyclopt::records::is_sensitivity_summary(values)) summaries.push_back(row);
        if (cyclopt::records::is_compared_foot(values)) feet.push_back(row);
      }
    for (const auto& [selected, what] :
         {std::pair{&designs, "densities"}, std::pair{&summaries, "parameters"}, std::pair{&feet, "feet"}})
      if (!selected->empty()) {
        cyclopt::client::print_rows(std::cout, *selected, o.format);
        if (const auto headline = cyclopt::client::comparison_envelope_line(*selected)) std::cout << *headline << "\n";
        std::fprintf(stderr, "cyclopt: %zu %s of %zu stored points (--wide: every point)\n", selected->size(), what, rows.size());
        return kOk;
      }
    cyclopt::client::print_rows(std::cout, rows, o.format);
    return kOk;
  }
  throw UsageError(o.command.empty() ? "no command given"
                                     : "unknown command '" + o.command + "'" + cli::did_you_mean(o.command, kCommands));
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      std::fputs(cli::kExitCodeTable, stdout);
      return kOk;
    }
    if (a == "--version") {
      std::printf("%s\n", cli::version_text("cyclopt").c_str());
      return kOk;
    }
  }
  try {
    return run(parse_args(argc, argv));
  } catch (const UsageError& e) {
    std::fputs(cli::short_usage("cyclopt", e.what(), kUsage).c_str(), stderr);
    return cli::kExitUsage;
  } catch (const LocalRejection& e) {
    std::fprintf(stderr, "cyclopt: %s\n", e.what());
    return kRejected;
  } catch (const cyclopt::client::NoAnswer& e) {
    std::fprintf(stderr, "cyclopt: %s\n", e.what());
    return kNoAnswer;
  } catch (const cyclopt::client::QueryError& e) {
    std::fprintf(stderr, "cyclopt: %s\n", e.what());
    return kRejected;
  } catch (const cyclopt::client::SignatureRejected& e) {  // the key file's key or secret is not the server's
    std::fprintf(stderr, "cyclopt: %s\n", e.what());
    return kRejected;
  } catch (const std::invalid_argument& e) {  // local queries: unknown job, bad filter
    std::fprintf(stderr, "cyclopt: %s\n", e.what());
    return kRejected;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cyclopt: %s\n", e.what());
    return cli::kExitResource;
  }
}
