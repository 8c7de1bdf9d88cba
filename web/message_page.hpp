#pragma once
// The small HTML page cyclopt-web answers with when it shows no dashboard (not logged in, no such
// job, a refused request): the message HTML-escaped, so a job's text in it stays text.

#include <string>

namespace cyclopt::web {

std::string message_page(const std::string& message);

}  // namespace cyclopt::web
