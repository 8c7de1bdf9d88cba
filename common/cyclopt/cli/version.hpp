#pragma once
// What `PROGRAM --version` prints: the program, the project version and the git revision it was
// built from (cli/CMakeLists.txt writes build_revision.hpp at build time, "-dirty" for a tree with
// uncommitted changes, "unknown" outside a git checkout).

#include <string>

namespace cyclopt::cli {

// The git revision of the build, e.g. "8ddceaf" or "8ddceaf-dirty".
const char* git_revision();

// The instruction-set level the build targets (CYCLOPT_ARCH): "x86-64-v3" by default, "native" for
// an opt-in host-specific build. Results are bitwise reproducible between hosts of one level.
const char* build_arch();

// The compiler and its code-generation flags, e.g. "GNU 12.2.0 -march=x86-64-v3 -mtune=generic -O3".
const char* build_flags();

// "cyclopt 0.1.0 (git 8ddceaf, x86-64-v3)" for program "cyclopt".
std::string version_text(const std::string& program);

}  // namespace cyclopt::cli
