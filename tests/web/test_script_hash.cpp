// The CSP hash-source of an inline script (web/script_hash.hpp) against SHA-256 test vectors
// (FIPS 180-2 "abc", the empty message) in base64, and the report's own script: the value the
// report policy of cyclopt-web allows (dashboard_browser checks in chromium that it runs).
#include "script_hash.hpp"

#include "cyclopt/plot/html_report.hpp"

#include <gtest/gtest.h>

namespace cyclopt::testing {
namespace {

TEST(ScriptHash, IsTheBase64OfTheSha256InQuotes) {
  EXPECT_EQ(web::script_hash_source("abc"), "'sha256-ungWv48Bz+pBQUDeXa4iI7ADYaOWF3qctBD/YfIAFa0='");
  EXPECT_EQ(web::script_hash_source(""), "'sha256-47DEQpj8HBSa+/TImW+5JCeuQeRkm5NMpJWZG3hSuFU='");
}

TEST(ScriptHash, AReportHoldsItsScriptOnlyWhenAFigureIsAnimated) {
  plot::Report report;
  report.title = "t";
  plot::ReportSection section;
  section.heading = "h";
  plot::ReportFigure still;
  still.svg = "<svg xmlns=\"http://www.w3.org/2000/svg\"><rect width=\"1\" height=\"1\"/></svg>";
  section.figures.push_back(still);
  report.sections.push_back(section);
  const std::string script = "<script>" + plot::report_script() + "</script>";
  EXPECT_EQ(plot::to_html(report).find("<script"), std::string::npos);
  plot::ReportFigure moving;
  moving.svg = "<svg xmlns=\"http://www.w3.org/2000/svg\"><rect width=\"1\" height=\"1\"><animate attributeName=\"width\" "
               "from=\"0\" to=\"1\" dur=\"1s\"/></rect></svg>";
  report.sections.front().figures.push_back(moving);
  const std::string html = plot::to_html(report);
  EXPECT_NE(html.find(script), std::string::npos);
  EXPECT_EQ(html.find("<script"), html.rfind("<script"));  // one script, the one the policy allows
}

}  // namespace
}  // namespace cyclopt::testing
