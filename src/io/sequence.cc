#include "io/sequence.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "common/error.h"
#include "io/calibration_yaml.h"
#include "io/image_file.h"
#include "io/frame_sets.h"
#include "io/map_geojson.h"
#include "io/video_timestamps.h"

namespace parkloc::io {
namespace fs = std::filesystem;

namespace {

std::optional<double> parseStem(const std::string& stem) {
  if (stem.empty()) return std::nullopt;
  char* end = nullptr;
  const double t = std::strtod(stem.c_str(), &end);
  if (end != stem.c_str() + stem.size() || !std::isfinite(t)) return std::nullopt;
  return t;
}

bool isImageFile(const fs::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext == ".jpg" || ext == ".jpeg" || ext == ".png";
}

// videos/<camera>.<ext>, any extension but the timestamps' .csv; empty when there is none.
std::optional<fs::path> videoOf(const fs::path& videos, const std::string& camera) {
  if (!fs::is_directory(videos)) return std::nullopt;
  std::vector<fs::path> found;
  for (const auto& entry : fs::directory_iterator(videos))
    if (entry.is_regular_file() && entry.path().stem() == camera &&
        entry.path().extension() != ".csv")
      found.push_back(entry.path());
  if (found.empty()) return std::nullopt;
  if (found.size() > 1) {
    std::sort(found.begin(), found.end());
    throw InputError(fmt::format("camera '{}' has {} videos in {} ({}, {}, ...): keep one",
                                 camera, found.size(), videos.string(),
                                 found[0].filename().string(), found[1].filename().string()));
  }
  return found.front();
}

std::string readText(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw IoError(fmt::format("sequence: cannot read {}", p.string()));
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

std::string timestampStem(double timestamp) { return fmt::format("{:.6f}", timestamp); }

Sequence::Sequence(const std::string& dir, const std::string& calib_path,
                   const std::string& map_path, const std::string& odometry_path,
                   SequenceContents contents)
    : dir_(dir) {
  const bool truth = contents == SequenceContents::kAll;
  const fs::path root(dir);
  if (!fs::is_directory(root)) throw InputError(fmt::format("sequence {}: not a directory", dir));

  const fs::path calib = calib_path.empty() ? root / "calib.yaml" : fs::path(calib_path);
  if (!fs::is_regular_file(calib))
    throw InputError(fmt::format("sequence {}: calibration {} not found", dir, calib.string()));
  rig_ = loadCalibration(calib.string());

  if (truth) {
    const fs::path map_file = map_path.empty() ? root / "map.geojson" : fs::path(map_path);
    if (!fs::is_regular_file(map_file))
      throw InputError(fmt::format("sequence {}: map {} not found", dir, map_file.string()));
    map_ = loadMap(map_file.string());
    if (const fs::path poses = root / "poses.tum"; fs::is_regular_file(poses))
      ground_truth_ = loadTum(poses.string());
    if (const fs::path levels = root / "levels.csv"; fs::is_regular_file(levels))
      level_truth_ = loadLevels(levels.string());
  }
  const fs::path odometry = odometry_path.empty() ? root / "odometry.csv" : fs::path(odometry_path);
  if (fs::is_regular_file(odometry))
    odometry_ = loadOdometry(odometry.string());
  else if (!odometry_path.empty())
    throw InputError(fmt::format("sequence {}: odometry {} not found", dir, odometry.string()));
  if (const fs::path meta = root / "meta.json"; truth && fs::is_regular_file(meta))
    meta_json_ = readText(meta);

  // Per camera, its images: files named by their capture time, or a video with its times.
  const fs::path images = root / "images";
  const fs::path videos = root / "videos";
  std::map<std::string, std::vector<double>> times;         // camera -> capture times
  std::map<std::string, std::vector<std::string>> paths;    // ... image files, in that order
  std::map<std::string, std::vector<int>> frames_in_video;  // ... or video frames
  for (const auto& camera : rig_.cameras) {
    const fs::path folder = images / camera.name;
    const std::optional<fs::path> video = videoOf(videos, camera.name);
    if (video && fs::is_directory(folder))
      throw InputError(fmt::format("sequence {}: camera '{}' has both {} and {}", dir,
                                   camera.name, folder.string(), video->string()));
    if (video) {
      const fs::path csv = videos / (camera.name + ".csv");
      if (!fs::is_regular_file(csv))
        throw InputError(fmt::format("sequence {}: video {} has no timestamps file {}", dir,
                                     video->string(), csv.string()));
      const std::vector<VideoFrameTime> rows = loadVideoTimestamps(csv.string());
      auto reader = std::make_shared<VideoReader>(video->string());
      if (reader->frameCount() > 0 && rows.back().frame >= reader->frameCount())
        throw InputError(fmt::format("video {}: {} frames, but {} lists frame {}",
                                     video->string(), reader->frameCount(), csv.string(),
                                     rows.back().frame));
      videos_[camera.name] = std::move(reader);
      for (const VideoFrameTime& row : rows) {
        times[camera.name].push_back(row.timestamp);
        frames_in_video[camera.name].push_back(row.frame);
      }
      cameras_.push_back(camera.name);
      continue;
    }
    if (!fs::is_directory(folder)) {
      warnings_.push_back(fmt::format("camera '{}': no images folder", camera.name));
      continue;
    }
    cameras_.push_back(camera.name);
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(folder))
      if (entry.is_regular_file() && isImageFile(entry.path())) files.push_back(entry.path());
    std::vector<std::pair<double, std::string>> stamped;
    std::set<std::string> stems;
    std::sort(files.begin(), files.end());
    for (const fs::path& file : files) {
      const std::string stem = file.stem().string();
      const auto t = parseStem(stem);
      if (!t) {
        warnings_.push_back(fmt::format("camera '{}': skipped {} (name is not a timestamp)",
                                        camera.name, file.filename().string()));
        continue;
      }
      if (!stems.insert(stem).second) {
        warnings_.push_back(fmt::format("camera '{}': skipped {} (another image has stem {})",
                                        camera.name, file.filename().string(), stem));
        continue;
      }
      stamped.emplace_back(*t, file.string());
    }
    std::sort(stamped.begin(), stamped.end());
    for (const auto& [t, path] : stamped) {
      times[camera.name].push_back(t);
      paths[camera.name].push_back(path);
    }
  }
  if (fs::is_directory(images)) {
    std::vector<std::string> unknown;
    for (const auto& entry : fs::directory_iterator(images))
      if (entry.is_directory() && !rig_.find(entry.path().filename().string()))
        unknown.push_back(entry.path().filename().string());
    std::sort(unknown.begin(), unknown.end());
    for (const auto& name : unknown)
      warnings_.push_back(
          fmt::format("images folder '{}' is not a camera of the rig; ignored", name));
  }

  const std::vector<FrameSet> sets = groupFrameSets(times, frameSetTolerance(times));
  for (size_t i = 0; i < sets.size(); ++i) {
    timestamps_.push_back(sets[i].timestamp);
    for (const auto& [camera, k] : sets[i].images) {
      capture_times_[camera][i] = times[camera][k];
      if (videos_.count(camera))
        video_frames_[camera][i] = frames_in_video[camera][k];
      else
        images_[camera][i] = paths[camera][k];
    }
  }
}

std::string Sequence::imagePath(size_t frame, const std::string& camera) const {
  const auto cam = images_.find(camera);
  if (cam == images_.end()) return "";
  const auto it = cam->second.find(frame);
  return it == cam->second.end() ? "" : it->second;
}

cv::Mat Sequence::loadImage(size_t frame, const std::string& camera, std::string* why) const {
  auto failed = [&](const std::string& reason) {
    if (why) *why = reason;
    return cv::Mat();
  };
  if (frame >= timestamps_.size())
    return failed(fmt::format("frame {} out of range ({} frames)", frame, timestamps_.size()));
  if (const auto video = videos_.find(camera); video != videos_.end()) {
    const auto& frames = video_frames_.at(camera);
    const auto it = frames.find(frame);
    if (it == frames.end())
      return failed(fmt::format("camera '{}' has no image at {}", camera,
                                timestampStem(timestamps_[frame])));
    std::string reason;
    cv::Mat image = video->second->frame(it->second, &reason);
    if (image.empty()) return failed(reason);
    if (why) why->clear();
    return image;
  }
  const std::string path = imagePath(frame, camera);
  if (path.empty())
    return failed(
        fmt::format("camera '{}' has no image at {}", camera, timestampStem(timestamps_[frame])));
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  if (ec) return failed(fmt::format("{}: cannot read ({})", path, ec.message()));
  if (size == 0) return failed(fmt::format("{}: empty file", path));
  // JPEG or PNG only, the header size checked before decoding (io/image_file.h).
  std::string reason;
  cv::Mat image = readFrameImage(path, &reason);
  if (image.empty()) return failed(reason);
  if (why) why->clear();
  return image;
}

std::optional<double> Sequence::captureTime(size_t frame, const std::string& camera) const {
  const auto cam = capture_times_.find(camera);
  if (cam == capture_times_.end()) return std::nullopt;
  const auto it = cam->second.find(frame);
  if (it == cam->second.end()) return std::nullopt;
  return it->second;
}

std::optional<ImageLabels> Sequence::loadLabels(size_t frame, const std::string& camera) const {
  if (frame >= timestamps_.size()) return std::nullopt;
  // Labels share the image's stem (its capture time); without an image, the frame set's.
  const std::string image = imagePath(frame, camera);
  const std::string stem =
      !image.empty() ? fs::path(image).stem().string()
                     : timestampStem(captureTime(frame, camera).value_or(timestamps_[frame]));
  const fs::path path = fs::path(dir_) / "labels" / camera / (stem + ".json");
  if (!fs::is_regular_file(path)) return std::nullopt;
  return io::loadLabels(path.string());
}

}  // namespace parkloc::io
