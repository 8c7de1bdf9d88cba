#pragma once
// What cyclopt-web reads from an HTTP request besides the route: a job id from the path, a cookie,
// and whether a write request comes from the dashboard's own page (docs/dashboard.md, security).

#include <cstdint>
#include <optional>
#include <string>

namespace cyclopt::web {

// A job id written in decimal, 1 .. 2^63-1; nullopt for anything else ("", "0", "-3", "1e3", "9..9").
std::optional<std::int64_t> job_id_of(const std::string& text);

// The value of cookie `name` in a Cookie header ("a=1; cyclopt_token=x"), "" if absent.
std::string cookie_value(const std::string& cookie_header, const std::string& name);

// A write request (POST) is accepted only from the dashboard's own page: it carries the header
// kActionHeader (a page of another origin cannot set it without a CORS preflight, which
// cyclopt-web never answers), and an Origin header, when the browser sends one, names this host.
inline constexpr const char* kActionHeader = "X-Cyclopt-Action";
bool same_origin(const std::string& origin_header, const std::string& host_header);

}  // namespace cyclopt::web
