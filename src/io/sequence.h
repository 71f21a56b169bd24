#pragma once
// A drive: one self-contained sequence folder as `parkloc simulate` writes it
//   calib.yaml  map.geojson  poses.tum (optional)  levels.csv (optional)  odometry.csv (optional)
//   meta.json (optional)
//   images/<camera>/<timestamp>.jpg|png   labels/<camera>/<timestamp>.json (optional)
// or, per camera, a recording instead of an image folder:
//   videos/<camera>.<ext> (any video FFmpeg reads)  videos/<camera>.csv (io/video_timestamps.h)
// File stems are timestamps in seconds printed with six decimals ("12.350000").
// A frame set is one image per camera, captured within a tolerance of each other
// (io/frame_sets.h): the same stem on a synchronised rig.
#include <map>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "geometry/rig.h"
#include "io/labels.h"
#include "io/levels_csv.h"
#include "io/odometry_csv.h"
#include "io/tum.h"
#include "io/video_reader.h"
#include "map/hd_map.h"

namespace parkloc::io {

std::string timestampStem(double timestamp);  // 12.35 -> "12.350000"

// What a Sequence reads. kSensors: only what the vehicle records (calib.yaml, odometry.csv,
// images): an estimator that must not see the truth (the map builder) reads a drive so.
enum class SequenceContents { kAll, kSensors };

class Sequence {
 public:
  // Reads calib.yaml and map.geojson (required, throws InputError), the optional files, and
  // lists the images. Paths may be overridden (e.g. --calib / --map on the CLI). With
  // kSensors, map.geojson, poses.tum, levels.csv and meta.json are not read (map() is empty).
  explicit Sequence(const std::string& dir, const std::string& calib_path = "",
                    const std::string& map_path = "", const std::string& odometry_path = "",
                    SequenceContents contents = SequenceContents::kAll);

  const std::string& dir() const { return dir_; }
  const geometry::Rig& rig() const { return rig_; }
  const map::HdMap& map() const { return map_; }
  const std::vector<StampedPose>& groundTruth() const { return ground_truth_; }
  // The level per frame set (levels.csv), ground truth for evaluation; empty when absent.
  const std::vector<StampedLevel>& levelTruth() const { return level_truth_; }
  const std::vector<OdometrySample>& odometry() const { return odometry_; }
  const std::string& metaJson() const { return meta_json_; }  // raw text, "{}" when absent

  // Frame-set timestamps, ascending (the union over cameras).
  const std::vector<double>& timestamps() const { return timestamps_; }
  // Cameras of the rig that have an image folder or a video; warnings() says which are missing.
  const std::vector<std::string>& cameras() const { return cameras_; }
  const std::vector<std::string>& warnings() const { return warnings_; }

  // Path of a frame's image; empty when that camera has no image file at that time (none, or
  // the camera is recorded as a video).
  std::string imagePath(size_t frame, const std::string& camera) const;
  // When the camera captured its image of the frame set; empty when it has none.
  std::optional<double> captureTime(size_t frame, const std::string& camera) const;
  // The decoded image; empty when missing or corrupt (the reason in *why when given). Video
  // frames decode fastest in order.
  cv::Mat loadImage(size_t frame, const std::string& camera, std::string* why = nullptr) const;
  std::optional<ImageLabels> loadLabels(size_t frame, const std::string& camera) const;

 private:
  std::string dir_;
  geometry::Rig rig_;
  map::HdMap map_;
  std::vector<StampedPose> ground_truth_;
  std::vector<StampedLevel> level_truth_;
  std::vector<OdometrySample> odometry_;
  std::string meta_json_ = "{}";
  std::vector<double> timestamps_;
  std::vector<std::string> cameras_;
  std::vector<std::string> warnings_;
  // camera -> (frame index -> image path)
  std::map<std::string, std::map<size_t, std::string>> images_;
  // camera -> (frame index -> frame in its video), and the camera's video
  std::map<std::string, std::map<size_t, int>> video_frames_;
  std::map<std::string, std::shared_ptr<VideoReader>> videos_;
  // camera -> (frame index -> capture time)
  std::map<std::string, std::map<size_t, double>> capture_times_;
};

}  // namespace parkloc::io
