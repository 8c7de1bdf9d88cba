#include "cyclopt/plot/walker_job_results.hpp"

#include "cyclopt/io/foot_spec_json.hpp"
#include "cyclopt/records/sweep_records.hpp"
#include "cyclopt/records/walker_point_record.hpp"

#include <cmath>
#include <map>
#include <stdexcept>

namespace cyclopt::plot {

const char* joint_name(int j) {
  static const char* names[] = {"H1 stance hip", "H2 swing hip", "K1 stance knee", "K2 swing knee",
                                "A1 stance ankle", "A2 swing ankle"};
  return names[j];
}

StoredWalker stored_walker(const nlohmann::json& spec) {
  StoredWalker w;
  w.setup = spec.get<records::WalkerSetupRecord>();
  w.foot = io::foot_value(w.setup.foot, "foot");
  w.constants.points = w.setup.points.value_or(w.constants.points);
  w.constants.bezier_degree = w.setup.bezier_degree.value_or(w.constants.bezier_degree);
  return w;
}

const nlohmann::json& stored_spec(const nlohmann::json& doc) {
  const bool resolved = doc.contains("resolved_spec") && doc["resolved_spec"].is_object();
  return resolved ? doc["resolved_spec"] : doc.at("spec");
}

WalkerJobResults walker_job_results(const nlohmann::json& doc) {
  WalkerJobResults r;
  r.id = doc.value("id", std::int64_t{0});
  const std::string scene = doc.value("scene", ""), task = doc.value("task", "");
  if (scene != "walker" || task == "foot_sweep" || !doc.contains("spec"))
    throw std::invalid_argument("job " + std::to_string(r.id) + " is a " + scene + " " + task +
                                " job; pictures of gaits need a walker evaluate, optimise, multistart or sweep job");
  r.spec = stored_spec(doc);
  r.walker = stored_walker(r.spec);
  const std::string foot = r.walker.foot.name.empty() ? std::string(foot::to_string(r.walker.foot.model)) : r.walker.foot.name;
  r.label = r.spec.value("name", "job " + std::to_string(r.id) + ": " + foot + ", " +
                                     r.spec.value("objective", std::string("f_mech")));
  r.points = gait_points(doc, 0);
  std::map<int, std::string> curves;  // curve -> its stored name
  const nlohmann::json none = nlohmann::json::array();
  for (const nlohmann::json& s : doc.contains("solutions") ? doc["solutions"] : none)
    if (s.value("curve", 0) > 0) curves[s.value("curve", 0)];
  for (const nlohmann::json& c : doc.contains("curves") ? doc["curves"] : none)
    if (curves.count(c.value("curve", 0))) curves[c.value("curve", 0)] = c.value("name", "");
  for (const auto& [curve, name] : curves) r.curves.push_back({curve, name, gait_points(doc, curve)});
  return r;
}

std::vector<GaitPoint> gait_points(const nlohmann::json& doc, int curve) {
  std::map<int, const nlohmann::json*> trajectories;  // by point, into doc
  const nlohmann::json none = nlohmann::json::array();
  for (const nlohmann::json& t : doc.contains("trajectories") ? doc["trajectories"] : none)
    if (t.value("format", "") == "json" && t.value("curve", 0) == curve) trajectories[t.value("point", 0)] = &t.at("data");
  const bool sweep_best_rows = doc.value("task", "") == "sweep" && curve == 0;
  std::vector<GaitPoint> points;
  for (const nlohmann::json& s : doc.contains("solutions") ? doc["solutions"] : none) {
    if (s.value("curve", 0) != curve) continue;
    GaitPoint p;
    p.speed = s.at("parameter").is_number() ? s["parameter"].get<double>() : std::nan("");
    p.status = s.value("status", "");
    const auto values = s.at("values").get<records::WalkerPointRecord>();
    if (values.gait) p.gait = *values.gait;
    p.converged = records::solved(values);
    p.sensitivities = values.sensitivities;
    // A sweep's best row (curve 0) with several seeds also holds its SweepBestRecord.
    if (sweep_best_rows && s["values"].contains("seed_spread"))
      p.seed_spread = s["values"].get<records::SweepBestRecord>().seed_spread;
    const auto t = trajectories.find(s.value("point", 0));
    if (t != trajectories.end()) p.trajectory = t->second->get<records::GaitTrajectoryRecord>();
    points.push_back(std::move(p));
  }
  return points;
}

const GaitPoint* point_near(const WalkerJobResults& r, double speed) {
  const GaitPoint* best = nullptr;
  for (const GaitPoint& p : r.points) {
    if (!p.converged || !p.trajectory) continue;
    if (!best || (std::isfinite(speed) && std::abs(p.speed - speed) < std::abs(best->speed - speed))) best = &p;
  }
  return best;
}

}  // namespace cyclopt::plot
