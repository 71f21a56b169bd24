#include "sim/floor_finish.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace parkloc::sim {

void coatWithEpoxy(Garage& g, float strength, std::mt19937_64& rng) {
  const float s = std::clamp(strength, 0.0f, 1.0f);
  // Colours of coated garage floors: the common green, a grey-green, a light grey, a blue-grey.
  const std::vector<Eigen::Vector3f> coats = {
      {0.13f, 0.30f, 0.17f}, {0.30f, 0.40f, 0.32f}, {0.52f, 0.53f, 0.52f}, {0.30f, 0.38f, 0.46f}};
  const Eigen::Vector3f coat =
      coats[std::uniform_int_distribution<size_t>(0, coats.size() - 1)(rng)];
  g.floor_albedo = g.floor_albedo + s * (coat - g.floor_albedo);
  // The coat fills the concrete's pores: its grain shows at a quarter of its contrast.
  const cv::Mat& base = g.concrete.levelTexels(0);
  const double mean = cv::mean(base)[0];
  cv::Mat flat;
  base.convertTo(flat, CV_8U, 1.0 - 0.75 * s, mean * 0.75 * s);
  g.concrete = MipTexture(flat, g.concrete.wraps());
  g.gloss = std::max(g.gloss, 0.35f * s);
}

void makeFloorGlossy(Garage& g, float strength, std::mt19937_64& rng) {
  g.gloss = std::max(g.gloss, std::clamp(strength, 0.0f, 1.0f));
  const double tpm = g.wetness_texels_per_metre;
  const cv::Size size(static_cast<int>(std::ceil(g.size.x() * tpm)) + 1,
                      static_cast<int>(std::ceil(g.size.y() * tpm)) + 1);
  for (GarageLevel& level : g.levels) {
    // Puddles: smooth noise thresholded, covering about a fifth of the floor.
    cv::Mat noise(size, CV_32F);
    cv::RNG(rng()).fill(noise, cv::RNG::NORMAL, 0.0, 1.0);
    cv::GaussianBlur(noise, noise, cv::Size(0, 0), 1.2 * tpm);
    cv::normalize(noise, noise, 0.0, 1.0, cv::NORM_MINMAX);
    cv::Mat wet = (noise - 0.62) * 8.0;
    wet = cv::max(cv::min(wet, 1.0), 0.0);
    level.floor_wetness = wet;
  }
}

float fresnelSchlick(float cos_incidence, float f0) {
  const float c = std::clamp(1.0f - cos_incidence, 0.0f, 1.0f);
  const float c2 = c * c;
  return f0 + (1.0f - f0) * c2 * c2 * c;
}

}  // namespace parkloc::sim
