#include "sim/legibility.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/renderer.h"

namespace parkloc::sim {

ImageBlur imageBlur(const LightingOptions& light, const geometry::RigCamera& camera) {
  ImageBlur blur;
  blur.defocus_sigma_px = std::max(0.0f, light.defocus_sigma);
  if (light.motion_blur_px > 1.0f) {
    const bool side = std::abs(camera.vehicle_from_camera.linear().col(2).y()) > 0.5;
    const long length = std::lround(side ? light.motion_blur_px : light.motion_blur_px / 3.0f);
    if (length > 1) blur.motion_length_px = static_cast<double>(length);
  }
  return blur;
}

double blurModulation(const ImageBlur& blur, const Eigen::Vector2d& direction,
                      double cycles_per_px) {
  const double f = std::abs(cycles_per_px);
  if (f > 0.5) return 0.0;
  const double s = blur.defocus_sigma_px;
  double modulation = std::exp(-2.0 * M_PI * M_PI * s * s * f * f);
  // The horizontal box of L pixels, seen along `direction`, is a box of L |dx| pixels; its
  // discrete response sin(pi L f) / (L sin(pi f)) counts only up to its first zero: past it,
  // the side lobes give contrast back reversed, which no reader reads.
  const double length = blur.motion_length_px * std::abs(direction.normalized().x());
  if (length > 1.0 && f > 0.0) {
    if (length * f >= 1.0) return 0.0;
    modulation *= std::sin(M_PI * length * f) / (length * std::sin(M_PI * f));
  }
  return modulation;
}

bool isLegible(const geometry::TextPolygon& p, int characters, const ImageBlur& blur,
               const LegibilityOptions& options) {
  const double height = geometry::apparentHeightPx(p);
  if (!(height >= options.min_height_px)) return false;
  const double pitch = geometry::readingLengthPx(p) / std::max(1, characters);
  const Eigen::Vector2d along = (0.5 * (p[1] + p[2]) - 0.5 * (p[0] + p[3])).normalized();
  const Eigen::Vector2d across = (0.5 * (p[0] + p[1]) - 0.5 * (p[3] + p[2])).normalized();
  const double c = options.cycles_per_character;
  return blurModulation(blur, along, c / pitch) >= options.min_modulation &&
         blurModulation(blur, across, c / height) >= options.min_modulation;
}

double featureSnr(const geometry::TextPolygon& p, int characters, const InkContrast& ink,
                  const LegibilityOptions& options) {
  const double height = geometry::apparentHeightPx(p);
  const double pitch = geometry::readingLengthPx(p) / std::max(1, characters);
  const double half_cycle = 0.5 / options.cycles_per_character;  // of a pitch, of a height
  const double area = std::max(0.0, pitch * half_cycle) * std::max(0.0, height * half_cycle);
  const double white = ink.channel_noise * kLumaNoisePerChannelNoise;
  const double luma_noise = std::sqrt(white * white + ink.block_noise * ink.block_noise * area);
  const double signal = std::abs(ink.luma_levels) * std::sqrt(area);
  if (!(luma_noise > 0.0)) return signal > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
  return signal / luma_noise;
}

bool inkStandsOut(const geometry::TextPolygon& p, int characters, const InkContrast& ink,
                  const LegibilityOptions& options) {
  return featureSnr(p, characters, ink, options) >= options.min_feature_snr;
}

int characterCount(const std::string& text) {
  int n = 0;
  for (const char ch : text)
    if ((static_cast<unsigned char>(ch) & 0xC0) != 0x80) ++n;
  return std::max(1, n);
}

}  // namespace parkloc::sim
