#include "io/sequence_conditions.h"

#include <gtest/gtest.h>

#include "common/error.h"

namespace parkloc::io {
namespace {

using Names = std::vector<std::string>;

TEST(SequenceConditions, FromMetaJsonInSeveralShapes) {
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

TEST(SequenceConditions, MalformedMetaThrowsWithTheFileName) {
  try {
    sequenceConditions("{oops", "seq1/meta.json");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("seq1/meta.json"), std::string::npos);
  }
}

}  // namespace
}  // namespace parkloc::io
