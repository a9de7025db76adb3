// The selection language: each operator on velocity components and
// disturbances, ranges, exclusions, the canonical text round trip, and
// refusals that name the clause.
#include "src/core/run_selection.hpp"

#include <gtest/gtest.h>

#include "src/core/error.hpp"

namespace hydrocoef {
namespace {

// Built in one go: GCC 12 at -O3 raises a false -Wstringop-overflow on
// assigning "b" to a default-constructed key's body.
RunKey key(double u, double v, std::map<std::string, double> disturbances = {}) {
  return RunKey{"b", {u, v, 0, 0, 0, 0}, std::move(disturbances)};
}

bool selects(const std::vector<std::string>& where, const RunKey& k, std::int64_t id = 1,
             const std::vector<std::int64_t>& excluded = {}) {
  return parse_selection(where, excluded).matches(k, id);
}

TEST(RunSelection, Operators) {
  EXPECT_TRUE(selects({"u=0.1"}, key(0.1, 0)));
  EXPECT_TRUE(selects({"u=0.1"}, key(0.1 + 1e-12, 0)));
  EXPECT_FALSE(selects({"u=0.1"}, key(0.2, 0)));
  EXPECT_TRUE(selects({"u!=0.1"}, key(0.2, 0)));
  EXPECT_FALSE(selects({"u!=0.1"}, key(0.1, 0)));
  EXPECT_TRUE(selects({"v>=0"}, key(0, 0)));
  EXPECT_TRUE(selects({"v>=0"}, key(0, -1e-15)));  // within the tolerance of 0
  EXPECT_FALSE(selects({"v>=0"}, key(0, -0.05)));
  EXPECT_FALSE(selects({"v>0"}, key(0, 0)));
  EXPECT_TRUE(selects({"v>0"}, key(0, 0.05)));
  EXPECT_TRUE(selects({"u<0.3"}, key(0.2, 0)));
  EXPECT_FALSE(selects({"u<0.3"}, key(0.3, 0)));
  EXPECT_TRUE(selects({"u<=0.3"}, key(0.3, 0)));
  EXPECT_TRUE(selects({"u==0.3"}, key(0.3, 0)));
}

TEST(RunSelection, RangesIncludeBothEnds) {
  for (double u : {0.1, 0.2, 0.3}) EXPECT_TRUE(selects({"u=0.1:0.3"}, key(u, 0))) << u;
  for (double u : {0.0, 0.31, -0.1}) EXPECT_FALSE(selects({"u=0.1:0.3"}, key(u, 0))) << u;
  EXPECT_TRUE(selects({"v=-0.1:0.1"}, key(0, -0.1)));
}

TEST(RunSelection, ClausesCombineWithAnd) {
  EXPECT_TRUE(selects({"u>0", "v=0"}, key(0.1, 0)));
  EXPECT_FALSE(selects({"u>0", "v=0"}, key(0.1, 0.05)));
}

TEST(RunSelection, DisturbancesAbsentMatchNothing) {
  EXPECT_TRUE(selects({"current_v=0.05"}, key(0.1, 0, {{"current_v", 0.05}})));
  EXPECT_FALSE(selects({"current_v=0.05"}, key(0.1, 0)));
  EXPECT_FALSE(selects({"current_v!=0"}, key(0.1, 0)));
  EXPECT_TRUE(selects({"current_v!=0"}, key(0.1, 0, {{"current_v", 0.05}})));
}

TEST(RunSelection, ExcludedRunsAreLeftOut) {
  EXPECT_FALSE(selects({}, key(0.1, 0), 7, {7}));
  EXPECT_TRUE(selects({}, key(0.1, 0), 6, {7}));
  EXPECT_FALSE(selects({"u=0.1"}, key(0.1, 0), 7, {3, 7}));
}

TEST(RunSelection, CanonicalTextReadsBack) {
  const auto selection = parse_selection({"u>=0.1", "v=-0.1:0.1", "current_v!=0"}, {9, 7, 7});
  EXPECT_EQ(selection.text(), "u>=0.1 v=-0.1:0.1 current_v!=0 exclude-run 7 exclude-run 9");
  const auto back = parse_selection_text(selection.text());
  EXPECT_EQ(back.text(), selection.text());
  EXPECT_EQ(back.excluded_runs, (std::vector<std::int64_t>{7, 9}));
  EXPECT_TRUE(parse_selection_text("").empty());
}

TEST(RunSelection, RefusalsNameTheClause) {
  const auto message = [](const std::string& clause) {
    try {
      parse_selection_clause(clause);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message("v>=abc"), "--where 'v>=abc': found 'abc', expected a finite number");
  EXPECT_NE(message("u").find("expected NAME=VALUE"), std::string::npos);
  EXPECT_NE(message("=3").find("expected NAME=VALUE"), std::string::npos);
  EXPECT_NE(message("u=0.3:0.1").find("expected LOW <= HIGH"), std::string::npos);
  EXPECT_NE(message("u<0:1").find("a range only as NAME=LOW:HIGH"), std::string::npos);
  EXPECT_NE(message("a;b=1").find("velocity component"), std::string::npos);
  EXPECT_NE(message("u=inf").find("finite"), std::string::npos);
  EXPECT_THROW(parse_selection({}, {0}), InputError);
}

}  // namespace
}  // namespace hydrocoef
