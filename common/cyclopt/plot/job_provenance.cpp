#include "cyclopt/plot/job_provenance.hpp"

#include "cyclopt/cli/version.hpp"

#include <cmath>
#include <ctime>

namespace cyclopt::plot {
namespace {

std::string text_or(const nlohmann::json& doc, const char* key, const std::string& missing) {
  const std::string v = doc.contains(key) && doc[key].is_string() ? doc[key].get<std::string>() : std::string();
  return v.empty() ? missing : v;
}

std::string now_utc() { return iso_utc(static_cast<double>(std::time(nullptr))); }

}  // namespace

std::string iso_utc(const nlohmann::json& unix_seconds) {
  if (!unix_seconds.is_number()) return "-";
  const std::time_t t = static_cast<std::time_t>(std::floor(unix_seconds.get<double>()));
  std::tm utc{};
  gmtime_r(&t, &utc);
  char b[32];
  std::strftime(b, sizeof b, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return b;
}

ReportSection provenance_section(const nlohmann::json& doc) {
  ReportSection s;
  s.heading = "Provenance";
  s.boxed = true;
  const std::string unrecorded = "not recorded (stored before the job row held it)";
  const nlohmann::json seeds = doc.value("seeds", nlohmann::json::object());
  const bool no_seeds = !seeds.is_object() || seeds.empty();
  ReportTable t;
  t.header = {"", ""};
  t.rows = {
      {"job", std::to_string(doc.value("id", 0)) + ": " + doc.value("scene", std::string()) + " " +
                  doc.value("task", std::string()) + ", state " + doc.value("state", std::string()) + ", " +
                  std::to_string(doc.value("attempts", 0)) + " attempt(s)"},
      {"program", text_or(doc, "program_version", unrecorded)},
      {"build level (ISA)", text_or(doc, "isa_level", unrecorded) +
                                " (results are bitwise reproducible between builds of one level)"},
      {"build flags", text_or(doc, "build_flags", unrecorded)},
      {"seeds", no_seeds ? std::string("none (the job draws no random numbers)") : seeds.dump()},
      {"submitted", iso_utc(doc.value("submitted_at", nlohmann::json()))},
      {"started", iso_utc(doc.value("started_at", nlohmann::json()))},
      {"finished", iso_utc(doc.value("finished_at", nlohmann::json()))},
      {"computation", report_number(doc.value("run_seconds", nlohmann::json()), "%.1f s") + ", " +
                          std::to_string(doc.value("points_stored", 0)) + " points stored"},
      {"report", "written " + now_utc() + " by " + cli::version_text("cyclopt")},
  };
  s.tables.push_back(std::move(t));
  const bool resolved = doc.contains("resolved_spec") && doc["resolved_spec"].is_object();
  s.listings.push_back({"Resolved spec (every default filled in: what the job ran)",
                        resolved ? doc["resolved_spec"].dump(2) : unrecorded});
  s.listings.push_back({"Submitted spec", doc.contains("spec") ? doc["spec"].dump(2) : std::string("-")});
  if (!doc.value("error", std::string()).empty())
    s.text = (doc.value("state", std::string()) == "incomplete" ? "Outcome: " : "Error: ") + doc["error"].get<std::string>();
  return s;
}

}  // namespace cyclopt::plot
