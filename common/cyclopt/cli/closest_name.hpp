#pragma once
// "Did you mean ...?" for a misspelled name (a foot preset, a command, an option): the known name
// nearest by edit distance, if it is near enough to be a plausible typo.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cyclopt::cli {

// Levenshtein distance (insertions, deletions, substitutions of one character; case-insensitive).
int edit_distance(std::string_view a, std::string_view b);

// The known name with the smallest edit distance to `given`, if that distance is at most
// max(2, |given| / 3); nullopt if none is that close (or `given` is itself known).
std::optional<std::string> closest_name(std::string_view given, const std::vector<std::string>& known);

// " (did you mean 'X'?)" or "" - to append to an error message.
std::string did_you_mean(std::string_view given, const std::vector<std::string>& known);

}  // namespace cyclopt::cli
