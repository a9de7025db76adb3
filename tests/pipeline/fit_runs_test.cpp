// Damping laws fitted to stored runs (src/pipeline/fit_runs): mirror images
// of runs for a body's planes of symmetry, fits made again from their
// records after the runs changed, and the warning for runs whose force
// histories did not converge.
#include "src/pipeline/fit_runs.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "src/core/error.hpp"
#include "tests/support/import_batch.hpp"
#include "tests/support/temp_dir.hpp"

namespace hydrocoef {
namespace {

using test::TempDir;

// One file (hash from `id`) giving one run at (u, v, 0, 0, 0, r) with Y, K and N.
ImportBatch run_file(int id, double u, double v, double r, double y, double k, double n, double x = -0.3) {
  ImportedRun run;
  run.key.body = "auv";
  run.key.nu_b = {u, v, 0, 0, 0, r};
  run.tau_b[0] = ForceComponent{x, std::nullopt, std::nullopt};
  run.tau_b[1] = ForceComponent{y, std::nullopt, std::nullopt};
  run.tau_b[3] = ForceComponent{k, std::nullopt, std::nullopt};
  run.tau_b[5] = ForceComponent{n, std::nullopt, std::nullopt};
  return test::one_run_batch(id, run);
}

// Sway force of a port-starboard symmetric body: odd in v, with a small
// deterministic "CFD noise" that is not odd, so that a half-plane fit and a
// whole-plane fit differ unless the images are made exactly.
double sway(double v, int i) { return -2.0 * v - 30.0 * v * std::abs(v) + 0.004 * std::sin(3.0 * i + 1.0); }

TEST(FitRuns, MirroredFitOverHalfThePlaneEqualsTheFitOverExplicitlyMirroredRuns) {
  TempDir dir;
  const std::vector<double> vs = {0.0, 0.05, 0.1, 0.2, 0.3};
  RunDatabase half(dir / "half.db"), whole(dir / "whole.db");
  int id = 1;
  for (int i = 0; i < static_cast<int>(vs.size()); ++i) {
    const double v = vs[static_cast<std::size_t>(i)], y = sway(v, i), k = 0.01 * y, n = 0.3 * y;
    half.import({run_file(id, 0.5, v, 0.0, y, k, n)}, ImportPolicy{});
    whole.import({run_file(id++, 0.5, v, 0.0, y, k, n)}, ImportPolicy{});
    // Port-starboard: (u, v, w, p, q, r) -> (u, -v, w, -p, q, -r); (X, Y, Z, K, M, N) -> (X, -Y, Z, -K, M, -N).
    if (v != 0.0) whole.import({run_file(id++, 0.5, -v, 0.0, -y, -k, -n)}, ImportPolicy{});
  }
  const DampingLawSpec spec = parse_damping_terms("1,v,v|v|");
  const MirrorSpec mirror = make_mirror_spec({"v"}, {});
  for (const std::size_t dof : {std::size_t{1}, std::size_t{3}, std::size_t{5}}) {
    const FitSamples mirrored = gather_fit_samples(half, "auv", dof, 1, RunSelection{}, mirror);
    const FitSamples explicit_runs = gather_fit_samples(whole, "auv", dof, 1, RunSelection{});
    ASSERT_EQ(mirrored.x.size(), 9u);  // v = 0 is its own image
    ASSERT_EQ(explicit_runs.x.size(), 9u);
    EXPECT_EQ(std::count(mirrored.mirrored.begin(), mirrored.mirrored.end(), true), 4);
    const DampingLawFit a = fit_damping_law(spec, mirrored.x, mirrored.y);
    const DampingLawFit b = fit_damping_law(spec, explicit_runs.x, explicit_runs.y);
    for (std::size_t t = 0; t < spec.terms.size(); ++t)
      EXPECT_NEAR(a.coefficients[t], b.coefficients[t], 1e-9 * (1.0 + std::abs(b.coefficients[t]))) << dof << " " << t;
  }
  // The half-plane fit alone is another fit (the noise is not odd): the images matter.
  const FitSamples alone = gather_fit_samples(half, "auv", 1, 1, RunSelection{});
  const FitSamples mirrored = gather_fit_samples(half, "auv", 1, 1, RunSelection{}, mirror);
  EXPECT_GT(std::abs(fit_damping_law(spec, alone.x, alone.y).coefficients[0] -
                     fit_damping_law(spec, mirrored.x, mirrored.y).coefficients[0]),
            1e-4);
}

TEST(FitRuns, MirrorImagesMapKeysAndForcesAndLeaveMeasuredRunsAlone) {
  TempDir dir;
  RunDatabase db(dir / "db");
  db.import({run_file(1, 0.5, 0.1, 0.2, 1.0, 2.0, 3.0, -0.7), run_file(2, 0.5, -0.1, -0.2, -1.5, -2.5, -3.5),
             run_file(3, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0)},
            ImportPolicy{});
  std::size_t skipped = 0;
  const auto runs = db.runs();
  const auto all = with_mirror_images(runs, make_mirror_spec({"v"}, {}), &skipped);
  // Runs 1 and 2 are each other's images (both measured: kept as measured);
  // run 3 is on the plane. Nothing is added.
  EXPECT_EQ(all.size(), 3u);
  EXPECT_EQ(skipped, 2u);

  const auto top_bottom = with_mirror_images({runs.front()}, make_mirror_spec({"w"}, {}));
  ASSERT_EQ(top_bottom.size(), 1u);  // w = p = q = 0: on the x-y plane

  const auto fore_aft = with_mirror_images({runs.back()}, make_mirror_spec({"u"}, {}));
  ASSERT_EQ(fore_aft.size(), 2u);
  const StoredRun& image = fore_aft[1];
  const StoredRun& run = fore_aft[0];
  EXPECT_EQ(image.id, run.id);
  EXPECT_EQ(image.key.nu_b[0], -run.key.nu_b[0]);                      // u -> -u
  EXPECT_EQ(image.key.nu_b[1], run.key.nu_b[1]);                       // v kept
  EXPECT_EQ(image.key.nu_b[5], -run.key.nu_b[5]);                      // r -> -r
  EXPECT_EQ(image.tau_b[0]->value.total, -run.tau_b[0]->value.total);  // X -> -X
  EXPECT_EQ(image.tau_b[1]->value.total, run.tau_b[1]->value.total);   // Y kept
  EXPECT_EQ(image.tau_b[3]->value.total, run.tau_b[3]->value.total);   // K kept
  EXPECT_EQ(image.tau_b[5]->value.total, -run.tau_b[5]->value.total);  // N -> -N

  // Two planes: the images in each and in both.
  const auto both = with_mirror_images({runs.front()}, make_mirror_spec({"v", "u"}, {}));
  EXPECT_EQ(both.size(), 4u);
  EXPECT_EQ(make_mirror_spec({"v", "u"}, {"current_v"}).text(), "u,v/current_v");
  EXPECT_EQ(parse_mirror_spec("u,v/current_v").text(), "u,v/current_v");
  EXPECT_THROW(make_mirror_spec({"v", "v"}, {}), InputError);
  EXPECT_THROW(make_mirror_spec({"q"}, {}), InputError);
  EXPECT_THROW(make_mirror_spec({}, {"current_v"}), InputError);
}

TEST(FitRuns, AStaleFitIsMadeAgainFromItsRecord) {
  TempDir dir;
  RunDatabase db(dir / "db");
  for (int i = 0; i < 5; ++i) {
    const double u = 0.1 * (i + 1);
    db.import({run_file(i + 1, u, 0.0, 0.0, 0.0, 0.0, 0.0, -3.0 * u * u)}, ImportPolicy{});
  }
  const DampingLawSpec spec = parse_damping_terms("u|u|");
  const RunSelection selection = parse_selection({"u>=0.2"}, {});
  const FitSamples samples = gather_fit_samples(db, "auv", 0, 0, selection);
  ASSERT_EQ(samples.runs.size(), 4u);
  const DampingLawFit fit = fit_damping_law(spec, samples.x, samples.y);
  EXPECT_NEAR(fit.coefficients[0], -3.0, 1e-9);
  db.save_fit(make_fit_record("law", "auv", 0, spec, fit, selection.text(), {}, samples, samples.run_ids));

  // The run at u = 0.3 is corrected (re-imported with --replace): the fit goes stale.
  ImportBatch corrected = run_file(3, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, -0.36);
  corrected.source.settings_key = "id=3 corrected";
  ImportPolicy replace;
  replace.replace = true;
  db.import({corrected}, replace);
  ASSERT_TRUE(db.fits().front().stale);

  const FitRecord again = refit(db, db.fits().front());
  EXPECT_EQ(again.name, "law");
  EXPECT_EQ(again.run_filter, "u>=0.2");
  EXPECT_EQ(again.run_ids.size(), 4u);
  // The least-squares u|u| coefficient of the corrected data, by hand.
  double num = 0.0, den = 0.0;
  for (const auto& run : db.runs()) {
    const double u = run.key.nu_b[0];
    if (u < 0.2 - 1e-12) continue;
    num += u * u * run.tau_b[0]->value.total;
    den += u * u * u * u;
  }
  EXPECT_NEAR(again.coefficients[0].value, num / den, 1e-9);
  EXPECT_GT(std::abs(again.coefficients[0].value + 3.0), 1e-3);
  db.save_fit(again, RunDatabase::NameTaken::Replace);
  EXPECT_FALSE(db.fits().front().stale);
  EXPECT_NEAR(db.fits().front().coefficients[0].value, num / den, 1e-9);

  // Its runs gone: refused with the fit's name.
  std::vector<std::int64_t> ids;
  for (const auto& run : db.runs()) ids.push_back(run.id);
  db.delete_runs(ids);
  try {
    (void)refit(db, db.fits().front());
    FAIL();
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("fit 'law'"), std::string::npos) << error.what();
  }
}

TEST(FitRuns, RunsWhoseHistoriesDidNotConvergeAreNamed) {
  std::vector<StoredRun> runs(3);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    runs[i].id = static_cast<std::int64_t>(i + 1);
    runs[i].tau_b[0] = StoredForce{};
  }
  EXPECT_EQ(unconverged_runs_warning(runs, 0), "");
  runs[1].tau_b[0]->statistics = StoredStatistics{};
  EXPECT_EQ(unconverged_runs_warning(runs, 0), "");
  runs[1].tau_b[0]->statistics->flags = {"drifting", "too-few-effective-samples"};
  const std::string warning = unconverged_runs_warning(runs, 0);
  EXPECT_NE(warning.find("1 of the 3 runs"), std::string::npos) << warning;
  EXPECT_NE(warning.find("run 2 (drifting,too-few-effective-samples)"), std::string::npos) << warning;
  EXPECT_EQ(unconverged_runs_warning(runs, 1), "");  // another component
}

}  // namespace
}  // namespace hydrocoef
