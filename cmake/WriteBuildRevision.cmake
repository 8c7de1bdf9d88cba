# Writes OUTPUT (cyclopt_build_revision.hpp) with the git revision of SOURCE_DIR, the project version,
# the instruction-set level (ARCH) and the compiler flags (FLAGS), only when they changed (so an unchanged revision recompiles nothing). Run at configure
# time and before every build (common/cyclopt/cli/CMakeLists.txt).
execute_process(COMMAND git -C "${SOURCE_DIR}" describe --always --dirty --abbrev=10
                OUTPUT_VARIABLE revision OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET RESULT_VARIABLE status)
if(NOT status EQUAL 0 OR revision STREQUAL "")
  set(revision "unknown")
endif()
set(text "#pragma once\n// Written by cmake/WriteBuildRevision.cmake; do not edit.\n#define CYCLOPT_GIT_REVISION \"${revision}\"\n#define CYCLOPT_PROJECT_VERSION \"${PROJECT_VERSION}\"\n#define CYCLOPT_BUILD_ARCH \"${ARCH}\"\n#define CYCLOPT_BUILD_FLAGS \"${FLAGS}\"\n")
set(old "")
if(EXISTS "${OUTPUT}")
  file(READ "${OUTPUT}" old)
endif()
if(NOT old STREQUAL text)
  file(WRITE "${OUTPUT}" "${text}")
endif()
