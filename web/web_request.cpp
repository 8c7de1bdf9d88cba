#include "web_request.hpp"

#include <charconv>

namespace cyclopt::web {

std::optional<std::int64_t> job_id_of(const std::string& text) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
  std::int64_t id = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), id);
  if (error != std::errc() || end != text.data() + text.size() || id < 1) return std::nullopt;
  return id;
}

std::string cookie_value(const std::string& cookie_header, const std::string& name) {
  std::size_t at = 0;
  while (at < cookie_header.size()) {
    std::size_t end = cookie_header.find(';', at);
    if (end == std::string::npos) end = cookie_header.size();
    std::string pair = cookie_header.substr(at, end - at);
    const std::size_t first = pair.find_first_not_of(' ');
    pair = first == std::string::npos ? "" : pair.substr(first);
    if (pair.size() > name.size() && pair.compare(0, name.size(), name) == 0 && pair[name.size()] == '=')
      return pair.substr(name.size() + 1);
    at = end + 1;
  }
  return "";
}

bool same_origin(const std::string& origin_header, const std::string& host_header) {
  if (origin_header.empty()) return true;  // browsers send Origin on every cross-origin POST
  return origin_header == "http://" + host_header || origin_header == "https://" + host_header;
}

}  // namespace cyclopt::web
