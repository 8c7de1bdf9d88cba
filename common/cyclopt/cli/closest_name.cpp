#include "cyclopt/cli/closest_name.hpp"

#include <algorithm>
#include <cctype>

namespace cyclopt::cli {

int edit_distance(std::string_view a, std::string_view b) {
  std::vector<int> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = static_cast<int>(j);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    int diagonal = row[0];
    row[0] = static_cast<int>(i);
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) == std::tolower(static_cast<unsigned char>(b[j - 1]));
      const int next = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = row[j];
      row[j] = next;
    }
  }
  return row[b.size()];
}

std::optional<std::string> closest_name(std::string_view given, const std::vector<std::string>& known) {
  if (std::find(known.begin(), known.end(), given) != known.end()) return std::nullopt;
  const int limit = std::max(2, static_cast<int>(given.size()) / 3);
  std::optional<std::string> best;
  int best_distance = limit + 1;
  for (const std::string& k : known) {
    const int d = edit_distance(given, k);
    if (d < best_distance) {
      best_distance = d;
      best = k;
    }
  }
  return best;
}

std::string did_you_mean(std::string_view given, const std::vector<std::string>& known) {
  const std::optional<std::string> c = closest_name(given, known);
  return c ? " (did you mean '" + *c + "'?)" : "";
}

}  // namespace cyclopt::cli
