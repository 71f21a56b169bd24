#include "mapping/sightings.h"

#include <chrono>

namespace parkloc::mapping {

std::vector<Sighting> readDrive(const io::Sequence& drive, size_t drive_index,
                                ocr::TextSpotter& spotter, int frame_step,
                                const std::vector<std::string>& lexicon,
                                const ReadingOptions& options, ReadingStats& stats,
                                const std::function<void(size_t, size_t)>& progress) {
  const auto started = std::chrono::steady_clock::now();
  std::vector<Sighting> sightings;
  const geometry::Rig& rig = drive.rig();
  const size_t step = static_cast<size_t>(std::max(1, frame_step));
  const size_t frames = drive.timestamps().size();
  for (size_t frame = 0; frame < frames; frame += step) {
    ++stats.frame_sets;
    for (size_t c = 0; c < rig.cameras.size(); ++c) {
      const cv::Mat image = drive.loadImage(frame, rig.cameras[c].name);
      if (image.empty()) {
        ++stats.missing_images;
        continue;
      }
      ++stats.images;
      // No map and no placed texts: whatever the full frame shows, read freely or against
      // the numbering's strings; the camera lets the engine look for floor text in its
      // bird's-eye view of the floor.
      ocr::SpotRequest request;
      request.camera = &rig.cameras[c];
      request.lexicon = lexicon;
      for (const ocr::TextInstance& instance : spotter.spot(image, request)) {
        ++stats.instances;
        // Parking numbers only: their corners lie on the floor, the plane the vehicle drives
        // on. A text the engine fitted or cut rather than read carries no reading of its own.
        if (instance.cls != map::TextClass::kParkingNumber || instance.text.empty() ||
            !instance.read || instance.partial || instance.sized_by_map ||
            instance.recognition_score < options.min_recognition_score)
          continue;
        Sighting s;
        s.drive = drive_index;
        s.frame = frame;
        s.camera = static_cast<int>(c);
        s.text = instance.text;
        s.cls = instance.cls;
        for (int i = 0; i < 4; ++i) s.pixels[i] = {instance.polygon[i].x, instance.polygon[i].y};
        s.recognition_score = instance.recognition_score;
        s.second_opinion = instance.second_opinion;
        s.off_numbering = !lexicon.empty() && !instance.lexicon_match;
        s.box_only = instance.box_only;
        sightings.push_back(std::move(s));
      }
    }
    if (progress) progress(frame + 1, frames);
  }
  stats.seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return sightings;
}

}  // namespace parkloc::mapping
