#pragma once
// What `PROGRAM --version` prints: the program, the project version and the git revision it was
// built from (cli/CMakeLists.txt writes build_revision.hpp at build time, "-dirty" for a tree with
// uncommitted changes, "unknown" outside a git checkout).

#include <string>

namespace cyclopt::cli {

// The git revision of the build, e.g. "8ddceaf" or "8ddceaf-dirty".
const char* git_revision();

// "cyclopt 0.1.0 (git 8ddceaf)" for program "cyclopt".
std::string version_text(const std::string& program);

}  // namespace cyclopt::cli
