// Model templates (src/derivatives/model_templates.hpp): every template
// parses, states its variables and source, and a fit of exact runs generated
// from random coefficients of its terms recovers them; the term lists are the
// sources' (checked for the ones that define each template); an unknown name
// or output is refused listing what there is.
#include "src/derivatives/model_templates.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "src/derivatives/derivative_fit.hpp"
#include "tests/derivatives/synthetic_model.hpp"
#include "tests/support/expect_input_error.hpp"

namespace hydrocoef {
namespace {

using test::expect_input_error;

// Ranges for every name the templates use: forward speed well away from
// zero for the AUV's u terms, the others on both sides of zero.
test::Ranges ranges_for(const std::vector<std::string>& names) {
  test::Ranges out;
  for (const auto& name : names) {
    if (name == "u") {
      out[name] = {1.0, 2.5};
    } else if (name == "delta" || name == "delta_r" || name == "delta_s") {
      out[name] = {-0.6, 0.6};
    } else {
      out[name] = {-0.4, 0.4};
    }
  }
  return out;
}

TEST(ModelTemplates, EveryTemplateParsesAndIsRecoveredFromItsOwnRuns) {
  std::set<std::string> seen;
  std::uint64_t seed = 1;
  for (const ModelTemplate& t : model_templates()) {
    const std::string label = std::string(t.name) + " " + std::string(t.output);
    EXPECT_TRUE(seen.insert(label).second) << label << " twice";
    EXPECT_FALSE(t.variables.empty()) << label;
    EXPECT_FALSE(t.source.empty()) << label;
    const std::vector<Term> terms = model_template_terms(t.name, t.output);
    ASSERT_FALSE(terms.empty()) << label;
    // The list is written in canonical form.
    EXPECT_EQ(format_terms(terms), std::string(t.terms)) << label;

    std::mt19937_64 random(seed++);
    std::uniform_real_distribution<double> coefficient(-500.0, 500.0);
    std::vector<double> truth;
    for (std::size_t k = 0; k < terms.size(); ++k) truth.push_back(coefficient(random));
    const auto points = test::latin_hypercube(ranges_for(term_variables(terms)), 4 * terms.size() + 20, seed);
    const DerivativeFit fit = fit_derivatives(t.output, terms, test::exact_runs(terms, truth, points));
    for (std::size_t k = 0; k < terms.size(); ++k)
      EXPECT_NEAR(fit.coefficients[k], truth[k], 1e-9 * std::abs(truth[k])) << label << ": " << terms[k].text();
  }
  EXPECT_EQ(seen.size(), 15u);
}

TEST(ModelTemplates, TermListsAreTheSourcesOnes) {
  // Fossen's mariner.m (Chislett & Strom-Tejsen 1965): X = Xu u + Xuu u^2 +
  // Xuuu u^3 + Xvv v^2 + Xrr r^2 + Xrv r v + Xdd d^2 + Xudd u d^2 + Xvd v d +
  // Xuvd u v d, u the surge perturbation.
  EXPECT_EQ(find_model_template("abkowitz", "X").terms,
            "du, du^2, du^3, v^2, r^2, v*r, delta^2, du*delta^2, v*delta, du*v*delta");
  EXPECT_EQ(model_template_terms("abkowitz", "Y").size(), 15u);
  EXPECT_EQ(find_model_template("abkowitz", "N").terms, find_model_template("abkowitz", "Y").terms);
  // Prestero (2001): Y = Yvv v|v| + Yrr r|r| + Yuv uv + Yur ur + Ywp wp + Ypq pq + Yuudr u^2 dr.
  EXPECT_EQ(find_model_template("auv", "Y").terms, "v*|v|, r*|r|, u*v, u*r, w*p, p*q, u^2*delta_r");
  EXPECT_EQ(find_model_template("auv", "K").terms, "p*|p|");
  // Yasukawa & Yoshimura (2015): X'_H = -R'_0 + X'vv v^2 + X'vr v r + X'rr r^2 + X'vvvv v^4.
  EXPECT_EQ(find_model_template("mmg", "X").terms, "1, v^2, v*r, r^2, v^4");
  EXPECT_EQ(find_model_template("mmg", "Y").terms, "v, r, v^3, v^2*r, v*r^2, r^3");
  EXPECT_EQ(find_model_template("mmg-beta", "X").terms, "1, beta^2, beta*r, r^2, beta^4");
  EXPECT_EQ(model_template_terms("mmg-beta", "N")[3].powers(), (std::map<std::string, int>{{"beta", 2}, {"r", 1}}));
}

TEST(ModelTemplates, RefusesUnknownNamesAndOutputsListingWhatThereIs) {
  expect_input_error(
      [] { find_model_template("abkowits", "Y"); },
      {"no model template named abkowits", "abkowitz (X Y N)", "auv (X Y Z K M N)", "mmg (X Y N)", "mmg-beta (X Y N)"});
  expect_input_error([] { model_template_terms("mmg", "Z"); },
                     {"the template mmg has no output Z", "expected one of abkowitz (X Y N); auv"});
}

}  // namespace
}  // namespace hydrocoef
