#include "ocr/ground_view.h"

#include <gtest/gtest.h>

#include "geometry/rig.h"

namespace parkloc::ocr {
namespace {

TEST(GroundView, ViewPixelsMapToTheRawPixelsOfTheirGroundPoints) {
  const auto rig = geometry::defaultRig();
  for (const auto& camera : rig.cameras) {
    GroundViewOptions options;
    const GroundView view(camera, options);
    EXPECT_EQ(view.size().width % 32, 0);
    EXPECT_EQ(view.size().height % 32, 0);
    // A raw image whose pixel values encode their own coordinates: the view must sample
    // each view pixel from rawFromView of that pixel.
    cv::Mat raw(camera.model.height, camera.model.width, CV_8UC3);
    for (int y = 0; y < raw.rows; ++y)
      for (int x = 0; x < raw.cols; ++x)
        raw.at<cv::Vec3b>(y, x) = cv::Vec3b(x % 256, y % 256, (x / 256) * 16 + y / 256);
    const cv::Mat rendered = view.render(raw);
    int checked = 0;
    for (int r = 8; r < view.size().height; r += 41)
      for (int c = 8; c < view.size().width; c += 37) {
        const auto px = view.rawFromView(cv::Point2f(c, r));
        if (!px || px->x < 1 || px->y < 1 || px->x > raw.cols - 2 || px->y > raw.rows - 2) continue;
        const cv::Point ip(cvRound(px->x), cvRound(px->y));
        // Only where the nearest raw pixel is close to the sample point (no blending).
        if (std::abs(px->x - ip.x) > 0.1f || std::abs(px->y - ip.y) > 0.1f) continue;
        EXPECT_EQ(rendered.at<cv::Vec3b>(r, c), raw.at<cv::Vec3b>(ip)) << camera.name;
        ++checked;
      }
    // Points on the floor straight ahead of the camera are visible in its view.
    EXPECT_TRUE(view.rawFromView(cv::Point2f(view.size().width / 2.f, view.size().height / 2.f)))
        << camera.name;
    EXPECT_GT(checked, 3) << camera.name;
  }
}

}  // namespace
}  // namespace parkloc::ocr
