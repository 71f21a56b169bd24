#pragma once
// Helpers shared by the training-data exporters (detector_training_data,
// recognizer_training_data, classifier_training): which frames of a sequence to use, its
// images as BGR, folder creation and image writing with IoError, and the name a sequence
// folder gives its files.
#include <cstddef>
#include <filesystem>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "io/sequence.h"

namespace parkloc::ocr {

// The folder's last component ("…/g01_B1_d0/" -> "g01_B1_d0").
std::string sequenceName(const std::string& dir);

// Every `stride`-th frame index of the sequence, at most `max_frames` frames (0: all).
std::vector<size_t> sampledFrames(const io::Sequence& sequence, size_t stride, size_t max_frames);

// The frame's image of `camera` as 8-bit BGR; empty when it cannot be read.
cv::Mat loadBgrImage(const io::Sequence& sequence, size_t frame, const std::string& camera);

// Throw IoError naming the path when the folder cannot be made or the image written.
void createDirectory(const std::filesystem::path& dir);
void writeImage(const std::filesystem::path& path, const cv::Mat& image);

}  // namespace parkloc::ocr
