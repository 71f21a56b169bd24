#include "localize/spotting.h"

#include <fmt/format.h>

#include "common/error.h"
#include "localize/stage_clock.h"

namespace parkloc::localize {

std::vector<bool> spotCameras(const FrameInput& frame, const geometry::Rig& rig,
                              ocr::TextSpotter* spotter, const std::vector<bool>& full_frame,
                              const std::function<ocr::SpotRequest(size_t c)>& request,
                              FrameResult& result) {
  for (const auto& input : frame.cameras)
    if (!rig.find(input.camera))
      result.warnings.push_back("camera '" + input.camera + "' is not in the rig: ignored");
  std::vector<bool> supplied(rig.cameras.size(), false);
  for (size_t c = 0; c < rig.cameras.size(); ++c) {
    const auto& camera = rig.cameras[c];
    CameraResult camera_result;
    camera_result.camera = camera.name;
    camera_result.full_frame = full_frame[c];
    const CameraInput* input = nullptr;
    for (const auto& in : frame.cameras)
      if (in.camera == camera.name) input = &in;
    if (!input) {
      camera_result.image_ok = false;
      result.warnings.push_back("camera '" + camera.name + "': no input this frame");
    } else if (input->instances) {
      camera_result.instances = *input->instances;
      supplied[c] = true;
    } else if (input->image.empty()) {
      camera_result.image_ok = false;
      result.warnings.push_back("camera '" + camera.name + "': image missing or corrupt, skipped");
    } else if (input->image.cols != camera.model.width || input->image.rows != camera.model.height) {
      // The floor view, the regions and every projection follow the calibration: an image of
      // another size (another camera, a resized recording) would be read as garbage.
      camera_result.image_ok = false;
      result.warnings.push_back(fmt::format(
          "camera '{}': image is {}x{} but its calibration is {}x{}: skipped", camera.name,
          input->image.cols, input->image.rows, camera.model.width, camera.model.height));
    } else if (!spotter) {
      result.warnings.push_back("camera '" + camera.name + "': no spotter and no instances");
    } else {
      const ocr::SpotRequest camera_request = request(c);
      if (!full_frame[c]) camera_result.regions = static_cast<int>(camera_request.regions.size());
      const Stopwatch spot_time;
      if (full_frame[c] || !camera_request.regions.empty()) {
        try {
          camera_result.instances = spotter->spot(input->image, camera_request);
        } catch (const InputError& e) {
          camera_result.image_ok = false;
          result.warnings.push_back("camera '" + camera.name + "': " + e.what());
        }
      }
      result.timings.spotting_ms += spot_time.elapsedMs();
    }
    result.cameras.push_back(std::move(camera_result));
  }
  return supplied;
}

}  // namespace parkloc::localize
