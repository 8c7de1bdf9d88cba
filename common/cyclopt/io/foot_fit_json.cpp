#include "cyclopt/io/foot_fit_json.hpp"

#include "cyclopt/errors/spec_error.hpp"
#include "cyclopt/io/foot_spec_json.hpp"

#include <cmath>

namespace cyclopt::io {

namespace {

std::vector<double> rounded(const std::vector<double>& v, double resolution) {
  if (resolution <= 0.0) return v;
  std::vector<double> out;
  out.reserve(v.size());
  const double scale = std::round(1.0 / resolution);  // divide by an integer: 0.41234, not 0.41234000000000003
  for (double x : v) out.push_back(std::round(x * scale) / scale);
  return out;
}

std::vector<double> coordinates(const nlohmann::json& t, const std::string& path, const char* key) {
  const std::string at = path + "." + key;
  if (!t.contains(key)) throw SpecError(at, "is required: the ankle's " + std::string(key) + " per sample (m)");
  const nlohmann::json& a = t[key];
  if (!a.is_array()) throw SpecError(at, "must be an array of numbers (m)");
  std::vector<double> out;
  out.reserve(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double v = a[i].is_number() ? a[i].get<double>() : std::nan("");
    if (!(std::abs(v) <= kMaxTrackCoordinate))
      throw SpecError(at + "[" + std::to_string(i) + "]",
                      "must be a number in " + range_text(-kMaxTrackCoordinate, kMaxTrackCoordinate, "m") + ", got " + a[i].dump());
    out.push_back(v);
  }
  return out;
}

}  // namespace

nlohmann::json to_json(const std::vector<foot_fit::AnkleTrack>& tracks, double resolution) {
  nlohmann::json out = nlohmann::json::array();
  for (const foot_fit::AnkleTrack& t : tracks)
    out.push_back({{"source", t.source}, {"x", rounded(t.x, resolution)}, {"z", rounded(t.z, resolution)}});
  return out;
}

nlohmann::json foot_fit_job_spec(const std::vector<foot_fit::AnkleTrack>& tracks, bool toe_bound) {
  return {{"scene", "walker"}, {"task", "foot_fit"}, {"trials", to_json(tracks, kTrackResolution)}, {"toe_bound", toe_bound}};
}

std::vector<foot_fit::AnkleTrack> ankle_tracks_from_json(const nlohmann::json& j, const std::string& path, int min_samples) {
  if (!j.is_array() || j.empty() || j.size() > static_cast<std::size_t>(kMaxFitTrials))
    throw SpecError(path, "must be an array of 1 to " + std::to_string(kMaxFitTrials) +
                              " trials {\"source\": ..., \"x\": [m], \"z\": [m]}");
  std::vector<foot_fit::AnkleTrack> tracks;
  for (std::size_t k = 0; k < j.size(); ++k) {
    const std::string at = path + "[" + std::to_string(k) + "]";
    const nlohmann::json& t = j[k];
    if (!t.is_object()) throw SpecError(at, "must be an object {\"source\": ..., \"x\": [m], \"z\": [m]}");
    for (const auto& [key, value] : t.items())
      if (key != "source" && key != "x" && key != "z") throw SpecError(at + "." + key, "is not a field of a trial (source, x, z)");
    foot_fit::AnkleTrack track;
    track.source = "trial " + std::to_string(k + 1);
    if (t.contains("source")) {
      if (!t["source"].is_string() || t["source"].get<std::string>().size() > 200)
        throw SpecError(at + ".source", "must be a text of at most 200 characters");
      track.source = t["source"].get<std::string>();
    }
    track.x = coordinates(t, at, "x");
    track.z = coordinates(t, at, "z");
    if (track.x.size() != track.z.size())
      throw SpecError(at + ".z", "has " + std::to_string(track.z.size()) + " samples, x has " + std::to_string(track.x.size()));
    if (track.samples() < min_samples)
      throw SpecError(at + ".x", "has " + std::to_string(track.samples()) + " samples, at least " + std::to_string(min_samples) +
                                     " needed in the rolling phase");
    track.last_sample = track.samples() - 1;
    track.phase_rule = "as submitted";
    tracks.push_back(std::move(track));
  }
  return tracks;
}

records::FootFitRecord foot_fit_record(const foot_fit::FootFitResult& f) {
  records::FootFitRecord r;
  r.model = std::string(foot::to_string(f.model));
  r.converged = f.converged;
  r.message = f.message;
  r.iterations = f.iterations;
  r.seconds = f.seconds;
  r.samples = f.samples;
  r.unknowns = f.unknowns;
  r.rms = f.rms;
  r.max_residual = f.max_residual;
  r.noise_estimate = f.noise_estimate;
  for (const foot_fit::ParameterEstimate& e : f.estimates)
    r.parameters.push_back({e.name, e.unit, e.value, e.lower, e.upper, e.standard_error, e.fixed, e.at_bound,
                            e.stride_spread, e.boundary_spread, e.flag});
  r.spread_refits = f.spread_refits;
  r.spread_unconverged = f.spread_unconverged;
  r.boundary_tolerance = f.boundary_tolerance;
  for (std::size_t k = 0; k < f.trials.size(); ++k)
    r.trials.push_back({f.trials[k].source, f.trials[k].samples, f.trials[k].rms, f.trials[k].max, f.x_off[k]});
  for (std::size_t c = 0; c < f.convexity.names.size(); ++c) r.convexity.push_back({f.convexity.names[c], f.convexity.values[c]});
  r.convex = f.convexity.convex;
  r.foot = to_json(f.spec("fitted " + r.model));
  return r;
}

records::FootFitAnglesRecord foot_fit_angles_record(const foot_fit::FootFitResult& f) {
  records::FootFitAnglesRecord a;
  for (const Eigen::VectorXd& theta : f.theta) a.theta.emplace_back(theta.data(), theta.data() + theta.size());
  return a;
}

foot_fit::FootFitResult foot_fit_result(const records::FootFitRecord& r, const records::FootFitAnglesRecord& angles) {
  foot_fit::FootFitResult f;
  foot::FootSpec spec;
  try {
    spec = foot_spec_from_json(r.foot, "values.foot");
  } catch (const std::exception& e) {
    throw records::RecordError(e.what());
  }
  if (spec.model != foot::FootModel::hm && spec.model != foot::FootModel::hmt)
    throw records::RecordError("values.foot: a fitted foot is HM or HMT");
  if (angles.theta.size() != r.trials.size())
    throw records::RecordError("trajectory.theta: " + std::to_string(angles.theta.size()) + " trials, the fit has " +
                               std::to_string(r.trials.size()));
  f.model = spec.model;
  f.parameters = spec.parameters;
  for (const records::FittedParameterRecord& p : r.parameters)
    f.estimates.push_back({p.name, p.unit, p.value, p.lower, p.upper, p.standard_error, p.fixed, p.at_bound,
                           p.stride_spread, p.boundary_spread, p.flag});
  f.spread_refits = r.spread_refits;
  f.spread_unconverged = r.spread_unconverged;
  f.boundary_tolerance = r.boundary_tolerance;
  for (std::size_t k = 0; k < r.trials.size(); ++k) {
    const std::vector<double>& theta = angles.theta[k];
    if (static_cast<int>(theta.size()) != r.trials[k].samples)
      throw records::RecordError("trajectory.theta[" + std::to_string(k) + "]: " + std::to_string(theta.size()) +
                                 " angles, the trial has " + std::to_string(r.trials[k].samples) + " samples");
    f.theta.push_back(Eigen::Map<const Eigen::VectorXd>(theta.data(), static_cast<Eigen::Index>(theta.size())));
    f.x_off.push_back(r.trials[k].x_off);
    f.trials.push_back({r.trials[k].source, r.trials[k].samples, r.trials[k].rms, r.trials[k].max});
  }
  f.samples = r.samples;
  f.unknowns = r.unknowns;
  f.rms = r.rms;
  f.max_residual = r.max_residual;
  f.noise_estimate = r.noise_estimate;
  for (const records::ConvexityRowRecord& c : r.convexity) {
    f.convexity.names.push_back(c.condition);
    f.convexity.values.push_back(c.value);
  }
  f.convexity.convex = r.convex;
  f.converged = r.converged;
  f.iterations = r.iterations;
  f.message = r.message;
  f.seconds = r.seconds;
  return f;
}

}  // namespace cyclopt::io
