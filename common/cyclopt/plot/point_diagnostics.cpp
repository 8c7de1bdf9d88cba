#include "cyclopt/plot/point_diagnostics.hpp"

#include "cyclopt/plot/walker_job_results.hpp"
#include "cyclopt/records/solver_record.hpp"
#include "cyclopt/records/sweep_records.hpp"
#include "cyclopt/records/walker_point_record.hpp"

#include <cmath>
#include <map>
#include <optional>
#include <set>

namespace cyclopt::plot {
namespace {

template <class Record>
std::optional<Record> record_of(const nlohmann::json& values) {
  try {
    return values.get<Record>();
  } catch (const records::RecordError&) {
    return std::nullopt;
  }
}

// The solver the spec names ("qpsqp", "ipopt", ...), empty when it names none.
std::string solver_name(const nlohmann::json& doc) {
  if (!doc.contains("spec")) return "";
  const nlohmann::json& spec = stored_spec(doc);
  const nlohmann::json solver = spec.is_object() ? spec.value("solver", nlohmann::json()) : nlohmann::json();
  if (solver.is_string()) return solver.get<std::string>();
  return solver.is_object() && solver.value("solver", nlohmann::json()).is_string() ? solver["solver"].get<std::string>() : "";
}

std::string integer_or_dash(const nlohmann::json& v) { return v.is_number() ? std::to_string(v.get<long long>()) : "-"; }

}  // namespace

ReportTable point_diagnostics_table(const nlohmann::json& doc) {
  ReportTable t;
  t.header = {"curve", "point", "speed [m/s] (or parameter)", "solver", "iterations", "KKT error", "constraint violation",
              "time [s]", "found by / start", "status", "converged"};
  const std::string solver = solver_name(doc);
  const nlohmann::json none = nlohmann::json::array();
  const bool walker = doc.value("scene", "") == "walker";
  std::map<int, std::string> parameter_of;  // curve -> the name of its parameter
  for (const nlohmann::json& c : doc.contains("curves") ? doc["curves"] : none)
    parameter_of[c.value("curve", 0)] = c.value("parameter_name", "");
  for (const nlohmann::json& s : doc.contains("solutions") ? doc["solutions"] : none) {
    const nlohmann::json values = s.value("values", nlohmann::json::object());
    // The speed, or another curve parameter with its name (a foot_design's density, a summary's index).
    const auto name = parameter_of.find(s.value("curve", 0));
    const bool speed = name == parameter_of.end() || name->second.empty() || name->second == "speed";
    std::vector<std::string> row = {std::to_string(s.value("curve", 0)), std::to_string(s.value("point", 0)),
                                    report_number(s.value("parameter", nlohmann::json()), "%.3f") +
                                        (speed ? std::string() : " (" + name->second + ")")};
    const std::optional<records::WalkerPointRecord> p =
        walker && values.contains("gait") ? record_of<records::WalkerPointRecord>(values) : std::nullopt;
    const std::optional<records::SolverRecord> sr =
        p ? p->solver : (values.contains("solver") ? record_of<records::SolverRecord>(values["solver"]) : std::nullopt);
    const std::optional<records::SweepBestRecord> best = record_of<records::SweepBestRecord>(values);
    std::string found_by = best && best->found_by ? *best->found_by : (p && p->start ? *p->start : "-");
    if (best && best->reason) found_by = *best->reason;
    if (p && p->continuation && !(best && best->found_by))
      found_by = "continuation: " + (p->start ? *p->start : std::string("previous point")) +
                 (p->continuation->on_grid ? ", grid speed" : "");
    double seconds = sr ? sr->wall_seconds : std::nan("");
    if (!std::isfinite(seconds) && p && p->continuation) seconds = p->continuation->point_seconds;
    const std::string termination = sr ? sr->termination : (p && p->continuation ? std::string("continuation corrector") : "-");
    row.push_back(solver.empty() ? termination : solver + ": " + termination);
    row.push_back(sr ? std::to_string(sr->iterations) : integer_or_dash(s.value("iterations", nlohmann::json())));
    row.push_back(sr ? report_number(sr->kkt_error, "%.1e") : "-");
    row.push_back(sr ? report_number(sr->constraint_violation, "%.1e")
                     : report_number(s.value("constraint_violation", nlohmann::json()), "%.1e"));
    row.push_back(report_number(seconds, "%.2f"));
    row.push_back(found_by);
    const std::string status = s.value("status", "");
    row.push_back(status);
    // Converged: a walker gait that is real and whose solve (if any) succeeded; another point by
    // its solver record; without either, unknown.
    std::optional<bool> converged;
    if (p) converged = records::solved(*p) && !(p->continuation && !p->continuation->converged && !p->solver);
    else if (sr) converged = sr->success;
    else if (walker && best) converged = false;  // a sweep speed without a point: "not found"
    row.push_back(converged ? (*converged ? "yes" : "NO") : "-");
    t.failed.push_back(converged && !*converged);
    t.rows.push_back(std::move(row));
  }
  return t;
}

ReportSection point_diagnostics_section(const nlohmann::json& doc) {
  ReportSection s;
  s.heading = "Solver diagnostics per stored point";
  s.tables.push_back(point_diagnostics_table(doc));
  s.tables.back().scroll = s.tables.back().rows.size() > 20;
  const ReportTable& t = s.tables.back();
  std::set<std::string> curves;
  int failed = 0;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    curves.insert(t.rows[r][0]);
    failed += t.failed[r];
  }
  s.text = std::to_string(t.rows.size()) + " stored points on " + std::to_string(curves.size()) +
           " curve(s), numbered as `cyclopt query` shows them" + (t.scroll ? " (the table scrolls)" : "") + "; " +
           (failed ? std::to_string(failed) + " did not converge (rows in red, converged NO)" : std::string("all converged")) +
           ". KKT error: the solver's stationarity measure at its last iterate; time: the solve's wall time (or the "
           "continuation step's); found by: the sweep step that found a best point, the start of a solve, or the "
           "continuation run that reached it.";
  return s;
}

}  // namespace cyclopt::plot
