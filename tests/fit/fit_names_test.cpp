// Fit names (src/fit/fit_names): a per-level fit's name can never be taken
// for a filtered fit's, and reads back to its level.
#include "src/fit/fit_names.hpp"

#include <gtest/gtest.h>

namespace hydrocoef {
namespace {

TEST(FitNames, FilteredAndPerLevelFitsHaveNamesOfDifferentShapes) {
  EXPECT_EQ(default_fit_name("asr-v", "X", "1,u,u|u|", ""), "asr-v:X(1,u,u|u|)");
  const std::string filtered = default_fit_name("asr-v", "X", "1,u,u|u|", "current_v=0.05");
  EXPECT_EQ(filtered, "asr-v:X(1,u,u|u|)@current_v=0.05");
  const std::string level = per_level_fit_name("asr-v:X(1,u,u|u|)", "current_v", 0.05);
  EXPECT_EQ(level, "asr-v:X(1,u,u|u|)[current_v=0.05]");
  // The filtered fit is no level of the pooled fit; the per-level one is.
  EXPECT_FALSE(fit_level(filtered, "asr-v:X(1,u,u|u|)"));
  const auto parsed = fit_level(level, "asr-v:X(1,u,u|u|)");
  ASSERT_TRUE(parsed);
  EXPECT_EQ(parsed->first, "current_v");
  EXPECT_EQ(parsed->second, 0.05);
  EXPECT_EQ(fit_family_name(level), "asr-v:X(1,u,u|u|)");
  EXPECT_EQ(fit_family_name(filtered), filtered);
  // Levels of a filtered fit.
  const std::string both = per_level_fit_name(filtered, "v", -0.1);
  EXPECT_EQ(both, "asr-v:X(1,u,u|u|)@current_v=0.05[v=-0.1]");
  EXPECT_EQ(fit_family_name(both), filtered);
  // Not levels: no '=', not a number, trailing text.
  for (const char* name : {"b[v]", "b[v=abc]", "b[v=1]x", "b[=1]", "b[v=1=2]"})
    EXPECT_FALSE(fit_level(name, "b")) << name;
  EXPECT_EQ(fit_family_name("[v=1]"), "[v=1]");
}

}  // namespace
}  // namespace hydrocoef
