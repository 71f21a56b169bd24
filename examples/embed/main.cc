// Localizes a vehicle along a recorded drive through parkloc's facade and prints the poses as
// TUM lines (timestamp x y z qx qy qz qw). The drive is a folder holding
//   calib.yaml  map.geojson  odometry.csv (timestamp,speed,yaw_rate)
//   videos/<camera>.<ext> and videos/<camera>.csv (frame,timestamp) for each camera
// Usage: embed SEQUENCE [CONFIG.yaml]
#include <parkloc/parkloc.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <opencv2/videoio.hpp>
#include <string>
#include <utility>

namespace fs = std::filesystem;

void print(const parkloc::PoseEstimate& p) {
  if (p.has_pose)
    std::printf("%.6f %.4f %.4f 0 0 0 %.6f %.6f\n", p.timestamp, p.x, p.y, std::sin(p.yaw / 2),
                std::cos(p.yaw / 2));
}

int main(int argc, char** argv) {
  if (argc < 2) return std::fprintf(stderr, "usage: embed SEQUENCE [CONFIG.yaml]\n"), 2;
  const fs::path dir = argv[1];
  parkloc::LocalizerSettings settings;
  settings.calibration_file = (dir / "calib.yaml").string();
  settings.map_file = (dir / "map.geojson").string();
  if (argc > 2) settings.config_file = argv[2];
  auto made = parkloc::Localizer::create(settings);
  if (!made.localizer) return std::fprintf(stderr, "embed: %s\n", made.error.c_str()), 1;
  parkloc::Localizer& localizer = *made.localizer;
  std::cerr << "models: " << localizer.modelsDir() << "\n";

  // Every camera's frames in capture-time order: time -> (camera, frame index in its video).
  std::multimap<double, std::pair<std::string, int>> frames;
  std::map<std::string, cv::VideoCapture> videos;
  std::map<std::string, int> next_frame;
  char comma;
  for (const auto& camera : localizer.cameras()) {
    std::ifstream times(dir / "videos" / (camera + ".csv"));
    std::string header;
    std::getline(times, header);
    int frame;
    double t;
    while (times >> frame >> comma >> t) frames.emplace(t, std::make_pair(camera, frame));
    for (const auto& entry : fs::directory_iterator(dir / "videos"))
      if (entry.path().stem() == camera && entry.path().extension() != ".csv")
        videos[camera].open(entry.path().string());
  }
  std::ifstream odometry(dir / "odometry.csv");
  std::string header;
  std::getline(odometry, header);
  double t_odo, speed, yaw_rate;
  bool have_odo = static_cast<bool>(odometry >> t_odo >> comma >> speed >> comma >> yaw_rate);

  for (const auto& [t, id] : frames) {
    // The samples up to this image's capture time go first, as a vehicle bus delivers them.
    for (; have_odo && t_odo <= t;
         have_odo = static_cast<bool>(odometry >> t_odo >> comma >> speed >> comma >> yaw_rate))
      localizer.addOdometry(t_odo, speed, yaw_rate);
    cv::Mat image;
    for (int& next = next_frame[id.first]; next <= id.second; ++next)
      if (!videos[id.first].read(image)) image.release();
    for (const auto& pose : localizer.addImage(id.first, t, image)) print(pose);
  }
  if (const auto pose = localizer.flush()) print(*pose);
  return 0;
}
