// Painted floor text must stand out of the sensor's noise to be labelled legible: the
// renderer says how much its ink differs from the floor under it, the rule (Rose's
// criterion on one reading feature) weighs that against the noise.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "sim/annotate.h"
#include "sim/legibility.h"
#include "sim/renderer.h"
#include "sim_test_util.h"

namespace parkloc::sim {
namespace {

// A text box reading left to right, `length` x `height` pixels.
geometry::TextPolygon box(double length, double height) {
  return {Eigen::Vector2d(0, 0), Eigen::Vector2d(length, 0), Eigen::Vector2d(length, height),
          Eigen::Vector2d(0, height)};
}

TEST(InkContrast, FeatureSnrSumsTheContrastOverHalfACycleEachWayAgainstLumaNoise) {
  // 4 characters in 48 x 12 px: a feature of 12/4 x 12/4 = 9 px. Luma noise of independent
  // channels: sqrt(0.299^2 + 0.587^2 + 0.114^2) = 0.6686 of a channel's.
  const double luma_share = std::sqrt(0.299 * 0.299 + 0.587 * 0.587 + 0.114 * 0.114);
  EXPECT_NEAR(featureSnr(box(48, 12), 4, {10.0, 2.0}), 10.0 * 3.0 / (2.0 * luma_share), 1e-9);
  // Twice the noise halves it; text twice as large in both directions doubles it.
  EXPECT_NEAR(featureSnr(box(48, 12), 4, {10.0, 4.0}),
              0.5 * featureSnr(box(48, 12), 4, {10.0, 2.0}), 1e-9);
  EXPECT_NEAR(featureSnr(box(96, 24), 4, {10.0, 2.0}),
              2.0 * featureSnr(box(48, 12), 4, {10.0, 2.0}), 1e-9);
  // Rose's k = 5 by default: 2 levels over noise 2 on a 9 px feature give 4.49.
  EXPECT_FALSE(inkStandsOut(box(48, 12), 4, {2.0, 2.0}));
  EXPECT_TRUE(inkStandsOut(box(48, 12), 4, {2.5, 2.0}));
  // No ink shows nothing; any ink shows without noise.
  EXPECT_FALSE(inkStandsOut(box(48, 12), 4, {0.0, 0.0}));
  EXPECT_TRUE(inkStandsOut(box(48, 12), 4, {0.5, 0.0}));
}

TEST(InkContrast, WornNumbersKeepPartOfTheirInkAndIntactOnesAllOfIt) {
  GarageSpec worn = testing::smallSpec();
  worn.worn_share = 1.0;
  for (const bool all_worn : {true, false}) {
    const Garage g = generateGarage(all_worn ? worn : testing::smallSpec(), 5);
    const GarageLevel& L = g.levels[0];
    int numbers = 0;
    for (const TextItem& item : L.texts) {
      if (item.landmark.cls != map::TextClass::kParkingNumber) continue;
      ++numbers;
      ASSERT_GE(item.floor_decal, 0) << item.landmark.text;
      const Decal& d = L.floor_decals.at(static_cast<size_t>(item.floor_decal));
      EXPECT_EQ(d.wear > 0.0f, all_worn) << item.landmark.text;
      if (all_worn) {
        EXPECT_GT(d.ink_kept, 0.0f) << item.landmark.text;
        EXPECT_LT(d.ink_kept, 0.95f) << item.landmark.text;
      } else {
        EXPECT_EQ(d.ink_kept, 1.0f) << item.landmark.text;
      }
    }
    EXPECT_GT(numbers, 0);
    for (const TextItem& item : L.texts)
      if (item.landmark.surface != map::Surface::kGround) {
        EXPECT_EQ(item.floor_decal, -1);
      }
  }
}

// The BT.601 luma of the mean BGR over a 5 x 5 window at `at`.
double lumaAround(const cv::Mat& bgr, const Eigen::Vector2d& at) {
  const cv::Rect window(static_cast<int>(std::lround(at.x())) - 2,
                        static_cast<int>(std::lround(at.y())) - 2, 5, 5);
  const cv::Scalar m = cv::mean(bgr(window));
  return 0.299 * m[2] + 0.587 * m[1] + 0.114 * m[0];
}

TEST(InkContrast, TheRenderersContrastIsWhatItsImageShows) {
  // A yellow 1 m square painted at half strength 2 m ahead of the front camera on a uniform floor:
  // the image's luma step at its edge is the contrast the renderer predicts, and dimmer light or
  // less ink make it smaller.
  const geometry::Rig rig = testing::scaledRig(0.5);
  const auto rays = testing::raysOf(rig);
  const geometry::Pose2 pose(8.0, 10.0, 0.0);
  Garage g = testing::emptyGarage();
  Decal d;
  d.origin = Eigen::Vector3f(13.5f, 10.5f, 0.0f);
  d.axis_u = Eigen::Vector3f(1, 0, 0);
  d.axis_v = Eigen::Vector3f(0, -1, 0);
  d.size_u = d.size_v = 1.0f;
  d.color = Eigen::Vector3f(0.9f, 0.85f, 0.2f);
  d.opacity = 0.5f;
  g.levels[0].floor_decals.push_back(d);
  const size_t front = 0;
  ASSERT_EQ(rig.cameras[front].name, "front");
  const geometry::Rigid3 camera_from_map =
      (pose.toRigid3() * rig.cameras[front].vehicle_from_camera).inverse();
  auto pixelOf = [&](double x, double y) {
    const auto px = rig.cameras[front].model.project(camera_from_map * Eigen::Vector3d(x, y, 0));
    EXPECT_TRUE(px.has_value());
    return px.value_or(Eigen::Vector2d::Zero());
  };
  // Inside the square near its left edge, and the floor just left of it (the same light and
  // nearly the same vignetting).
  const Eigen::Vector2d ink_px = pixelOf(14.0, 10.1), floor_px = pixelOf(14.0, 10.9);

  LightingOptions bright = testing::flatLight();
  bright.ambient = 0.6f;
  double predicted_bright = 0.0;
  for (const float ambient : {0.6f, 0.15f}) {
    LightingOptions light = bright;
    light.ambient = ambient;
    const Renderer renderer(g, 0, rig, rays, light);
    const cv::Mat img = renderer.renderCamera(front, pose, 1);
    const double shown = std::abs(lumaAround(img, ink_px) - lumaAround(img, floor_px));
    const double predicted = renderer.floorInkContrast(front, ink_px, 0);
    EXPECT_NEAR(predicted, shown, 0.1 * shown + 1.0) << "ambient " << ambient;
    if (ambient == 0.6f)
      predicted_bright = predicted;
    else
      EXPECT_LT(predicted, 0.7 * predicted_bright);
  }
  g.levels[0].floor_decals[0].ink_kept = 0.3f;
  const Renderer worn(g, 0, rig, rays, bright);
  EXPECT_LT(worn.floorInkContrast(front, ink_px, 0), 0.5 * predicted_bright);
}

TEST(InkContrast, LabelsCarryTheSnrAndFaintPaintInNoiseIsNotLegible) {
  const geometry::Rig rig = geometry::defaultRig();
  const Garage g = generateGarage(testing::smallSpec(), 5);
  const geometry::Pose2 pose(14.0, g.aisle_y[0] + 0.5, 0.0);
  AnnotateOptions clear, faint;
  clear.floor_ink_contrast = [](int, const Eigen::Vector2d&) { return 60.0; };
  faint.floor_ink_contrast = [](int, const Eigen::Vector2d&) { return 1.0; };
  clear.channel_noise = faint.channel_noise = 6.0;
  int numbers = 0;
  for (const auto& camera : rig.cameras) {
    const auto plain = annotateImage(g, 0, camera, pose);
    const auto a = annotateImage(g, 0, camera, pose, clear);
    const auto b = annotateImage(g, 0, camera, pose, faint);
    ASSERT_EQ(a.size(), plain.size());
    ASSERT_EQ(b.size(), plain.size());
    for (size_t i = 0; i < plain.size(); ++i) {
      EXPECT_FALSE(plain[i].ink_snr.has_value());  // no contrast given: the size rule alone
      if (plain[i].cls != map::TextClass::kParkingNumber) continue;
      ++numbers;
      ASSERT_TRUE(a[i].ink_snr.has_value()) << a[i].text;
      ASSERT_TRUE(b[i].ink_snr.has_value()) << b[i].text;
      EXPECT_NEAR(*a[i].ink_snr, 60.0 * *b[i].ink_snr, 1e-6 * *a[i].ink_snr);
      EXPECT_EQ(a[i].legible, plain[i].legible && *a[i].ink_snr >= 5.0) << a[i].text;
      EXPECT_EQ(b[i].legible, plain[i].legible && *b[i].ink_snr >= 5.0) << b[i].text;
      if (plain[i].legible && geometry::apparentHeightPx(plain[i].polygon) < 60.0) {
        EXPECT_FALSE(b[i].legible) << b[i].text;
      }
    }
  }
  EXPECT_GT(numbers, 0);
}

}  // namespace
}  // namespace parkloc::sim
