#pragma once
// The edges of the OCR module: reading images and lexicons, text instances as JSON and as
// one-line descriptions, and overlays for looking at the results.
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "ocr/text_spotter.h"

namespace parkloc::ocr {

// An 8-bit BGR image; throws IoError for a missing file and InputError for an empty or
// undecodable one (the path in the message).
cv::Mat readImage(const std::string& path);

// One candidate text a line; blank lines and surrounding spaces ignored. Throws IoError.
std::vector<std::string> loadLexiconFile(const std::string& path);

nlohmann::json toJson(const TextInstance& instance);
nlohmann::json toJson(const std::vector<TextInstance>& instances);
// "B2-117 [parking_number] rec 0.99 det 0.83 cls 0.97 (lexicon; raw B2-117) @ (x,y)..."
std::string describe(const TextInstance& instance);

// The image with each polygon (top edge thicker, the top-left corner marked), its text and
// class drawn.
cv::Mat drawInstances(const cv::Mat& image, const std::vector<TextInstance>& instances);

}  // namespace parkloc::ocr
