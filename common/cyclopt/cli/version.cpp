#include "cyclopt/cli/version.hpp"

#include "cyclopt_build_revision.hpp"

namespace cyclopt::cli {

const char* git_revision() { return CYCLOPT_GIT_REVISION; }

const char* build_arch() { return CYCLOPT_BUILD_ARCH; }

const char* build_flags() { return CYCLOPT_BUILD_FLAGS; }

std::string version_text(const std::string& program) {
  return program + " " + CYCLOPT_PROJECT_VERSION + " (git " + git_revision() + ", " + build_arch() + ")";
}

}  // namespace cyclopt::cli
