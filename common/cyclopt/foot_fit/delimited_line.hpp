#pragma once
// Splitting one line of a delimited text file into its fields (views into the line).

#include <string_view>
#include <vector>

namespace cyclopt::foot_fit {

inline std::vector<std::string_view> split_fields(std::string_view line, char delimiter) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = line.find(delimiter, start);
    fields.push_back(line.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (end == std::string_view::npos) break;
    start = end + 1;
  }
  return fields;
}

// The non-empty fields of a line whose fields are separated by runs of `delimiter` (headers
// padded with extra tabs, e.g. OpenSim's motion_capture_walk.trc).
inline std::vector<std::string_view> split_on_runs(std::string_view line, char delimiter) {
  std::vector<std::string_view> fields;
  for (std::string_view f : split_fields(line, delimiter))
    if (!f.empty()) fields.push_back(f);
  return fields;
}

inline bool is_blank(std::string_view line) {
  return line.find_first_not_of(" \t\r") == std::string_view::npos;
}

}  // namespace cyclopt::foot_fit
