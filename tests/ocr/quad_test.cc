#include "ocr/quad.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

namespace parkloc::ocr {
namespace {

TEST(Quad, RotatedRectCornersFollowTheLongSideLeftToRight) {
  for (float angle : {-80.f, -30.f, 0.f, 30.f, 60.f, 89.f, 120.f}) {
    const cv::RotatedRect r({100, 50}, {60, 20}, angle);
    const Quad q = quadFromRotatedRect(r);
    EXPECT_NEAR(quadWidth(q), 60, 1e-3);
    EXPECT_NEAR(quadHeight(q), 20, 1e-3);
    const cv::Point2f along = q[1] - q[0];
    EXPECT_GE(along.x, -1e-3f) << angle;  // forward has non-negative x
    // TL, TR, BR, BL turn clockwise in image coordinates (y down): positive cross product.
    const cv::Point2f down = q[3] - q[0];
    EXPECT_GT(along.x * down.y - along.y * down.x, 0.f) << angle;
  }
}

TEST(Quad, ShiftBy180SwapsOppositeCorners) {
  const Quad q = {cv::Point2f(0, 0), {10, 0}, {10, 4}, {0, 4}};
  const Quad s = shiftedBy180(q);
  EXPECT_EQ(s[0], q[2]);
  EXPECT_EQ(s[1], q[3]);
  EXPECT_EQ(s[2], q[0]);
  EXPECT_EQ(s[3], q[1]);
}

TEST(Quad, ExpandScalesAboutTheCentreAlongEachAxis) {
  const Quad q = {cv::Point2f(10, 20), {50, 20}, {50, 30}, {10, 30}};
  const Quad e = expandQuad(q, 2.f, 3.f);
  EXPECT_NEAR(quadWidth(e), 80, 1e-3);
  EXPECT_NEAR(quadHeight(e), 30, 1e-3);
  EXPECT_NEAR(e[0].x, -10, 1e-3);
  EXPECT_NEAR(e[0].y, 10, 1e-3);
}

TEST(Quad, CentreIsTheMeanOfTheCorners) {
  const Quad q = {cv::Point2f(0.f, 0.f), cv::Point2f(8.f, 2.f), cv::Point2f(10.f, 6.f),
                  cv::Point2f(2.f, 4.f)};
  const cv::Point2f c = quadCentre(q);
  EXPECT_FLOAT_EQ(c.x, 5.f);
  EXPECT_FLOAT_EQ(c.y, 3.f);
}

TEST(Quad, OrientedAlongTurnsTheQuadToReadTheGivenWayAndRefusesACrossingOne) {
  // Reads along +x, tilted 10 degrees.
  const Quad q = {cv::Point2f(0.f, 0.f), cv::Point2f(40.f, 7.f), cv::Point2f(38.f, 17.f),
                  cv::Point2f(-2.f, 10.f)};
  const double max_angle = CV_PI / 6;
  const auto same = orientedAlong(q, {1.f, 0.f}, max_angle);
  ASSERT_TRUE(same);
  EXPECT_EQ((*same)[0], q[0]);
  const auto turned = orientedAlong(q, {-3.f, 0.f}, max_angle);
  ASSERT_TRUE(turned);
  EXPECT_EQ((*turned)[0], q[2]);  // its top-left is the upright quad's bottom-right
  EXPECT_EQ((*turned)[1], q[3]);
  EXPECT_FALSE(orientedAlong(q, {0.f, 1.f}, max_angle));  // across the text
  EXPECT_FALSE(orientedAlong(q, {1.f, 1.f}, max_angle));  // 35 degrees off
  EXPECT_TRUE(orientedAlong(q, {1.f, 1.f}, CV_PI / 4));
  EXPECT_FALSE(orientedAlong(q, {0.f, 0.f}, max_angle));  // no direction
}

TEST(Quad, RectifiedCropMapsCornersToTheCropEdges) {
  // A bright dot at the quad's top-left corner lands in the crop's top-left pixel.
  cv::Mat image(100, 100, CV_8UC3, cv::Scalar::all(0));
  const Quad q = {cv::Point2f(20.5f, 30.5f), {80.5f, 40.5f}, {76.5f, 60.5f}, {16.5f, 50.5f}};
  cv::circle(image, {21, 31}, 1, cv::Scalar::all(255), cv::FILLED);
  const cv::Mat crop = rectifiedCrop(image, q, 48, 16, 400);
  EXPECT_EQ(crop.rows, 48);
  EXPECT_NEAR(crop.cols, 48.0 * quadWidth(q) / quadHeight(q), 1.0);
  EXPECT_GT(crop.at<cv::Vec3b>(1, 1)[0], 100);
  EXPECT_LT(crop.at<cv::Vec3b>(40, 40)[0], 10);
}

}  // namespace
}  // namespace parkloc::ocr
