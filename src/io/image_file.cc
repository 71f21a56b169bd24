#include "io/image_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <opencv2/imgcodecs.hpp>

namespace parkloc::io {
namespace {

// A compressed frame far beyond this is not a camera frame (a 1280x800 JPEG is ~200 KB).
constexpr long long kMaxFrameFileBytes = 1LL << 28;

unsigned readBigEndian16(const std::vector<unsigned char>& b, size_t at) {
  return (unsigned{b[at]} << 8) | b[at + 1];
}
unsigned long readBigEndian32(const std::vector<unsigned char>& b, size_t at) {
  return (static_cast<unsigned long>(readBigEndian16(b, at)) << 16) | readBigEndian16(b, at + 2);
}

std::optional<cv::Size> pngSize(const std::vector<unsigned char>& b) {
  // Signature (8 bytes), then the IHDR chunk: length, "IHDR", width, height (big endian).
  static const unsigned char kIhdr[] = {'I', 'H', 'D', 'R'};
  if (b.size() < 24 || !std::equal(kIhdr, kIhdr + 4, b.begin() + 12)) return std::nullopt;
  const unsigned long width = readBigEndian32(b, 16);
  const unsigned long height = readBigEndian32(b, 20);
  if (width == 0 || height == 0 || width > 0x7fffffffUL || height > 0x7fffffffUL)
    return std::nullopt;
  return cv::Size(static_cast<int>(width), static_cast<int>(height));
}

std::optional<cv::Size> jpegSize(const std::vector<unsigned char>& b) {
  // Walk the marker segments after SOI up to the first start-of-frame (SOFn: C0-CF except
  // DHT C4, JPG C8, DAC CC), which holds precision, height, width.
  size_t i = 2;
  while (i + 4 <= b.size()) {
    if (b[i] != 0xFF) return std::nullopt;
    const unsigned char marker = b[i + 1];
    if (marker == 0xFF) {  // fill byte
      ++i;
      continue;
    }
    if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) {  // no payload
      i += 2;
      continue;
    }
    if (marker == 0xD9 || marker == 0xDA) return std::nullopt;  // EOI or scan before a frame
    const size_t length = readBigEndian16(b, i + 2);
    if (length < 2) return std::nullopt;
    const bool sof =
        marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
    if (sof) {
      if (length < 7 || i + 9 > b.size()) return std::nullopt;
      const int height = static_cast<int>(readBigEndian16(b, i + 5));
      const int width = static_cast<int>(readBigEndian16(b, i + 7));
      if (width == 0 || height == 0) return std::nullopt;
      return cv::Size(width, height);
    }
    i += 2 + length;
  }
  return std::nullopt;
}

}  // namespace

std::optional<cv::Size> frameImageSize(const std::vector<unsigned char>& bytes) {
  static const unsigned char kPng[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (bytes.size() >= 8 && std::equal(kPng, kPng + 8, bytes.begin())) return pngSize(bytes);
  if (bytes.size() >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF)
    return jpegSize(bytes);
  return std::nullopt;
}

cv::Mat decodeFrameImage(const std::vector<unsigned char>& bytes, std::string* why) {
  auto failed = [&](const std::string& reason) {
    if (why) *why = reason;
    return cv::Mat();
  };
  if (bytes.empty()) return failed("empty file");
  const auto size = frameImageSize(bytes);
  // Not a JPEG or PNG, or a malformed header: no decoder gets to see the bytes.
  if (!size) return failed("cannot decode the image");
  if (static_cast<long long>(size->width) * size->height > kMaxFramePixels)
    return failed(fmt::format("header says {}x{} pixels, more than a camera frame can have",
                              size->width, size->height));
  cv::Mat image;
  try {
    image = cv::imdecode(bytes, cv::IMREAD_COLOR);
  } catch (const cv::Exception& e) {
    return failed(fmt::format("cannot decode ({})", e.err));
  }
  if (image.empty()) return failed("cannot decode the image");
  if (why) why->clear();
  return image;
}

cv::Mat readFrameImage(const std::string& path, std::string* why) {
  auto failed = [&](const std::string& reason) {
    if (why) *why = fmt::format("{}: {}", path, reason);
    return cv::Mat();
  };
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return failed("cannot open");
  const std::streamoff length = in.tellg();
  if (length < 0) return failed("cannot read");
  if (length > kMaxFrameFileBytes)
    return failed(fmt::format("{} bytes, too large for a camera frame", length));
  std::vector<unsigned char> bytes(static_cast<size_t>(length));
  in.seekg(0);
  if (length > 0 && !in.read(reinterpret_cast<char*>(bytes.data()), length))
    return failed("cannot read");
  std::string reason;
  cv::Mat image = decodeFrameImage(bytes, &reason);
  if (image.empty()) return failed(reason);
  if (why) why->clear();
  return image;
}

}  // namespace parkloc::io
