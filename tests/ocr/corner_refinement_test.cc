// The corner fit finds the text's ink, and the spotter keeps a fit only when it is plausible
// for the box it refines.
#include "ocr/corner_refinement.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <optional>
#include <thread>
#include <vector>

#include "synthetic_text.h"

namespace parkloc::ocr {
namespace {

Quad box(float x0, float y0, float x1, float y1) {
  return {cv::Point2f(x0, y0), cv::Point2f(x1, y0), cv::Point2f(x1, y1), cv::Point2f(x0, y1)};
}

TEST(PlausibleRefinement, ATightenedBoxIsKept) {
  const Quad detected = box(100, 100, 300, 150);
  EXPECT_TRUE(plausibleRefinement(detected, box(110, 110, 290, 140)));
  EXPECT_TRUE(plausibleRefinement(detected, box(95, 95, 305, 155)));  // a little larger
}

TEST(PlausibleRefinement, AFitThatLostPartOfTheTextIsNot) {
  // Blurred ink broken in two: the fit covers the left half only.
  const Quad detected = box(100, 100, 300, 150);
  EXPECT_FALSE(plausibleRefinement(detected, box(105, 105, 200, 145)));
  EXPECT_TRUE(plausibleRefinement(detected, box(105, 105, 250, 145)));  // 72 % kept
  CornerRefinementOptions lenient;
  lenient.min_length_share = 0.f;
  EXPECT_TRUE(plausibleRefinement(detected, box(105, 105, 200, 145), lenient));
}

TEST(PlausibleRefinement, AFitOutsideTheGrownBoxIsNot) {
  const Quad detected = box(100, 100, 300, 150);
  EXPECT_FALSE(plausibleRefinement(detected, box(100, 100, 300, 200)));  // runs off below
  EXPECT_FALSE(plausibleRefinement(detected, box(200, 100, 400, 150)));  // shifted along
}

// Yellow paint on grey concrete whose glyph tops touch a car's dark bumper: the grey levels
// split bumper from floor and leave the paint, about as bright as the concrete, with the
// floor. Returns the image and the ink's box.
struct BumperScene {
  cv::Mat image;
  cv::Rect ink;
};
BumperScene yellowTextUnderABumper() {
  const cv::Scalar concrete(150, 150, 150), yellow(40, 170, 200);  // BGR, luminance ~155
  const cv::Mat line = testing::renderTextLine("P2-069", 40, 0, yellow, concrete);
  BumperScene scene;
  scene.image = cv::Mat(160, line.cols + 120, CV_8UC3, concrete);
  scene.ink = cv::Rect(60, 70, line.cols, line.rows);
  // The bumper's shadow reaches 2 px into the glyphs' tops, across the whole crop.
  scene.image(cv::Rect(0, 0, scene.image.cols, 72)).setTo(cv::Scalar(25, 25, 25));
  line(cv::Rect(0, 2, line.cols, line.rows - 2))
      .copyTo(scene.image(cv::Rect(60, 72, line.cols, line.rows - 2)));
  return scene;
}

double meanCornerDistance(const Quad& a, const Quad& b) {
  double sum = 0.0;
  for (int i = 0; i < 4; ++i) sum += std::hypot(a[i].x - b[i].x, a[i].y - b[i].y);
  return sum / 4.0;
}

TEST(RefineInCrop, YellowPaintBesideADarkShadowIsFoundByItsColour) {
  const BumperScene scene = yellowTextUnderABumper();
  const cv::Rect& r = scene.ink;
  // A detector box loose by 8 px on every side.
  const Quad detected = box(r.x - 8, r.y - 8, r.x + r.width + 8, r.y + r.height + 8);
  // The visible ink: its top two rows lie in the shadow.
  const Quad truth = box(r.x - 0.5f, r.y + 1.5f, r.x + r.width - 0.5f, r.y + r.height - 0.5f);

  CornerRefinementOptions grey_only;
  grey_only.colour_fallback = false;
  EXPECT_FALSE(refineInCrop(scene.image, detected, grey_only).has_value());

  const auto fit = refineInCrop(scene.image, detected);
  ASSERT_TRUE(fit.has_value());
  EXPECT_LT(meanCornerDistance(*fit, truth), 2.5);
  EXPECT_GT(meanCornerDistance(detected, truth), 6.0);
}

TEST(RefineInCrop, ThreadsThatFitByColourAtOnceGetTheSameFit) {
  // Under ctest each test runs in a process of its own, so these threads make the process's
  // first Lab conversions together: OpenCV builds its tables then, and builds them once
  // (buildColourTables).
  const BumperScene scene = yellowTextUnderABumper();
  const cv::Rect& r = scene.ink;
  const Quad detected = box(r.x - 8, r.y - 8, r.x + r.width + 8, r.y + r.height + 8);
  std::vector<std::optional<Quad>> fits(4);
  std::vector<std::thread> threads;
  for (auto& fit : fits) threads.emplace_back([&] { fit = refineInCrop(scene.image, detected); });
  for (auto& t : threads) t.join();
  const auto alone = refineInCrop(scene.image, detected);
  ASSERT_TRUE(alone.has_value());
  for (const auto& fit : fits) {
    ASSERT_TRUE(fit.has_value());
    EXPECT_LT(meanCornerDistance(*fit, *alone), 1e-4);
  }
}

// White digits on grey concrete inside a painted frame (a white line a tenth of the text's
// height, a quarter of it clear all round), or on a dark blue patch that reaches 20 px out.
struct BackedScene {
  cv::Mat image;
  cv::Rect ink, backing;
};
BackedScene numberOn(bool patch) {
  const cv::Scalar concrete(140, 140, 140), white(235, 235, 235), blue(150, 60, 30);
  const cv::Scalar behind = patch ? blue : concrete;
  const cv::Mat line = testing::renderTextLine("2047", 40, 0, white, behind);
  BackedScene scene;
  scene.image = cv::Mat(200, line.cols + 200, CV_8UC3, concrete);
  scene.ink = cv::Rect(100, 80, line.cols, line.rows);
  scene.backing = cv::Rect(80, 64, line.cols + 40, line.rows + 32);
  if (patch)
    scene.image(scene.backing).setTo(blue);
  else
    cv::rectangle(scene.image, scene.backing, white, 4);
  line.copyTo(scene.image(scene.ink));
  return scene;
}

TEST(RefineInCrop, ANumberInsideAFrameOrOnAPatchIsFittedToItsGlyphs) {
  for (const bool patch : {false, true}) {
    SCOPED_TRACE(patch ? "patch" : "frame");
    const BackedScene scene = numberOn(patch);
    const cv::Rect& b = scene.backing;
    // The detector boxed the backing, a few pixels loose.
    const Quad detected = box(b.x - 6, b.y - 6, b.x + b.width + 6, b.y + b.height + 6);
    const cv::Rect& r = scene.ink;
    const Quad glyphs = box(r.x - 0.5f, r.y - 0.5f, r.x + r.width - 0.5f, r.y + r.height - 0.5f);
    const Quad backing = box(b.x - 0.5f, b.y - 0.5f, b.x + b.width - 0.5f, b.y + b.height - 0.5f);

    const auto fit = refineInCrop(scene.image, detected);
    ASSERT_TRUE(fit.has_value());
    EXPECT_LT(meanCornerDistance(*fit, glyphs), 3.0);

    // Without the rule the backing's own box is the fit.
    CornerRefinementOptions backing_kept;
    backing_kept.frames = backing_kept.patches = false;
    const auto kept = refineInCrop(scene.image, detected, backing_kept);
    ASSERT_TRUE(kept.has_value());
    EXPECT_LT(meanCornerDistance(*kept, backing), 3.0);
  }
}

TEST(RefineInCrop, PlainGlyphsAreNotTakenForABacking) {
  // Bold digits whose counters are holes: no backing, the fit is the glyphs' box either way.
  const cv::Scalar concrete(140, 140, 140), white(235, 235, 235);
  const cv::Mat line = testing::renderTextLine("808", 40, 60, white, concrete);
  const Quad detected = box(50, 50, line.cols - 50, line.rows - 50);
  CornerRefinementOptions no_rule;
  no_rule.frames = no_rule.patches = false;
  const auto with_rule = refineInCrop(line, detected),
             without = refineInCrop(line, detected, no_rule);
  ASSERT_TRUE(with_rule.has_value());
  ASSERT_TRUE(without.has_value());
  EXPECT_LT(meanCornerDistance(*with_rule, *without), 0.5);
}

TEST(RefineInCrop, ColourlessBlankFloorGivesNoFit) {
  cv::Mat floor(120, 400, CV_8UC3, cv::Scalar(150, 150, 150));
  floor(cv::Rect(0, 0, 400, 40)).setTo(cv::Scalar(25, 25, 25));
  EXPECT_FALSE(refineInCrop(floor, box(100, 50, 300, 90)).has_value());
}

}  // namespace
}  // namespace parkloc::ocr
