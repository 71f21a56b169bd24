#include "sim/birds_eye.h"

#include <cmath>
#include <map>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "geometry/image_polygon.h"
#include "geometry/text_polygon.h"

namespace parkloc::sim {
namespace {

// Whether a text's polygon (pixels) shares more than a pixel of area with the image.
bool overlapsImage(const geometry::TextPolygon& polygon, cv::Size size) {
  std::vector<cv::Point2f> quad;
  for (const Eigen::Vector2d& p : polygon)
    quad.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()));
  return geometry::polygonArea(geometry::clippedToImage(quad, size)) > 1.0;
}

}  // namespace

BirdsEyeStitcher::BirdsEyeStitcher(const geometry::Rig& rig, const BirdsEyeOptions& options)
    : options_(options), rig_(rig) {
  const double m = options.metres_per_pixel;
  const int cols = static_cast<int>(std::lround(2.0 * options.half_width_m / m));
  const int rows = static_cast<int>(std::lround((options.ahead_m + options.behind_m) / m));
  owner_ = cv::Mat(rows, cols, CV_8S, cv::Scalar(-1));
  for (size_t c = 0; c < rig.cameras.size(); ++c) {
    map_x_.emplace_back(rows, cols, CV_32F, cv::Scalar(-1));
    map_y_.emplace_back(rows, cols, CV_32F, cv::Scalar(-1));
  }
  std::vector<geometry::Rigid3> camera_from_vehicle;
  for (const auto& cam : rig.cameras)
    camera_from_vehicle.push_back(cam.vehicle_from_camera.inverse());
  for (int v = 0; v < rows; ++v)
    for (int u = 0; u < cols; ++u) {
      const Eigen::Vector2d xy = vehicleFromPixel(Eigen::Vector2d(u, v));
      const Eigen::Vector3d ground(xy.x(), xy.y(), 0.0);
      // Under the car no camera sees the floor.
      bool under_car = false;
      for (const auto& cam : rig.cameras)
        if (cam.body && xy.x() >= cam.body->lo.x() && xy.x() <= cam.body->hi.x() &&
            xy.y() >= cam.body->lo.y() && xy.y() <= cam.body->hi.y())
          under_car = true;
      if (under_car) {
        owner_.at<int8_t>(v, u) = -2;
        continue;
      }
      // The camera that sees the point closest to its optical axis: the usual seams of an
      // AVM run on the diagonals between the cameras' fields.
      double best = -2.0;
      for (size_t c = 0; c < rig.cameras.size(); ++c) {
        const auto& cam = rig.cameras[c];
        const Eigen::Vector3d eye = cam.vehicle_from_camera.translation();
        if (cam.body && geometry::bodyBlocks(*cam.body, eye, ground)) continue;
        const Eigen::Vector3d p = camera_from_vehicle[c] * ground;
        const auto px = cam.model.project(p);
        if (!px || !cam.model.inImage(*px, 1.0)) continue;
        const Eigen::Vector3d axis = cam.vehicle_from_camera.linear().col(2);
        const Eigen::Vector2d to = (ground - eye).head<2>();
        const double score = axis.head<2>().normalized().dot(to.normalized());
        if (score > best) {
          best = score;
          owner_.at<int8_t>(v, u) = static_cast<int8_t>(c);
        }
        map_x_[c].at<float>(v, u) = static_cast<float>(px->x());
        map_y_[c].at<float>(v, u) = static_cast<float>(px->y());
      }
    }
}

Eigen::Vector2d BirdsEyeStitcher::pixelFromVehicle(const Eigen::Vector2d& xy) const {
  const double m = options_.metres_per_pixel;
  return {(options_.half_width_m - xy.y()) / m - 0.5, (options_.ahead_m - xy.x()) / m - 0.5};
}

Eigen::Vector2d BirdsEyeStitcher::vehicleFromPixel(const Eigen::Vector2d& pixel) const {
  const double m = options_.metres_per_pixel;
  return {options_.ahead_m - (pixel.y() + 0.5) * m, options_.half_width_m - (pixel.x() + 0.5) * m};
}

int BirdsEyeStitcher::cameraAt(const Eigen::Vector2d& pixel) const {
  const int u = static_cast<int>(std::lround(pixel.x())),
            v = static_cast<int>(std::lround(pixel.y()));
  if (u < 0 || v < 0 || u >= owner_.cols || v >= owner_.rows) return -1;
  return std::max(-1, static_cast<int>(owner_.at<int8_t>(v, u)));
}

cv::Mat BirdsEyeStitcher::stitch(const std::vector<cv::Mat>& images) const {
  CV_Assert(images.size() == map_x_.size());
  cv::Mat out(owner_.size(), CV_8UC3, cv::Scalar::all(0));
  out.setTo(cv::Scalar::all(40), owner_ == -2);
  for (size_t c = 0; c < images.size(); ++c) {
    cv::Mat warped;
    cv::remap(images[c], warped, map_x_[c], map_y_[c], cv::INTER_LINEAR, cv::BORDER_CONSTANT);
    warped.copyTo(out, owner_ == static_cast<int>(c));
  }
  return out;
}

