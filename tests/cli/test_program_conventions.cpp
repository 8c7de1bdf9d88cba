// Conventions every program shares (issue 17 item 8): --version with the git revision, one exit
// code table (cli/exit_codes.hpp), a short usage on a bad option, a spec file checked before it is
// sent (no server needed to learn it is not JSON), "did you mean" for a misspelled preset.
#include "cyclopt/cli/closest_name.hpp"
#include "cyclopt/cli/exit_codes.hpp"
#include "cyclopt/cli/version.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace cyclopt::cli {
namespace {

struct Outcome {
  int exit_code = -1;
  std::string out;  // stdout and stderr
  double seconds = 0;
};

Outcome run(const std::string& command) {
  Outcome r;
  const auto start = std::chrono::steady_clock::now();
  FILE* p = ::popen((command + " 2>&1").c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf;
  std::size_t n = 0;
  while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) r.out.append(buf.data(), n);
  const int status = ::pclose(p);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

const std::array<std::pair<const char*, const char*>, 6> kPrograms = {{{"cyclopt", CYCLOPT_CLI},
                                                                        {"cyclopt-foot", CYCLOPT_FOOT_CLI},
                                                                        {"cyclopt-giant-swing", CYCLOPT_GIANT_SWING_CLI},
                                                                        {"cycloptd", CYCLOPTD},
                                                                        {"cyclopt-worker", CYCLOPT_WORKER},
                                                                        {"cyclopt-web", CYCLOPT_WEB}}};

// A newcomer reads --help in an 80-column terminal: no line of any program's help (and of the
// subcommands' own) is wider.
TEST(ProgramConventions, EveryHelpFitsEightyColumns) {
  std::vector<std::string> commands;
  for (const auto& [name, path] : kPrograms) commands.push_back(std::string(path) + " --help");
  commands.push_back(std::string(CYCLOPT_FOOT_CLI) + " fit --help");
  commands.push_back(std::string(CYCLOPT_FOOT_CLI) + " synth --help");
  for (const std::string& command : commands) {
    const Outcome r = run(command);
    EXPECT_EQ(r.exit_code, kExitOk) << command;
    EXPECT_GT(r.out.size(), 40u) << command;
    std::istringstream lines(r.out);
    int number = 0;
    for (std::string line; std::getline(lines, line);) {
      ++number;
      EXPECT_LE(line.size(), 80u) << command << ", line " << number << ": " << line;
    }
  }
}

TEST(ProgramConventions, EveryProgramPrintsItsVersionWithTheGitRevision) {
  const Outcome git = run("git -C " CYCLOPT_SOURCE_DIR " rev-parse --short=7 HEAD");
  for (const auto& [name, path] : kPrograms) {
    const Outcome r = run(std::string(path) + " --version");
    EXPECT_EQ(r.exit_code, kExitOk) << name;
    EXPECT_EQ(r.out.rfind(std::string(name) + " ", 0), 0u) << r.out;
    EXPECT_NE(r.out.find("(git "), std::string::npos) << r.out;
    if (git.exit_code == 0) {
      EXPECT_NE(r.out.find(git.out.substr(0, 7)), std::string::npos) << name << ": " << r.out;
    }
  }
  EXPECT_EQ(version_text("x").find("x 0."), 0u);
}

TEST(ProgramConventions, ABadOptionGivesTheShortUsageAndExitCodeOne) {
  for (const auto& [name, path] : kPrograms) {
    const Outcome help = run(std::string(path) + " --help");
    EXPECT_EQ(help.exit_code, kExitOk) << name;
    EXPECT_NE(help.out.find(kExitCodeTable), std::string::npos) << name << " --help lacks the exit code table";
    const Outcome bad = run(std::string(path) + " --no-such-option");
    EXPECT_EQ(bad.exit_code, kExitUsage) << name << ": " << bad.out;
    EXPECT_NE(bad.out.find("Run '" + std::string(name) + " --help' for all options."), std::string::npos) << bad.out;
    EXPECT_LT(bad.out.size(), help.out.size() / 2 + 200) << name << ": the usage on a bad option is not short";
  }
  const Outcome typo = run(std::string(CYCLOPT_CLI) + " submit --spec x.json --wach");
  EXPECT_NE(typo.out.find("did you mean '--watch'?"), std::string::npos) << typo.out;
  const Outcome command = run(std::string(CYCLOPT_CLI) + " stauts 3");
  EXPECT_NE(command.out.find("did you mean 'status'?"), std::string::npos) << command.out;
}

// No server listens on memq:// in another process: a spec is judged before anything is sent,
// so the answer is immediate and says what is wrong (before, the client waited for --timeout).
TEST(ProgramConventions, ASpecIsCheckedBeforeItIsSent) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "cyclopt_test_program_conventions";
  std::filesystem::create_directories(dir);
  const std::string not_json = (dir / "not_json.json").string(), bad_speed = (dir / "bad_speed.json").string();
  std::ofstream(not_json) << "{\"scene\": \"walker\", \"task\": \"optimise\",";
  std::ofstream(bad_speed) << R"({"scene": "walker", "task": "optimise", "foot": "point", "speed": 9})";
  const std::string cli = std::string(CYCLOPT_CLI) + " --lcm-url memq:// --timeout 20 submit --spec ";
  const Outcome j = run(cli + not_json);
  EXPECT_EQ(j.exit_code, kExitRejected) << j.out;
  EXPECT_NE(j.out.find("is not valid JSON"), std::string::npos) << j.out;
  EXPECT_NE(j.out.find("nothing was sent"), std::string::npos) << j.out;
  EXPECT_LT(j.seconds, 10.0);
  const Outcome s = run(cli + bad_speed);
  EXPECT_EQ(s.exit_code, kExitRejected) << s.out;
  EXPECT_NE(s.out.find("rejected before sending (field speed)"), std::string::npos) << s.out;
  EXPECT_LT(s.seconds, 10.0);
}

TEST(ProgramConventions, AMisspelledPresetGetsASuggestion) {
  const Outcome submit = run(std::string(CYCLOPT_CLI) +
                         " --lcm-url memq:// submit --foot P2-shoes-left-HTM --speeds 1:0.1:1.2");
  EXPECT_EQ(submit.exit_code, kExitRejected) << submit.out;
  EXPECT_NE(submit.out.find("did you mean 'P2-shoes-left-HMT'?"), std::string::npos) << submit.out;
  const Outcome foot = run(std::string(CYCLOPT_FOOT_CLI) + " --preset p1-barefoot-left-hn");
  EXPECT_EQ(foot.exit_code, kExitRejected) << foot.out;
  EXPECT_NE(foot.out.find("did you mean 'P1-barefoot-left-HM'?"), std::string::npos) << foot.out;
}

TEST(ClosestName, SuggestsOnlyPlausibleTypos) {
  const std::vector<std::string> known = {"P2-shoes-left-HMT", "P1-barefoot-left-HM", "P1-shoes-left-HMT", "point"};
  EXPECT_EQ(closest_name("P1-shoes-left-HTM", known), "P1-shoes-left-HMT");
  EXPECT_EQ(closest_name("pont", known), "point");
  EXPECT_EQ(closest_name("P2-shoes-left-HMT", known), std::nullopt);  // known: nothing to suggest
  EXPECT_EQ(closest_name("giraffe", known), std::nullopt);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3);
  EXPECT_EQ(edit_distance("", "abc"), 3);
  EXPECT_EQ(did_you_mean("stauts", {"status", "submit"}), " (did you mean 'status'?)");
}

}  // namespace
}  // namespace cyclopt::cli
