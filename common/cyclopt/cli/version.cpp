#include "cyclopt/cli/version.hpp"

#include "cyclopt_build_revision.hpp"

namespace cyclopt::cli {

const char* git_revision() { return CYCLOPT_GIT_REVISION; }

std::string version_text(const std::string& program) {
  return program + " " + CYCLOPT_PROJECT_VERSION + " (git " + git_revision() + ")";
}

}  // namespace cyclopt::cli
