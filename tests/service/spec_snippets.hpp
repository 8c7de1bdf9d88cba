#pragma once
// The job specs written out in the repository's text: every JSON object that begins with
// `{"scene"` in a file (README.md's examples, the specs of shell scripts, C++ raw strings), for
// the schema test. Shell scripts build their specs with variables and printf formats; expand()
// substitutes them.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace cyclopt::testing {

struct SpecSnippet {
  std::string where;  // "file:line"
  std::string text;   // from `{"scene"` to its closing brace (strings and escapes respected)
};

std::vector<SpecSnippet> spec_snippets(const std::filesystem::path& file);

// `text` with each `${NAME:-default}` replaced by its default and each key of `values` (a shell
// expansion such as "$FOOT" or "${SPEEDS%%:*}", or a printf format such as "%d") by its value,
// longest keys first.
std::string expand(std::string text, const std::map<std::string, std::string>& values);

}  // namespace cyclopt::testing
