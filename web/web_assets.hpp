#pragma once
// The dashboard's static files, compiled into cyclopt-web (web/embed_assets.cmake): the page, its
// script and style, and the vendored uPlot chart library (web/vendor/uplot/, MIT, its LICENSE
// served beside it).

#include <string_view>
#include <vector>

namespace cyclopt::web {

struct Asset {
  const char* url;           // e.g. "/static/dashboard.js"
  const char* content_type;
  std::string_view bytes;
};

const std::vector<Asset>& assets();

}  // namespace cyclopt::web
