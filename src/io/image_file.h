#pragma once
// Camera frames as files: JPEG or PNG only. The bytes are checked before any decoder sees
// them: the format by its signature, the size in the header against what a camera can
// produce. A forged header cannot make the reader allocate gigabytes, and bytes of another
// format never reach the other codecs OpenCV carries (the Radiance HDR decoder of OpenCV
// 4.6 leaks a file descriptor on every corrupt file). Found by fuzz/fuzz_image.
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

namespace parkloc::io {

// Larger than any automotive camera (8 K x 8 K); a 3-channel frame of this size is 192 MiB.
constexpr long long kMaxFramePixels = 1LL << 26;

// Width and height from a JPEG (SOF segment) or PNG (IHDR) header; empty when the bytes are
// neither or the header is malformed.
std::optional<cv::Size> frameImageSize(const std::vector<unsigned char>& bytes);

// Decodes a JPEG or PNG frame to 8-bit BGR. Empty on failure, with the reason in *why.
cv::Mat decodeFrameImage(const std::vector<unsigned char>& bytes, std::string* why = nullptr);

// Reads and decodes a frame file; empty on failure (missing, empty, too large, another
// format, corrupt), with the reason naming the file in *why.
cv::Mat readFrameImage(const std::string& path, std::string* why = nullptr);

}  // namespace parkloc::io
