#include "eval/conditions.h"

#include <gtest/gtest.h>

#include "common/error.h"

namespace parkloc::eval {
namespace {

using Names = std::vector<std::string>;

TEST(Conditions, FromMetaJsonInSeveralShapes) {
  EXPECT_EQ(sequenceConditions(R"({"condition": "weak_light"})"), Names({"weak_light"}));
  EXPECT_EQ(sequenceConditions(R"({"condition": "bright+blur"})"), Names({"blur", "bright"}));
  EXPECT_EQ(sequenceConditions(R"({"conditions": ["dim", "motion_blur"]})"),
            Names({"blur", "weak_light"}));
  EXPECT_EQ(sequenceConditions(R"({"condition": {"light": "bright", "blur": false}})"),
            Names({"bright"}));
  EXPECT_EQ(sequenceConditions(R"({"condition": {"light": "weak", "blur": 1.5}})"),
            Names({"blur", "weak_light"}));
  EXPECT_EQ(sequenceConditions(R"({"condition": "normal"})"), Names());
  EXPECT_EQ(sequenceConditions("{}"), Names());
}

TEST(Conditions, MalformedMetaThrowsWithTheFileName) {
  try {
    sequenceConditions("{oops", "seq1/meta.json");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("seq1/meta.json"), std::string::npos);
  }
}

TEST(Conditions, RotationBins) {
  EXPECT_EQ(rotationSubset(0.0), std::nullopt);
  EXPECT_EQ(rotationSubset(29.0), std::nullopt);
  EXPECT_EQ(rotationSubset(31.0), "rot45");
  EXPECT_EQ(rotationSubset(-50.0), "rot45");
  EXPECT_EQ(rotationSubset(95.0), "rot90");
  EXPECT_EQ(rotationSubset(-80.0), "rot90");
  EXPECT_EQ(rotationSubset(135.0), std::nullopt);
  EXPECT_EQ(rotationSubset(140.0), std::nullopt);
  EXPECT_EQ(rotationSubset(152.0), "rot180");
  EXPECT_EQ(rotationSubset(-175.0), "rot180");
  EXPECT_EQ(rotationSubset(540.0), "rot180");
}

}  // namespace
}  // namespace parkloc::eval
