// Ground truth geometry: what the renderer draws lies where the camera model projects it.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "sim/annotate.h"
#include "sim_test_util.h"

namespace parkloc::sim {
namespace {

using testing::emptyGarage;
using testing::flatLight;
using testing::raysOf;
using testing::scaledRig;

// A bright disc of `diameter` metres on the floor centred at `centre`.
void addFloorMarker(Garage& g, const Eigen::Vector2d& centre, double diameter) {
  const int px = 64, pad = 6;
  cv::Mat disc(px, px, CV_8UC1, cv::Scalar(0));
  cv::circle(disc, {px * 8 - 8, px * 8 - 8}, px * 8 - 16, cv::Scalar(255), -1, cv::LINE_AA, 4);
  cv::Mat padded;
  cv::copyMakeBorder(disc, padded, pad, pad, pad, pad, cv::BORDER_CONSTANT, cv::Scalar(0));
  g.textures.emplace_back(padded);
  Decal d;
  d.origin =
      Eigen::Vector3f(float(centre.x() - diameter / 2), float(centre.y() + diameter / 2), 0.0f);
  d.axis_u = Eigen::Vector3f(1, 0, 0);
  d.axis_v = Eigen::Vector3f(0, -1, 0);
  d.size_u = d.size_v = static_cast<float>(diameter);
  d.texels_per_metre = static_cast<float>(px / diameter);
  d.pad = pad;
  d.texture = static_cast<int>(g.textures.size()) - 1;
  d.color = Eigen::Vector3f(1, 1, 1);
  g.levels[0].floor_decals.push_back(d);
}

// Centroid of the brightness above the local background in a window around `guess`.
Eigen::Vector2d brightCentroid(const cv::Mat& bgr, const Eigen::Vector2d& guess, int half) {
  cv::Mat grey;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  const cv::Rect win(static_cast<int>(guess.x()) - half, static_cast<int>(guess.y()) - half,
                     2 * half + 1, 2 * half + 1);
  cv::Mat patch;
  grey(win & cv::Rect(0, 0, grey.cols, grey.rows)).convertTo(patch, CV_64F);
  // Background: the median of the window's border.
  std::vector<double> border;
  for (int i = 0; i < patch.cols; ++i)
    border.push_back(patch.at<double>(0, i)), border.push_back(patch.at<double>(patch.rows - 1, i));
  std::nth_element(border.begin(), border.begin() + border.size() / 2, border.end());
  const double bg = border[border.size() / 2];
  double sw = 0, sx = 0, sy = 0;
  for (int y = 0; y < patch.rows; ++y)
    for (int x = 0; x < patch.cols; ++x) {
      const double w = std::max(0.0, patch.at<double>(y, x) - bg - 3.0);
      sw += w;
      sx += w * (x + win.x);
      sy += w * (y + win.y);
    }
  EXPECT_GT(sw, 0.0);
  return {sx / sw, sy / sw};
}

TEST(RenderGeometry, MarkerCentroidMatchesProjection) {
  const geometry::Rig rig = scaledRig(0.5);
  const auto rays = raysOf(rig);
  const geometry::Pose2 pose(9.0, 10.0, 0.3);
  // Markers around the car, each seen by one camera, some far off the optical axis.
  const std::vector<std::pair<std::string, Eigen::Vector2d>> markers = {
      {"front", {5.5, 0.4}}, {"front", {4.8, -1.6}}, {"left", {2.6, 2.4}},
      {"left", {0.5, 2.0}},  {"rear", {-2.8, 0.6}},  {"right", {1.5, -2.3}}};
  for (const auto& [camera_name, in_vehicle] : markers) {
    Garage g = emptyGarage();
    const Eigen::Vector2d centre = pose * in_vehicle;
    addFloorMarker(g, centre, 0.12);
    const Renderer renderer(g, 0, rig, rays, flatLight());
    size_t ci = 0;
    while (rig.cameras[ci].name != camera_name) ++ci;
    const geometry::RigCamera& cam = rig.cameras[ci];
    const geometry::Rigid3 camera_from_map = (pose.toRigid3() * cam.vehicle_from_camera).inverse();
    const auto expected =
        cam.model.project(camera_from_map * Eigen::Vector3d(centre.x(), centre.y(), 0.0));
    ASSERT_TRUE(expected.has_value()) << camera_name;
    ASSERT_TRUE(cam.model.inImage(*expected, 20)) << camera_name;
    const cv::Mat img = renderer.renderCamera(ci, pose, 1);
    const Eigen::Vector2d found = brightCentroid(img, *expected, 20);
    EXPECT_LT((found - *expected).norm(), 0.5)
        << camera_name << " marker at " << in_vehicle.transpose() << ": found " << found.transpose()
        << " expected " << expected->transpose();
  }
}

TEST(RenderGeometry, LabelPolygonsCoverTheDrawnText) {
  const geometry::Rig rig = scaledRig(0.5);
  const auto rays = raysOf(rig);
  const Garage g = generateGarage(testing::smallSpec(), 11);
  // The same garage without text: the difference of the two renders is exactly the text.
  Garage bare = g;
  bare.levels[0].floor_decals.clear();
  const LightingOptions light = flatLight();
  const Renderer renderer(g, 0, rig, rays, light), bare_renderer(bare, 0, rig, rays, light);
  int checked = 0;
  for (const double x : {12.0, 17.0}) {
    const geometry::Pose2 pose(x, g.aisle_y[0] + 0.3, 0.0);
    for (size_t ci = 0; ci < rig.cameras.size(); ++ci) {
      cv::Mat diff;
      cv::absdiff(renderer.renderCamera(ci, pose, 3), bare_renderer.renderCamera(ci, pose, 3),
                  diff);
      cv::cvtColor(diff, diff, cv::COLOR_BGR2GRAY);
      const cv::Mat ink = diff > 30;
      for (const auto& inst : annotateImage(g, 0, rig.cameras[ci], pose)) {
        if (inst.cls == map::TextClass::kPillar || inst.truncated || inst.occluded_fraction > 0)
          continue;
        std::vector<cv::Point> quad;
        for (const auto& p : inst.polygon) quad.emplace_back(cvRound(p.x()), cvRound(p.y()));
        if (cv::contourArea(quad) < 150.0) continue;
        // The label's corners are the projected corners of the text box; its edges are curved
        // in a fisheye image, so trace them densely.
        const map::Landmark* lm = g.map.findById(inst.landmark_id);
        ASSERT_NE(lm, nullptr);
        const auto corners = lm->corners();
        const geometry::Rigid3 camera_from_map =
            (pose.toRigid3() * rig.cameras[ci].vehicle_from_camera).inverse();
        std::vector<cv::Point> poly;
        for (int k = 0; k < 4; ++k)
          for (int s = 0; s < 16; ++s) {
            const Eigen::Vector3d p = corners[k] + (corners[(k + 1) % 4] - corners[k]) * (s / 16.0);
            const auto px = rig.cameras[ci].model.project(camera_from_map * p);
            ASSERT_TRUE(px.has_value());
            poly.emplace_back(cvRound(px->x()), cvRound(px->y()));
          }
        for (int k = 0; k < 4; ++k) {
          EXPECT_EQ(quad[k], poly[16 * k]) << "label corners are the projected text corners";
        }
        // Ink within 8 px of the outline must lie inside it (2 px tolerance for rounding and
        // filtering) and fill a fair share of it.
        cv::Mat inside(ink.size(), CV_8U, cv::Scalar(0)), near;
        cv::fillPoly(inside, std::vector<std::vector<cv::Point>>{poly}, cv::Scalar(255));
        cv::dilate(inside, near, cv::getStructuringElement(cv::MORPH_ELLIPSE, {17, 17}));
        cv::dilate(inside, inside, cv::getStructuringElement(cv::MORPH_ELLIPSE, {5, 5}));
        const double ink_near = cv::countNonZero(ink & near);
        const double ink_inside = cv::countNonZero(ink & inside);
        ASSERT_GT(ink_near, 0) << inst.text;
        EXPECT_GT(ink_inside / ink_near, 0.97) << inst.text << " camera " << rig.cameras[ci].name;
        EXPECT_GT(ink_inside / cv::contourArea(poly), 0.2)
            << inst.text << " camera " << rig.cameras[ci].name;
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 4);
}

}  // namespace
}  // namespace parkloc::sim
