// The annotated frame of `parkloc run --video` (run/run_visualization.h): every camera of a rig
// has its view, whatever the rig's size, in a frame of one size.
#include <gtest/gtest.h>

#include "run/run_visualization.h"

namespace parkloc::run {
namespace {

// A frame set of `n` cameras, each image one flat colour that tells the camera apart.
struct Rig {
  explicit Rig(int n) {
    for (int c = 0; c < n; ++c) {
      localize::CameraResult camera;
      camera.camera = "cam" + std::to_string(c);
      camera.full_frame = false;
      result.cameras.push_back(camera);
      images.emplace_back(800, 1280, CV_8UC3, colour(c));
    }
  }
  static cv::Scalar colour(int c) { return cv::Scalar(40 + 30 * c, 200 - 25 * c, 100); }
  localize::FrameResult result;
  std::vector<cv::Mat> images;
};

cv::Mat draw(const Rig& rig) {
  VisualizationInput input;
  input.result = &rig.result;
  input.images = rig.images;
  const map::HdMap empty;
  return drawRunFrame(input, empty, BirdsEyeView::fitting(empty, {}));
}

// The colour at the middle of camera c's view, in a grid of two columns and `rows` rows.
cv::Vec3b viewCentre(const cv::Mat& frame, int c, int rows) {
  const int height = frame.rows / rows;
  // Images keep their aspect ratio from the view's top left corner: sample within the
  // image's part of the view.
  return frame.at<cv::Vec3b>((c / 2) * height + height / 2, (c % 2) * 640 + 100);
}

TEST(RunVisualization, EveryCameraOfASixCameraRigHasItsView) {
  const Rig six(6), four(4);
  const cv::Mat a = draw(six), b = draw(four);
  EXPECT_EQ(a.size(), b.size());
  for (int c = 0; c < 6; ++c) {
    const cv::Vec3b pixel = viewCentre(a, c, 3);
    const cv::Scalar want = Rig::colour(c);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(pixel[k], want[k]) << "camera " << c << " channel " << k;
  }
  for (int c = 0; c < 4; ++c) EXPECT_EQ(viewCentre(b, c, 2)[1], Rig::colour(c)[1]) << c;
}

}  // namespace
}  // namespace parkloc::run
