#include "io/sequence_video.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <opencv2/videoio.hpp>

#include "common/error.h"

namespace parkloc::io {
namespace fs = std::filesystem;

void writeSequenceVideos(const Sequence& sequence, const std::string& out_dir,
                         const SequenceVideoOptions& options) {
  const fs::path out(out_dir);
  if (fs::exists(out) && !(fs::is_directory(out) && fs::is_empty(out)))
    throw InputError(fmt::format("{}: exists and is not an empty folder", out_dir));
  if (options.fourcc.size() != 4)
    throw InputError(fmt::format("codec '{}' is not a FourCC", options.fourcc));
  if (options.mjpeg_quality < 1 || options.mjpeg_quality > 100)
    throw InputError(fmt::format("JPEG quality {} is not in 1-100", options.mjpeg_quality));
  fs::create_directories(out / "videos");
  const fs::path in(sequence.dir());
  for (const char* file : {"calib.yaml", "map.geojson", "odometry.csv", "poses.tum",
                           "levels.csv", "meta.json"})
    if (fs::is_regular_file(in / file)) fs::copy_file(in / file, out / file);
  if (fs::is_directory(in / "labels"))
    fs::copy(in / "labels", out / "labels", fs::copy_options::recursive);

  const int fourcc = cv::VideoWriter::fourcc(options.fourcc[0], options.fourcc[1],
                                             options.fourcc[2], options.fourcc[3]);
  const bool mjpeg = options.fourcc == "MJPG";
  const int backend = mjpeg ? cv::CAP_OPENCV_MJPEG : cv::CAP_FFMPEG;
  for (const std::string& camera : sequence.cameras()) {
    const fs::path video = out / "videos" / (camera + options.extension);
    std::ofstream csv(out / "videos" / (camera + ".csv"));
    csv << "frame,timestamp\n";
    cv::VideoWriter writer;
    int written = 0;
    for (size_t i = 0; i < sequence.timestamps().size(); ++i) {
      const std::optional<double> t = sequence.captureTime(i, camera);
      if (!t) continue;
      const cv::Mat image = sequence.loadImage(i, camera);
      if (image.empty()) continue;
      if (!writer.isOpened()) {
        if (!writer.open(video.string(), backend, fourcc, options.fps, image.size()))
          throw InputError(fmt::format("{}: cannot write codec {} ({})", video.string(),
                                       options.fourcc, options.extension));
        if (mjpeg) writer.set(cv::VIDEOWRITER_PROP_QUALITY, options.mjpeg_quality);
      }
      writer.write(image);
      csv << fmt::format("{},{:.6f}\n", written++, *t);
    }
  }
}

}  // namespace parkloc::io
