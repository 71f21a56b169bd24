#include "io/anchors_csv.h"

#include <gtest/gtest.h>

#include "common/error.h"
#include "test_dir.h"

namespace parkloc::io {
namespace {

using AnchorsCsv = testing::TempDirTest;

TEST_F(AnchorsCsv, ReadsRowsAndSkipsComments) {
  const auto path = write("a.csv", "# surveyed\ntext,x,y\nB001, 7.75 ,11.88\n\nB015,42.75,-1e-1\n");
  const auto anchors = loadAnchors(path);
  ASSERT_EQ(anchors.size(), 2u);
  EXPECT_EQ(anchors[0].text, "B001");
  EXPECT_DOUBLE_EQ(anchors[0].position.x(), 7.75);
  EXPECT_DOUBLE_EQ(anchors[1].position.y(), -0.1);
}

TEST_F(AnchorsCsv, RejectsBadInputWithTheFileAndLine) {
  EXPECT_THROW(loadAnchors(path("missing.csv")), InputError);
  EXPECT_THROW(loadAnchors(write("h.csv", "name,x,y\nB001,1,2\n")), InputError);
  EXPECT_THROW(loadAnchors(write("e.csv", "")), InputError);
  EXPECT_THROW(loadAnchors(write("d.csv", "text,x,y\nB001,1,2\nB001,3,4\n")), InputError);
  try {
    loadAnchors(write("n.csv", "text,x,y\nB001,1,nan\n"));
    FAIL() << "a NaN coordinate was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos) << e.what();
  }
  EXPECT_THROW(loadAnchors(write("c.csv", "text,x,y\nB001,1\n")), InputError);
}

}  // namespace
}  // namespace parkloc::io
