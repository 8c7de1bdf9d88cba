// The figures of a stored foot_fit job (plot/foot_fit_figures.hpp, issue 20 item 4) read back
// through the records: the fit as stored (FootFitRecord + FootFitAnglesRecord) gives the model
// ankle of every sample the fit itself gives; an unconverged fit is not drawn, and says why.
#include "cyclopt/foot/foot_presets.hpp"
#include "cyclopt/foot_fit/circle_fit_start.hpp"
#include "cyclopt/foot_fit/synthetic_trials.hpp"
#include "cyclopt/io/foot_fit_json.hpp"
#include "cyclopt/plot/foot_fit_figures.hpp"
#include "cyclopt/plot/job_report.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace cyclopt;
namespace ff = cyclopt::foot_fit;

namespace {

struct StoredFit {
  std::vector<ff::AnkleTrack> tracks;
  ff::FootFitResult hm;
  nlohmann::json document;

  StoredFit() {
    const foot::FootSpec spec = foot::foot_preset("P1-shoes-left-HM-SG").spec;
    for (int k = 0; k < 2; ++k) {
      ff::SyntheticTrialOptions o;
      o.noise = 0.0005;
      o.offset = 0.4 + 0.11 * k;
      o.seed = 5 + k;
      o.foot_angle = ff::default_foot_angle_history(spec);
      o.source = "trial" + std::to_string(k + 1);
      tracks.push_back(ff::ankle_track(ff::synthetic_trial(spec, o)));
    }
    hm = ff::fit_hm(tracks, ff::circle_fit_start(tracks));
    // The document `cyclopt export` writes, with the parts the figures read.
    document = {{"id", 7}, {"scene", "walker"}, {"task", "foot_fit"}, {"spec", io::foot_fit_job_spec(tracks)}};
    document["solutions"] = {{{"curve", 0}, {"point", 0}, {"values", io::foot_fit_record(hm)}}};
    document["trajectories"] = {{{"curve", 0}, {"point", 0}, {"format", "json"}, {"data", io::foot_fit_angles_record(hm)}}};
  }
};

const StoredFit& stored() {
  static const StoredFit s;
  return s;
}

}  // namespace

TEST(FootFitJobFigures, TheStoredFitGivesTheFitsOwnModelAnkles) {
  const StoredFit& s = stored();
  ASSERT_TRUE(s.hm.converged) << s.hm.message;
  const ff::FootFitResult back = io::foot_fit_result(io::foot_fit_record(s.hm), io::foot_fit_angles_record(s.hm));
  EXPECT_EQ(back.model, s.hm.model);
  EXPECT_EQ(back.trials.size(), s.tracks.size());
  // The stored foot parameters are rounded by the foot spec JSON; the ankles agree to far below the noise.
  for (int k = 0; k < static_cast<int>(s.tracks.size()); ++k)
    for (int j = 0; j < s.tracks[static_cast<std::size_t>(k)].samples(); ++j)
      EXPECT_LT((back.model_ankle(k, j) - s.hm.model_ankle(k, j)).norm(), 1e-9) << "trial " << k << " sample " << j;
  std::vector<std::string> not_drawn;
  const std::vector<plot::Figure> figures = plot::foot_fit_job_figures(s.document, &not_drawn);
  EXPECT_TRUE(not_drawn.empty());
  ASSERT_EQ(figures.size(), 2u);
  EXPECT_EQ(figures[0].name, "fit_hm_ankle");
  EXPECT_EQ(figures[1].name, "fit_hm_outline");
  EXPECT_EQ(figures[0].caption.rfind("HM fit: ankle of 2 trial(s), RMS ", 0), 0u) << figures[0].caption;
  EXPECT_GT(plot::svg_of(figures[0]).size(), 10000u);
}

TEST(FootFitJobFigures, AnUnconvergedOrIncompleteFitIsNotDrawnAndSaysWhy) {
  nlohmann::json doc = stored().document;
  doc["solutions"][0]["values"]["converged"] = false;
  doc["solutions"][0]["values"]["message"] = "max_iterations";
  std::vector<std::string> not_drawn;
  EXPECT_TRUE(plot::foot_fit_job_figures(doc, &not_drawn).empty());
  ASSERT_EQ(not_drawn.size(), 1u);
  EXPECT_EQ(not_drawn[0], "HM fit: did not converge (max_iterations)");

  doc = stored().document;
  doc["trajectories"] = nlohmann::json::array();
  not_drawn.clear();
  EXPECT_TRUE(plot::foot_fit_job_figures(doc, &not_drawn).empty());
  ASSERT_EQ(not_drawn.size(), 1u);
  EXPECT_NE(not_drawn[0].find("no stored foot angles"), std::string::npos);

  doc = stored().document;
  doc["trajectories"][0]["data"]["theta"][1].erase(0);
  EXPECT_THROW(plot::foot_fit_job_figures(doc), records::RecordError);

  doc = stored().document;
  doc["solutions"] = nlohmann::json::array();
  EXPECT_THROW(plot::foot_fit_job_figures(doc), std::invalid_argument);
  doc = stored().document;
  doc["task"] = "sweep";
  EXPECT_THROW(plot::foot_fit_job_figures(doc), std::invalid_argument);
}

// Issue 54 item 4: a foot fit's report: provenance, a diagnostics row for its stored point, its figures.
TEST(FootFitJobFigures, ItsReportHasProvenanceDiagnosticsAndTheFitsFigures) {
  const plot::Report r = plot::job_report(stored().document);
  ASSERT_EQ(r.sections.size(), 3u);
  EXPECT_EQ(r.sections[0].heading, "Provenance");
  ASSERT_EQ(r.sections[1].tables.size(), 1u);
  EXPECT_EQ(r.sections[1].tables[0].rows.size(), 1u);
  EXPECT_EQ(r.sections[2].figures.size(), 2u) << r.sections[2].text;
  EXPECT_NE(plot::to_html(r).find("Resolved spec"), std::string::npos);
}
