#include "spec_snippets.hpp"

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace cyclopt::testing {

namespace {

// The end (one past the closing brace) of the object opening at `begin`; text.size() if unclosed.
std::size_t object_end(const std::string& text, std::size_t begin) {
  int depth = 0;
  bool in_string = false;
  for (std::size_t i = begin; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '{') {
      ++depth;
    } else if (c == '}' && --depth == 0) {
      return i + 1;
    }
  }
  return text.size();
}

}  // namespace

std::vector<SpecSnippet> spec_snippets(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  std::ostringstream s;
  s << in.rdbuf();
  const std::string text = s.str();
  std::vector<SpecSnippet> snippets;
  const std::string opening = "{\"scene\"";
  for (std::size_t at = text.find(opening); at != std::string::npos; at = text.find(opening, at + 1)) {
    const auto line = 1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n');
    snippets.push_back({file.filename().string() + ":" + std::to_string(line), text.substr(at, object_end(text, at) - at)});
  }
  return snippets;
}

std::string expand(std::string text, const std::map<std::string, std::string>& values) {
  text = std::regex_replace(text, std::regex(R"(\$\{[A-Za-z_][A-Za-z0-9_]*:-([^}]*)\})"), "$1");
  std::vector<std::pair<std::string, std::string>> by_length(values.begin(), values.end());
  std::stable_sort(by_length.begin(), by_length.end(),
                   [](const auto& a, const auto& b) { return a.first.size() > b.first.size(); });
  for (const auto& [key, value] : by_length)
    for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + value.size()))
      text.replace(at, key.size(), value);
  return text;
}

}  // namespace cyclopt::testing
