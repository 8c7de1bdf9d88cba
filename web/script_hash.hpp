#pragma once
// A Content-Security-Policy source that allows one inline script by its content:
// "'sha256-" base64(SHA-256(text)) "'" (CSP level 2, hash-source). The dashboard serves reports
// under a policy that allows no script but the report's own (plot/html_report.hpp).

#include <string>

namespace cyclopt::web {

std::string script_hash_source(const std::string& text);

}  // namespace cyclopt::web
