#include "eval/photo_recall.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "common/error.h"

namespace parkloc::eval {
namespace {

namespace fs = std::filesystem;

// A folder holding labels.tsv with `text`.
std::string labelFolder(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / ("parkloc_photo_recall_" + name);
  fs::create_directories(dir);
  std::ofstream(dir / "labels.tsv") << text;
  return dir.string();
}

TEST(PhotoRecall, ReadsLabelsAndDropsTheParkingPrefix) {
  const auto photos =
      loadPhotoLabels(labelFolder("ok",
                                  "a.jpg\trepo\tpath/a.jpg\t[P]10|Theatre|[P]Carpark\n"
                                  "\n"
                                  "b.jpg\trepo\tpath/b.jpg\t[P]\xe7\x9a\x96"
                                  "A-195K9|X\r\n"));
  ASSERT_EQ(photos.size(), 2u);
  EXPECT_EQ(photos[0].file, "a.jpg");
  EXPECT_EQ(photos[0].tokens, (std::vector<std::string>{"10", "Theatre", "Carpark"}));
  // Non-ASCII and single-character tokens are listed but not scored.
  EXPECT_EQ(photos[1].tokens.size(), 2u);
  EXPECT_TRUE(scoredTokens(photos[1]).empty());
  EXPECT_EQ(scoredTokens(photos[0]).size(), 3u);
}

TEST(PhotoRecall, RejectsAMalformedLineNamingIt) {
  const std::string dir = labelFolder("bad", "a.jpg\trepo\tpath\tA|B\nb.jpg\trepo only\n");
  try {
    loadPhotoLabels(dir);
    FAIL() << "accepted a line of two fields";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("labels.tsv: line 2"), std::string::npos) << e.what();
  }
  EXPECT_THROW(loadPhotoLabels(labelFolder("empty", "")), InputError);
  EXPECT_THROW(loadPhotoLabels("/nonexistent/parkloc/photos"), IoError);
}

TEST(PhotoRecall, ATokenIsReadInsideAnyReadingIgnoringCase) {
  const std::vector<std::string> tokens{"Carpark", "10", "Retail", "Genexis"};
  // "CARPARK" inside a longer reading counts; "RETAI" is not "Retail"; "10" is in "B-104".
  EXPECT_EQ(tokensRead(tokens, {"the CARPARK entrance", "RETAI", "B-104"}), 2);
  EXPECT_EQ(tokensRead(tokens, {}), 0);
  PhotoRecall recall;
  recall.add(4, 2);
  recall.add(2, 1);
  EXPECT_EQ(recall.photos, 2);
  EXPECT_DOUBLE_EQ(recall.recall(), 0.5);
  EXPECT_DOUBLE_EQ(PhotoRecall{}.recall(), 0.0);
}

}  // namespace
}  // namespace parkloc::eval
