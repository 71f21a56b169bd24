#include <opencv2/imgproc.hpp>

#include "common/error.h"
#include "ocr/ppocr/dedup.h"
#include "ocr/ppocr/pp_ocr_models.h"
#include "ocr/ppocr/pp_ocr_spotter.h"

namespace parkloc::ocr {

std::vector<TextInstance> PpOcrSpotter::spotBirdsEye(const cv::Mat& image,
                                                     const SpotRequest& request,
                                                     std::optional<double> metres_per_pixel) {
  requireBgrImage(image, "birdseye image");
  if (metres_per_pixel && !(*metres_per_pixel > 0.0 && *metres_per_pixel < 1.0))
    throw InputError("birdseye: metres per pixel must be in (0, 1), not " +
                     std::to_string(*metres_per_pixel));
  // The floor detector learned numbers at the floor view's scale: resample to it.
  const double scale =
      metres_per_pixel ? *metres_per_pixel / options_.detection.floor_view.resolution : 1.0;
  cv::Mat view = image;
  if (std::abs(scale - 1.0) > 1e-3)
    cv::resize(image, view, cv::Size(), scale, scale,
               scale < 1.0 ? cv::INTER_AREA : cv::INTER_LINEAR);
  SpotRequest floor_request = request;
  floor_request.camera = nullptr;
  floor_request.placed_floor_texts.clear();
  floor_request.regions.clear();
  // The reading cascade reads a box either way round; a quarter turn lets the detector see
  // text that runs down the image as it sees text that runs across.
  std::vector<TextInstance> out;
  for (const bool turned : {false, true}) {
    cv::Mat input = view;
    if (turned) cv::rotate(view, input, cv::ROTATE_90_CLOCKWISE);
    std::vector<TextInstance> found =
        detectAndRead(input, floor_request, nullptr, DetectorRole::kFloorView, nullptr, 1.f,
                      {options_.detection.birdseye_unfitted_unclip_ratio, nullptr});
    for (TextInstance& inst : found)
      for (auto& p : inst.polygon) {
        // A quarter turn clockwise maps view (x, y) to (rows - 1 - y, x).
        if (turned) p = cv::Point2f(p.y, static_cast<float>(view.rows - 1) - p.x);
        p = cv::Point2f((p.x + 0.5f) / static_cast<float>(scale) - 0.5f,
                        (p.y + 0.5f) / static_cast<float>(scale) - 0.5f);
      }
    appendUnseen(out, std::move(found));
  }
  for (TextInstance& inst : out) {
    const auto [cls, score] = models_->headFor(inst).classify(image, inst.polygon, inst.text);
    inst.cls = cls;
    inst.class_score = score;
  }
  return out;
}

}  // namespace parkloc::ocr
