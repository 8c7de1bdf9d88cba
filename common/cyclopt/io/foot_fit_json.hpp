#pragma once
// JSON of the foot fit (seed 001 section 4.2) beside its numerics in foot_fit/: the ankle tracks
// a foot_fit job carries inline, and the record (records/foot_fit_record.hpp) of a fit result.
//
// The trials of a foot_fit job spec (service/foot_fit_kind.hpp) are the sagittal ankle tracks of
// the rolling phase, already taken from the marker files by the client (`cyclopt-foot fit
// --job-spec`, `cyclopt submit --task foot_fit --trials`), since file names on the client mean
// nothing to the server:
//   "trials": [{"source": "trial1.trc", "x": [m, ...], "z": [m, ...]}, ...]
// x along the walking direction, z above the ground, written to 1e-5 m (10 um, far below the
// marker noise of a gait lab).

#include "cyclopt/foot_fit/ankle_track.hpp"
#include "cyclopt/foot_fit/rolling_foot_fit.hpp"
#include "cyclopt/records/foot_fit_record.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace cyclopt::io {

inline constexpr int kMaxFitTrials = 100;
inline constexpr double kMaxTrackCoordinate = 100.0;  // m, |x| and |z|
inline constexpr double kTrackResolution = 1e-5;      // m

// `resolution` > 0 (1 / an integer) rounds the coordinates to multiples of it (m); 0 writes them exactly.
nlohmann::json to_json(const std::vector<foot_fit::AnkleTrack>& tracks, double resolution = 0.0);
// The foot_fit job spec of `tracks` (coordinates to kTrackResolution), what the clients submit.
nlohmann::json foot_fit_job_spec(const std::vector<foot_fit::AnkleTrack>& tracks, bool toe_bound = true);
// Throws SpecError naming the element (`path` + "[1].z[17]") and its admissible range: at least
// one trial, x and z of equal length >= min_samples, finite numbers within kMaxTrackCoordinate.
std::vector<foot_fit::AnkleTrack> ankle_tracks_from_json(const nlohmann::json& j, const std::string& path = "trials",
                                                         int min_samples = foot_fit::AnkleTrackOptions{}.min_samples);

records::FootFitRecord foot_fit_record(const foot_fit::FootFitResult& fit);
records::FootFitAnglesRecord foot_fit_angles_record(const foot_fit::FootFitResult& fit);
// The fit as stored, back (what the figures of a stored foot_fit job draw): throws
// records::RecordError when the angles do not match the record's trials or the foot is invalid.
foot_fit::FootFitResult foot_fit_result(const records::FootFitRecord& record, const records::FootFitAnglesRecord& angles);

}  // namespace cyclopt::io
