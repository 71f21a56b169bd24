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
#include "io/map_geojson.h"

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

  // Gather (camera, stem) -> path; a frame set is all images sharing one stem.
  const fs::path images = root / "images";
  std::map<std::string, std::map<std::string, std::string>> stems_by_camera;
  std::map<std::string, double> stem_time;
  for (const auto& camera : rig_.cameras) {
    const fs::path folder = images / camera.name;
    if (!fs::is_directory(folder)) {
      warnings_.push_back(fmt::format("camera '{}': no images folder", camera.name));
      continue;
    }
    cameras_.push_back(camera.name);
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(folder))
      if (entry.is_regular_file() && isImageFile(entry.path())) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& file : files) {
      const std::string stem = file.stem().string();
      const auto t = parseStem(stem);
      if (!t) {
        warnings_.push_back(fmt::format("camera '{}': skipped {} (name is not a timestamp)",
                                        camera.name, file.filename().string()));
        continue;
      }
      auto& by_stem = stems_by_camera[camera.name];
      if (by_stem.count(stem)) {
        warnings_.push_back(fmt::format("camera '{}': skipped {} (another image has stem {})",
                                        camera.name, file.filename().string(), stem));
        continue;
      }
      by_stem[stem] = file.string();
      stem_time[stem] = *t;
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

  std::vector<std::pair<double, std::string>> frames;
  for (const auto& [stem, t] : stem_time) frames.emplace_back(t, stem);
  std::sort(frames.begin(), frames.end());
  std::map<std::string, size_t> frame_of_stem;
  for (size_t i = 0; i < frames.size(); ++i) {
    timestamps_.push_back(frames[i].first);
    frame_of_stem[frames[i].second] = i;
  }
  for (const auto& [camera, by_stem] : stems_by_camera)
    for (const auto& [stem, path] : by_stem) images_[camera][frame_of_stem.at(stem)] = path;
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

std::optional<ImageLabels> Sequence::loadLabels(size_t frame, const std::string& camera) const {
  if (frame >= timestamps_.size()) return std::nullopt;
  // Labels share the image's stem; without an image, fall back to the canonical stem.
  const std::string image = imagePath(frame, camera);
  const std::string stem =
      image.empty() ? timestampStem(timestamps_[frame]) : fs::path(image).stem().string();
  const fs::path path = fs::path(dir_) / "labels" / camera / (stem + ".json");
  if (!fs::is_regular_file(path)) return std::nullopt;
  return io::loadLabels(path.string());
}

}  // namespace parkloc::io