io::ImageLabels birdsEyeLabels(const Garage& garage, int level, const BirdsEyeStitcher& stitcher,
                               const geometry::Pose2& map_from_vehicle,
                               const std::vector<io::ImageLabels>& camera_labels) {
  io::ImageLabels out;
  out.camera = "birdseye";
  out.width = stitcher.size().width;
  out.height = stitcher.size().height;
  if (!camera_labels.empty()) out.timestamp = camera_labels.front().timestamp;
  const geometry::Rigid3 vehicle_from_map = map_from_vehicle.toRigid3().inverse();
  for (const TextItem& item : garage.levels.at(level).texts) {
    const map::Landmark& lm = item.landmark;
    if (lm.surface != map::Surface::kGround) continue;
    io::LabelInstance inst;
    bool inside = true;
    const auto corners = lm.corners();
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector3d v = vehicle_from_map * corners[k];
      inst.polygon[k] = stitcher.pixelFromVehicle(v.head<2>());
      inside = inside && inst.polygon[k].x() >= 0.0 && inst.polygon[k].y() >= 0.0 &&
               inst.polygon[k].x() <= out.width - 1.0 && inst.polygon[k].y() <= out.height - 1.0;
    }
    if (!inside) {
      // Cut by the image's border, a number shows some of its characters: no reader reads it
      // whole, and a detector's box on the part that shows is neither rewarded nor counted
      // wrong (don't care, as ICDAR marks a cut word).
      if (overlapsImage(inst.polygon, {out.width, out.height})) {
        inst.text = lm.text;
        inst.cls = lm.cls;
        inst.landmark_id = lm.id;
        inst.legible = false;
        inst.truncated = true;
        out.instances.push_back(inst);
      }
      continue;
    }
    const Eigen::Vector2d centre =
        0.25 * (inst.polygon[0] + inst.polygon[1] + inst.polygon[2] + inst.polygon[3]);
    const int camera = stitcher.cameraAt(centre);
    if (camera < 0 || static_cast<size_t>(camera) >= camera_labels.size()) continue;
    const io::LabelInstance* seen = nullptr;
    for (const auto& l : camera_labels[static_cast<size_t>(camera)].instances)
      if (l.landmark_id == lm.id) seen = &l;
    if (seen == nullptr) continue;  // the camera does not show it (too far, cut off)
    inst.text = lm.text;
    inst.cls = lm.cls;
    inst.landmark_id = lm.id;
    inst.legible = seen->legible;
    inst.occluded_fraction = seen->occluded_fraction;
    inst.paint_wear = seen->paint_wear;
    inst.ink_snr = seen->ink_snr;
    // Every corner must come from a camera that sees the floor there: a text across the car
    // or beyond every camera's field is cut in the AVM.
    for (const auto& p : inst.polygon) inst.truncated = inst.truncated || stitcher.cameraAt(p) < 0;
    const Eigen::Vector2d reading =
        0.5 * (inst.polygon[1] + inst.polygon[2]) - 0.5 * (inst.polygon[0] + inst.polygon[3]);
    inst.rotation_deg = std::atan2(reading.y(), reading.x()) * 180.0 / M_PI;
    out.instances.push_back(inst);
  }
  // Text above the floor (plates, pillar labels) is smeared across the floor by the stitching:
  // where the camera that fills that part of the AVM labels it, it is kept as "not legible", so
  // that a detector finding the smear is neither rewarded nor counted wrong.
  for (size_t c = 0; c < camera_labels.size() && c < stitcher.cameraCount(); ++c)
    for (const io::LabelInstance& seen : camera_labels[c].instances) {
      bool on_floor = false;
      for (const TextItem& item : garage.levels.at(level).texts)
        if (item.landmark.id == seen.landmark_id)
          on_floor = item.landmark.surface == map::Surface::kGround;
      if (on_floor) continue;
      io::LabelInstance inst = seen;
      bool mapped = true;
      for (int k = 0; k < 4 && mapped; ++k) {
        const auto p = stitcher.pixelFromCameraPixel(c, seen.polygon[k]);
        if (p) inst.polygon[k] = *p;
        mapped = p.has_value();
      }
      if (!mapped) continue;
      const Eigen::Vector2d centre =
          0.25 * (inst.polygon[0] + inst.polygon[1] + inst.polygon[2] + inst.polygon[3]);
      if (stitcher.cameraAt(centre) != static_cast<int>(c)) continue;
      inst.legible = false;
      inst.visible_polygon.reset();
      out.instances.push_back(inst);
    }
  return out;
}

std::optional<Eigen::Vector2d> BirdsEyeStitcher::pixelFromCameraPixel(
    size_t camera, const Eigen::Vector2d& pixel) const {
  const geometry::RigCamera& cam = rig_.cameras.at(camera);
  const auto ray = cam.model.unproject(pixel);
  if (!ray) return std::nullopt;
  const Eigen::Vector3d eye = cam.vehicle_from_camera.translation();
  const Eigen::Vector3d d = cam.vehicle_from_camera.linear() * *ray;
  if (d.z() >= -1e-6) return std::nullopt;  // at or above the horizon: never meets the floor
  const double t = -eye.z() / d.z();
  return pixelFromVehicle((eye + t * d).head<2>());
}

}  // namespace parkloc::sim
