#pragma once
// Stage 3 of the pipeline, spotting: each rig camera's text instances for this frame set,
// from the instances the frame brings (oracle OCR, or spotted elsewhere) or from the
// injected spotter, asked as read planning says. A camera without input, with a missing or
// corrupt image, or whose image the spotter rejects, is reported in the warnings and left
// out; the others go on.
#include <functional>
#include <vector>

#include "geometry/rig.h"
#include "localize/frame_types.h"
#include "ocr/text_spotter.h"

namespace parkloc::localize {

// Fills result.cameras (rig order) and adds the spotter's time to result.timings. `request`
// gives camera c's request; `full_frame[c]`: camera c is spotted on the full frame. Returns,
// per rig camera, whether its instances came with the frame.
std::vector<bool> spotCameras(const FrameInput& frame, const geometry::Rig& rig,
                              ocr::TextSpotter* spotter, const std::vector<bool>& full_frame,
                              const std::function<ocr::SpotRequest(size_t c)>& request,
                              FrameResult& result);

}  // namespace parkloc::localize
