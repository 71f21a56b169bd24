#include "ocr/db_postprocess.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

namespace parkloc::ocr {
namespace {

cv::Point2f centreOf(const Quad& q) { return (q[0] + q[1] + q[2] + q[3]) * 0.25f; }

TEST(DbPostprocess, FindsOneBoxPerBlobGrownByTheOffsetDistance) {
  cv::Mat prob(200, 300, CV_32F, cv::Scalar(0.02f));
  // Two solid blobs: 80 x 20 axis-aligned, and 60 x 16 rotated by 30 degrees.
  cv::rectangle(prob, cv::Rect(20, 30, 80, 20), cv::Scalar(0.95f), cv::FILLED);
  const cv::RotatedRect tilted({200.f, 130.f}, {60.f, 16.f}, 30.f);
  cv::Point2f c[4];
  tilted.points(c);
  std::vector<cv::Point> poly;
  for (const auto& p : c) poly.emplace_back(cvRound(p.x), cvRound(p.y));
  cv::fillConvexPoly(prob, poly, cv::Scalar(0.9f));

  DbOptions options;
  const auto boxes = dbBoxesFromProbability(prob, options);
  ASSERT_EQ(boxes.size(), 2u);
  const DbBox& a = centreOf(boxes[0].quad).x < 150 ? boxes[0] : boxes[1];
  const DbBox& b = &a == &boxes[0] ? boxes[1] : boxes[0];

  // Blob A: the contour runs through the outer pixel centres, so its box is 79 x 19.
  const double w = 79, h = 19;
  const double d = w * h * options.unclip_ratio / (2 * (w + h));
  EXPECT_NEAR(centreOf(a.quad).x, 59.5, 1.0);
  EXPECT_NEAR(centreOf(a.quad).y, 39.5, 1.0);
  EXPECT_NEAR(quadWidth(a.quad), w + 2 * d, 1.0);
  EXPECT_NEAR(quadHeight(a.quad), h + 2 * d, 1.0);
  EXPECT_GT(a.score, 0.9f);
  // Reading order: the top-left corner is up and to the left of the centre.
  EXPECT_LT(a.quad[0].x, centreOf(a.quad).x);
  EXPECT_LT(a.quad[0].y, centreOf(a.quad).y);

  EXPECT_NEAR(centreOf(b.quad).x, 200, 1.5);
  EXPECT_NEAR(centreOf(b.quad).y, 130, 1.5);
  const double d2 = 60.0 * 16.0 * options.unclip_ratio / (2 * (60.0 + 16.0));
  EXPECT_NEAR(quadWidth(b.quad), 60 + 2 * d2, 2.5);
  EXPECT_NEAR(quadHeight(b.quad), 16 + 2 * d2, 2.5);
  const cv::Point2f along = b.quad[1] - b.quad[0];
  EXPECT_NEAR(std::atan2(along.y, along.x) * 180 / CV_PI, 30.0, 2.0);
}

TEST(DbPostprocess, DropsFaintAndTinyBlobs) {
  cv::Mat prob(100, 100, CV_32F, cv::Scalar(0.f));
  cv::rectangle(prob, cv::Rect(10, 10, 40, 12), cv::Scalar(0.45f), cv::FILLED);  // faint
  cv::rectangle(prob, cv::Rect(70, 70, 2, 2), cv::Scalar(0.99f), cv::FILLED);    // tiny
  EXPECT_TRUE(dbBoxesFromProbability(prob, DbOptions{}).empty());
  DbOptions lenient;
  lenient.box_threshold = 0.4f;
  EXPECT_EQ(dbBoxesFromProbability(prob, lenient).size(), 1u);
}

TEST(Unclip, GrowsEverySideByAreaTimesRatioOverPerimeter) {
  const cv::RotatedRect r({0, 0}, {40, 10}, 12);
  const auto g = unclipRect(r, 2.0);
  const double d = 40.0 * 10.0 * 2.0 / 100.0;
  EXPECT_NEAR(g.size.width, 40 + 2 * d, 1e-4);
  EXPECT_NEAR(g.size.height, 10 + 2 * d, 1e-4);
  EXPECT_FLOAT_EQ(g.angle, 12.f);
}

TEST(Unclip, ABoxGrownAtOneRatioRegrowsAtAnotherFromTheSameKernel) {
  const cv::RotatedRect kernel({200, 120}, {70, 12}, 0);
  const Quad wide = quadFromRotatedRect(unclipRect(kernel, 2.0));
  const Quad tight = quadFromRotatedRect(unclipRect(kernel, 1.3));
  const Quad regrown = reunclipQuad(wide, 2.0, 1.3);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(regrown[i].x, tight[i].x, 1e-2);
    EXPECT_NEAR(regrown[i].y, tight[i].y, 1e-2);
  }
  EXPECT_LT(quadWidth(regrown), quadWidth(wide) - 1.f);
  // The same ratio gives the box back; a degenerate box is left as it is.
  const Quad same = reunclipQuad(wide, 2.0, 2.0);
  EXPECT_NEAR(quadWidth(same), quadWidth(wide), 1e-2);
  const Quad flat = {cv::Point2f(0, 0), {10, 0}, {10, 0}, {0, 0}};
  EXPECT_EQ(reunclipQuad(flat, 2.0, 1.3), flat);
}

TEST(ReadingPriority, ConfidentBoxesFirstThenTheLargest) {
  auto box = [](float w, float h, float score) {
    DbBox b;
    b.quad = {cv::Point2f(0, 0), cv::Point2f(w, 0), cv::Point2f(w, h), cv::Point2f(0, h)};
    b.score = score;
    return b;
  };
  const std::vector<DbBox> boxes = {
      box(100, 30, 0.4f),  // the largest, but weak
      box(40, 10, 0.9f),   // confident, small
      box(60, 20, 0.6f),   // confident, larger: exactly at the threshold
      box(50, 10, 0.35f),  // weak, small
  };
  EXPECT_EQ(readingPriority(boxes, 0.6f), (std::vector<size_t>{2, 1, 0, 3}));
  // Every box confident: the largest first, as with PaddleOCR's threshold alone.
  EXPECT_EQ(readingPriority(boxes, 0.3f), (std::vector<size_t>{0, 2, 3, 1}));
  EXPECT_TRUE(readingPriority({}, 0.6f).empty());
}

}  // namespace
}  // namespace parkloc::ocr
