#include "message_page.hpp"

#include "cyclopt/plot/html_report.hpp"

namespace cyclopt::web {

std::string message_page(const std::string& message) {
  return "<!DOCTYPE html><html lang=\"en\"><meta charset=\"utf-8\"><title>cyclopt</title><p>" + plot::html_escape(message) +
         "</p><p><a href=\"/\">jobs</a></p></html>";
}

}  // namespace cyclopt::web
