// Text a reader could not read is labelled "not legible" (ICDAR's don't care), not left out:
// a detector that still finds it is then neither rewarded nor counted wrong. Legible means
// tall enough, and 2 cycles per character surviving the pixel grid and the camera's blur.
#include "sim/legibility.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "sim/annotate.h"
#include "sim/renderer.h"
#include "sim_test_util.h"

namespace parkloc::sim {
namespace {

double readingLength(const geometry::TextPolygon& p) {
  return 0.5 * ((p[1] - p[0]).norm() + (p[2] - p[3]).norm());
}

// An axis-aligned text box, reading left to right, or turned to read downwards.
geometry::TextPolygon box(double length, double height, bool reads_down = false) {
  if (reads_down)
    return {Eigen::Vector2d(height, 0), Eigen::Vector2d(height, length), Eigen::Vector2d(0, length),
            Eigen::Vector2d(0, 0)};
  return {Eigen::Vector2d(0, 0), Eigen::Vector2d(length, 0), Eigen::Vector2d(length, height),
          Eigen::Vector2d(0, height)};
}

TEST(Legibility, SharpTextNeedsItsHeightAndFourPixelsPerCharacter) {
  // Without blur, 2 cycles per character pass the pixel grid from a pitch of 4 px on.
  const geometry::Rig rig = geometry::defaultRig();
  const Garage g = generateGarage(testing::smallSpec(), 5);
  const geometry::Pose2 pose(14.0, g.aisle_y[0] + 0.5, 0.0);
  AnnotateOptions options;
  int legible = 0, illegible = 0;
  for (const auto& camera : rig.cameras)
    for (const auto& l : annotateImage(g, 0, camera, pose, options)) {
      const double h = geometry::apparentHeightPx(l.polygon);
      const double pitch = readingLength(l.polygon) / characterCount(l.text);
      EXPECT_GE(h, options.min_labelled_height_px - 1e-9) << l.text;
      EXPECT_EQ(l.legible, h >= 8.0 && pitch >= 4.0) << l.text << " " << h << " " << pitch;
      (l.legible ? legible : illegible)++;
    }
  EXPECT_GT(legible, 0);
  EXPECT_GT(illegible, 0);  // far numbers along the aisle, seen edge-on
}

TEST(Legibility, ABlurredCameraLabelsFewerTextsLegible) {
  const geometry::Rig rig = geometry::defaultRig();
  const Garage g = generateGarage(testing::smallSpec(), 5);
  const geometry::Pose2 pose(14.0, g.aisle_y[0] + 0.5, 0.0);
  AnnotateOptions sharp, blurred;
  blurred.blur = {1.5, 9.0};
  for (const auto& camera : rig.cameras) {
    const auto a = annotateImage(g, 0, camera, pose, sharp);
    const auto b = annotateImage(g, 0, camera, pose, blurred);
    ASSERT_EQ(a.size(), b.size()) << camera.name;  // blur changes the flag, not what is labelled
    int lost = 0;
    for (size_t i = 0; i < a.size(); ++i) {
      EXPECT_FALSE(b[i].legible && !a[i].legible) << a[i].text;
      lost += a[i].legible && !b[i].legible;
    }
    if (camera.name == "right") {
      EXPECT_GT(lost, 0);
    }
  }
}

TEST(Legibility, MotionBlurSmearsAlongItsOwnDirectionOnly) {
  const ImageBlur motion{0.0, 9.0};  // a horizontal box of 9 px
  // 12 px tall, 24 px per character: legible reading across the smear (the glyph height
  // runs vertically), not when turned so that the 12 px run horizontally.
  EXPECT_TRUE(isLegible(box(96, 12), 4, motion));
  EXPECT_FALSE(isLegible(box(96, 12, true), 4, motion));
  // 12 px per character reading horizontally: the smear is longer than a cycle.
  EXPECT_FALSE(isLegible(box(48, 24), 4, motion));
  EXPECT_TRUE(isLegible(box(48, 24), 4, ImageBlur{}));
  // Below the height floor nothing is legible, however wide.
  EXPECT_FALSE(isLegible(box(400, 7.5), 4, ImageBlur{}));
}

TEST(Legibility, ModulationMatchesTheRenderersBlurOnASineGrating) {
  // The renderer's blur (Gaussian defocus, then a horizontal box) applied to a sine grating:
  // its measured amplitude is what blurModulation predicts.
  const ImageBlur blur{1.5, 7.0};
  for (const bool horizontal : {true, false})
    for (const double f : {0.03, 0.06, 0.1, 0.13}) {
      const int n = 512;
      cv::Mat img(n, n, CV_64F);
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
          img.at<double>(y, x) = std::sin(2.0 * M_PI * f * (horizontal ? x : y));
      cv::GaussianBlur(img, img, cv::Size(0, 0), blur.defocus_sigma_px);
      cv::blur(img, img, cv::Size(static_cast<int>(blur.motion_length_px), 1));
      // Amplitude by projection on sine and cosine over the image's middle, away from borders.
      double s = 0.0, c = 0.0;
      int count = 0;
      for (int k = n / 4; k < 3 * n / 4; ++k) {
        const double v = horizontal ? img.at<double>(n / 2, k) : img.at<double>(k, n / 2);
        s += v * std::sin(2.0 * M_PI * f * k);
        c += v * std::cos(2.0 * M_PI * f * k);
        ++count;
      }
      const double measured = 2.0 * std::hypot(s, c) / count;
      const Eigen::Vector2d direction = horizontal ? Eigen::Vector2d(1, 0) : Eigen::Vector2d(0, 1);
      EXPECT_NEAR(blurModulation(blur, direction, f), measured, 0.02)
          << (horizontal ? "horizontal" : "vertical") << " f = " << f;
    }
  EXPECT_EQ(blurModulation(ImageBlur{}, Eigen::Vector2d(1, 0), 0.6), 0.0);  // past Nyquist
}

TEST(Legibility, SideCamerasGetTheWholeMotionBlurFrontAndRearAThird) {
  const geometry::Rig rig = geometry::defaultRig();
  LightingOptions light;
  light.defocus_sigma = 1.25f;
  light.motion_blur_px = 9.0f;
  for (const auto& camera : rig.cameras) {
    const ImageBlur blur = imageBlur(light, camera);
    EXPECT_DOUBLE_EQ(blur.defocus_sigma_px, 1.25);
    const bool side = camera.name == "left" || camera.name == "right";
    EXPECT_DOUBLE_EQ(blur.motion_length_px, side ? 9.0 : 3.0) << camera.name;
  }
  light.motion_blur_px = 4.0f;  // a third of it rounds to one pixel: no blur
  EXPECT_EQ(imageBlur(light, rig.cameras.front()).motion_length_px, 0.0);
  EXPECT_EQ(rig.cameras.front().name, "front");
}

TEST(Legibility, CharactersAreCodePoints) {
  EXPECT_EQ(characterCount("B1-117"), 6);
  EXPECT_EQ(characterCount("\xE5\x87\xBA\xE5\x8F\xA3"), 2);  // two CJK characters
  EXPECT_EQ(characterCount(""), 1);
}

}  // namespace
}  // namespace parkloc::sim
