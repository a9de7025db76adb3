#include "src/pipeline/fit_runs.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <tuple>

#include "src/core/error.hpp"
#include "src/core/names.hpp"
#include "src/core/sign_convention.hpp"
#include "src/core/text.hpp"

namespace hydrocoef {
namespace {

/// A key as the store tells runs apart: body, velocity and the canonical
/// disturbances (mirror images negate values exactly, and -0 equals 0).
using KeyIdentity = std::tuple<std::string, std::array<double, 6>, std::string>;
KeyIdentity identity(const RunKey& key) { return {key.body, key.nu_b, disturbance_signature(key.disturbances)}; }

/// The fields between commas as strings; none for "".
std::vector<std::string> comma_list(std::string_view text) {
  std::vector<std::string> out;
  if (text.empty()) return out;
  for (const auto field : split(text, ',')) out.emplace_back(field);
  return out;
}

}  // namespace

std::string MirrorSpec::text() const {
  if (planes.empty()) return {};
  return join(planes, ",") + (odd.empty() ? "" : "/" + join(odd, ","));
}

std::vector<std::vector<BodyMirror>> MirrorSpec::images() const {
  std::vector<BodyMirror> single;
  for (const auto& plane : planes) single.push_back(parse_body_mirror(plane, odd));
  // Every non-empty subset of the planes: the reflections and their compositions.
  std::vector<std::vector<BodyMirror>> out;
  for (unsigned mask = 1; mask < (1u << single.size()); ++mask) {
    std::vector<BodyMirror> chain;
    for (std::size_t i = 0; i < single.size(); ++i)
      if (mask & (1u << i)) chain.push_back(single[i]);
    out.push_back(std::move(chain));
  }
  return out;
}

MirrorSpec make_mirror_spec(const std::vector<std::string>& planes, const std::vector<std::string>& odd) {
  MirrorSpec spec;
  std::set<std::string> seen;
  for (const auto& plane : planes) {
    (void)parse_body_mirror(plane);  // u, v or w; InputError otherwise
    if (!seen.insert(plane).second) throw InputError("--mirror " + plane + " given twice; expected each plane once");
    spec.planes.push_back(plane);
  }
  std::sort(spec.planes.begin(), spec.planes.end());
  if (spec.planes.empty() && !odd.empty())
    throw InputError("--mirror-odd without --mirror; expected --mirror u, v or w with it");
  std::set<std::string> odd_seen;
  for (const auto& name : odd) {
    check_name(NameKind::Parameter, name, {}, "--mirror-odd");
    if (odd_seen.insert(name).second) spec.odd.push_back(name);
  }
  std::sort(spec.odd.begin(), spec.odd.end());
  return spec;
}

MirrorSpec parse_mirror_spec(std::string_view text) {
  if (text.empty()) return {};
  const auto slash = text.find('/');
  return make_mirror_spec(comma_list(text.substr(0, slash)), slash == std::string_view::npos
                                                                 ? std::vector<std::string>{}
                                                                 : comma_list(text.substr(slash + 1)));
}

std::vector<StoredRun> selected_runs(RunDatabase& database, const RunFilter& filter, const RunSelection& selection) {
  auto runs = database.runs(filter);
  std::erase_if(runs, [&](const StoredRun& run) { return !selection.matches(run.key, run.id); });
  return runs;
}

std::vector<StoredRun> with_mirror_images(const std::vector<StoredRun>& runs, const MirrorSpec& mirror,
                                          std::size_t* skipped) {
  std::vector<StoredRun> out = runs;
  std::set<KeyIdentity> measured, present;
  for (const auto& run : runs) measured.insert(identity(run.key));
  present = measured;
  std::size_t left_out = 0;
  for (const auto& chain : mirror.images()) {
    for (std::size_t i = 0; i < runs.size(); ++i) {
      StoredRun image = runs[i];
      std::array<double, 6> signs{1, 1, 1, 1, 1, 1};
      for (const auto& reflection : chain) {
        image.key = reflection.key(image.key);
        const auto s = reflection.signs();
        for (std::size_t c = 0; c < 6; ++c) signs[c] *= s[c];
      }
      const KeyIdentity key = identity(image.key);
      if (!present.insert(key).second) {
        // Its own image (on the plane), or an image where a run was measured.
        if (measured.count(key) && key != identity(runs[i].key)) ++left_out;
        continue;
      }
      for (std::size_t c = 0; c < 6; ++c) {
        auto& force = image.tau_b[c];
        if (!force || signs[c] > 0) continue;
        force->value.total = -force->value.total;
        if (force->value.pressure) *force->value.pressure = -*force->value.pressure;
        if (force->value.viscous) *force->value.viscous = -*force->value.viscous;
        if (force->statistics) force->statistics->values.drift = -force->statistics->values.drift;
      }
      // The moment reference point is mirrored with the body.
      for (const auto& reflection : chain)
        image.reference_point_b[reflection.axis] = -image.reference_point_b[reflection.axis];
      image.surface.reset();
      out.push_back(std::move(image));
    }
  }
  if (skipped) *skipped = left_out;
  return out;
}

FitSamples gather_fit_samples(RunDatabase& database, const std::string& body, std::size_t dof, std::size_t variable,
                              const RunSelection& selection, const MirrorSpec& mirror) {
  RunFilter filter;
  filter.body = body;
  filter.with_force = dof;
  FitSamples out;
  out.runs = database.runs(filter);
  std::erase_if(out.runs, [&](const StoredRun& run) { return !selection.matches(run.key, run.id); });
  if (out.runs.empty())
    throw InputError("no runs of body '" + body + "' with " + std::string(kForceNames[dof]) +
                     (selection.empty() ? "" : " where " + selection.text()) + " in " + database.path().string());
  std::set<SignConvention> conventions;
  for (const auto& run : out.runs) conventions.insert(run.tau_b[dof]->sign);
  out.sign = conventions.size() == 1 ? *conventions.begin() : SignConvention::OnBody;
  const auto all = with_mirror_images(out.runs, mirror, &out.images_skipped);
  for (std::size_t i = 0; i < all.size(); ++i) {
    const auto& force = *all[i].tau_b[dof];
    out.keys.push_back(all[i].key);
    out.x.push_back(all[i].key.nu_b[variable]);
    out.y.push_back(to_convention(force.value.total, force.sign, out.sign));
    out.sigma.push_back(force.standard_uncertainty());
    out.run_ids.push_back(all[i].id);
    out.mirrored.push_back(i >= out.runs.size());
  }
  return out;
}

std::vector<double> fit_weights(const FitSamples& samples, bool wanted, std::string* note) {
  if (!wanted) return {};
  const auto stated = static_cast<std::size_t>(
      std::count_if(samples.sigma.begin(), samples.sigma.end(), [](double s) { return s > 0.0 && std::isfinite(s); }));
  if (stated == samples.sigma.size() && stated > 0) return samples.sigma;
  if (stated > 0 && note)
    *note = std::to_string(samples.sigma.size() - stated) + " of the " + std::to_string(samples.sigma.size()) +
            " runs state no uncertainty (no mean over a force history, import --uncertainty or gci): fitted "
            "unweighted";
  return {};
}

std::string unconverged_runs_warning(const std::vector<StoredRun>& runs, std::size_t dof) {
  std::string list;
  std::size_t count = 0;
  for (const auto& run : runs) {
    const auto& force = run.tau_b[dof];
    if (!force || !force->statistics || force->statistics->flags.empty()) continue;
    if (count++ < 10)
      list += (list.empty() ? "" : "; ") + std::string("run ") + std::to_string(run.id) + " (" +
              join(force->statistics->flags, ",") + ")";
  }
  if (count == 0) return {};
  if (count > 10) list += "; and " + std::to_string(count - 10) + " more";
  return std::to_string(count) + " of the " + std::to_string(runs.size()) +
         " runs are means over force histories that did not converge: " + list +
         "; 'hydrocoef runs show ID' gives the window, or leave them out with --exclude-run ID";
}

FitRecord make_fit_record(const std::string& name, const std::string& body, std::size_t dof, const DampingLawSpec& spec,
                          const DampingLawFit& fit, const std::string& selection_text, const MirrorSpec& mirror,
                          const FitSamples& samples, const std::vector<std::int64_t>& run_ids) {
  FitRecord record;
  record.name = name;
  record.body = body;
  record.dof = std::string(kForceNames[dof]);
  record.variable = spec.variable;
  record.terms = format_damping_terms(spec);
  record.loss = fit.loss;
  record.run_filter = selection_text;
  record.mirror = mirror.text();
  record.sign = samples.sign;
  record.n = fit.n;
  record.rmse = fit.rmse;
  record.r2 = fit.r2;
  record.weighting = fit.weighted ? "uncertainty" : "none";
  if (std::isfinite(fit.chi2_reduced)) record.chi2_reduced = fit.chi2_reduced;
  if (std::all_of(fit.covariance.begin(), fit.covariance.end(), [](double c) { return std::isfinite(c); }))
    record.covariance = fit.covariance;
  for (std::size_t k = 0; k < spec.terms.size(); ++k) {
    FitRecord::Coefficient c{term_name(spec.terms[k], spec.variable), fit.coefficients[k], std::nullopt};
    if (std::isfinite(fit.std_errors[k])) c.std_error = fit.std_errors[k];
    record.coefficients.push_back(c);
  }
  std::set<std::int64_t> unique(run_ids.begin(), run_ids.end());
  record.run_ids.assign(unique.begin(), unique.end());
  return record;
}

FitRecord refit(RunDatabase& database, const FitRecord& record) {
  const DampingLawSpec spec = parse_damping_terms(record.terms);
  const LossOptions options = parse_loss(record.loss);
  const auto dof = force_index(record.dof);
  const auto variable = velocity_index(spec.variable);
  if (!dof || !variable) throw InputError("fit '" + record.name + "': unknown component " + record.dof);
  const RunSelection selection = parse_selection_text(record.run_filter);
  const MirrorSpec mirror = parse_mirror_spec(record.mirror);
  FitSamples samples;
  try {
    samples = gather_fit_samples(database, record.body, *dof, *variable, selection, mirror);
  } catch (const InputError& error) {
    throw InputError("fit '" + record.name + "' cannot be made again: " + error.what() +
                     "; delete it or import runs that its selection picks");
  }
  const DampingLawFit fit =
      fit_damping_law(spec, samples.x, samples.y, options, fit_weights(samples, record.weighting != "none"));
  return make_fit_record(record.name, record.body, *dof, spec, fit, record.run_filter, mirror, samples,
                         samples.run_ids);
}

}  // namespace hydrocoef
