#include "sim/camera_effects.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <random>

namespace parkloc::sim {
namespace {

double uniform(std::mt19937_64& rng, double a, double b) {
  return std::uniform_real_distribution<double>(a, b)(rng);
}

constexpr int kReduce = 4;  // the wide blurs of glare, dirt and metering run at 1/4 size

}  // namespace

CameraEffects::CameraEffects(const AppearanceOptions& appearance, const geometry::Rig& rig,
                             uint64_t seed)
    : a_(appearance), active_(appearance.changesCamera()) {
  std::mt19937_64 rng(seed ^ 0xca3e7a5eULL);
  // The lamps' cast: warm (sodium, halogen) to cool green-blue (old fluorescent tubes), the same
  // for the drive, each camera's white balance correcting it a little differently.
  const double warmth = uniform(rng, -1.0, 1.0), tint = uniform(rng, -0.5, 1.0);
  for (size_t c = 0; c < rig.cameras.size(); ++c) {
    const double w = a_.white_balance * (0.22 * warmth + uniform(rng, -0.06, 0.06));
    const double gt = a_.white_balance * (0.07 * tint + uniform(rng, -0.03, 0.03));
    white_balance_.emplace_back(static_cast<float>(1.0 - w), static_cast<float>(1.0 + gt),
                                static_cast<float>(1.0 + w));
    phase_.push_back(uniform(rng, 0.0, 6.283));
    const geometry::CameraModel& m = rig.cameras[c].model;
    cv::Mat dirt(m.height / kReduce, m.width / kReduce, CV_32F, cv::Scalar(0));
    if (a_.lens_dirt > 0.0f) {
      // Smudges (wide, faint) and dried drops (small, denser), more toward the lens' rim.
      const int smudges = 3 + static_cast<int>(uniform(rng, 0, 4));
      for (int i = 0; i < smudges; ++i)
        cv::circle(dirt,
                   cv::Point(static_cast<int>(uniform(rng, 0, dirt.cols)),
                             static_cast<int>(uniform(rng, 0, dirt.rows))),
                   static_cast<int>(uniform(rng, 0.06, 0.18) * dirt.cols),
                   cv::Scalar(uniform(rng, 0.12, 0.3)), -1, cv::LINE_AA);
      const int drops = 10 + static_cast<int>(uniform(rng, 0, 20));
      for (int i = 0; i < drops; ++i)
        cv::circle(dirt,
                   cv::Point(static_cast<int>(uniform(rng, 0, dirt.cols)),
                             static_cast<int>(uniform(rng, 0, dirt.rows))),
                   static_cast<int>(uniform(rng, 0.008, 0.03) * dirt.cols),
                   cv::Scalar(uniform(rng, 0.5, 0.9)), -1, cv::LINE_AA);
      cv::GaussianBlur(dirt, dirt, cv::Size(0, 0), 0.01 * dirt.cols + 1.0);
      dirt *= a_.lens_dirt;
    }
    dirt_.push_back(dirt);
  }
}

double CameraEffects::huntingGain(size_t camera, double t) const {
  // The exposure loop overshoots and settles: two slow oscillations of about 0.35 and 0.15
  // stops at full strength.
  const double phase = phase_.at(camera);
  const double stops = a_.auto_exposure * (0.35 * std::sin(6.283 * t / 5.3 + phase) +
                                           0.15 * std::sin(6.283 * t / 1.9 + 2.0 * phase));
  return std::exp2(stops);
}

void CameraEffects::apply(cv::Mat& bgr, size_t camera, double t, uint64_t frame_seed) const {
  develop(bgr, camera, t);
  compress(bgr, camera, frame_seed);
}

void CameraEffects::develop(cv::Mat& bgr, size_t camera, double t) const {
  if (!active_) return;
  CV_Assert(bgr.type() == CV_8UC3);
  const cv::Size full = bgr.size();
  const cv::Size small(full.width / kReduce, full.height / kReduce);
  // Optics, in linear light: flare and lens dirt scatter the light of the lamps in view.
  if (a_.flare > 0.0f || a_.lens_dirt > 0.0f) {
    cv::Mat img;
    bgr.convertTo(img, CV_32FC3, 1.0 / 255.0);
    cv::pow(img, 2.2, img);
    cv::Mat reduced, luma, bright;
    cv::resize(img, reduced, small, 0, 0, cv::INTER_AREA);
    cv::cvtColor(reduced, luma, cv::COLOR_BGR2GRAY);
    // Lamps clip: what is near white stands for far more light than the image shows.
    bright = cv::max(luma - 0.8, 0.0) * 5.0;
    cv::Mat scatter(small, CV_32FC3, cv::Scalar::all(0));
    if (a_.flare > 0.0f) {
      cv::Mat glare, ghost;
      cv::GaussianBlur(bright, glare, cv::Size(0, 0), 0.06 * small.width);
      cv::flip(bright, ghost, -1);  // a ghost mirrored through the optical centre
      cv::GaussianBlur(ghost, ghost, cv::Size(0, 0), 0.02 * small.width);
      cv::Mat glare3, ghost3;
      cv::merge(std::vector<cv::Mat>{glare, glare, glare}, glare3);
      cv::merge(std::vector<cv::Mat>{ghost * 0.9, ghost * 1.0, ghost * 0.5}, ghost3);
      scatter += a_.flare * (0.7 * glare3 + 0.6 * ghost3);
    }
    cv::Mat veil;
    if (a_.lens_dirt > 0.0f) {
      // Dirt spreads the light it catches: the image under it is veiled by its surroundings,
      // and it glows where a lamp is near.
      cv::GaussianBlur(reduced, veil, cv::Size(0, 0), 0.03 * small.width);
      cv::Mat glow;
      cv::GaussianBlur(bright, glow, cv::Size(0, 0), 0.08 * small.width);
      cv::Mat dirt3, glow3;
      cv::merge(std::vector<cv::Mat>{dirt_[camera], dirt_[camera], dirt_[camera]}, dirt3);
      cv::merge(std::vector<cv::Mat>{glow, glow, glow}, glow3);
      scatter += 3.0 * dirt3.mul(glow3);
    }
    cv::Mat scatter_full;
    cv::resize(scatter, scatter_full, full, 0, 0, cv::INTER_LINEAR);
    if (a_.lens_dirt > 0.0f) {
      cv::Mat veil_full, dirt_full, dirt3;
      cv::resize(veil, veil_full, full, 0, 0, cv::INTER_LINEAR);
      cv::resize(dirt_[camera], dirt_full, full, 0, 0, cv::INTER_LINEAR);
      cv::merge(std::vector<cv::Mat>{dirt_full, dirt_full, dirt_full}, dirt3);
      dirt3 *= 0.6;
      img = img.mul(cv::Scalar::all(1.0) - dirt3) + veil_full.mul(dirt3);
    }
    img += scatter_full;
    img = cv::max(img, 0.0);
    cv::pow(img, 1.0 / 2.2, img);
    img.convertTo(bgr, CV_8UC3, 255.0);
  }
  // The image processor: exposure gain and white balance in linear light, then the tone curve.
  if (a_.auto_exposure > 0.0f || a_.white_balance > 0.0f || a_.hdr_clipping > 0.0f) {
    double gain = huntingGain(camera, t);
    if (a_.auto_exposure > 0.0f) {
      // Metering pulls the mean toward mid grey, partly: a dark scene is brightened (and its
      // noise with it), a scene with lamps in view darkened.
      // Metered inside the lens' circle only (the black beyond it is no scene).
      cv::Mat grey;
      cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
      const double mean = std::max(8.0, cv::mean(grey, grey > 4)[0]);
      gain *= std::pow(118.0 / mean, 0.5 * a_.auto_exposure);
      gain = std::clamp(gain, 0.35, 3.0);
    }
    const cv::Vec3f wb = white_balance_[camera];
    // HDR tone mapping of a multi-exposure sensor pushed too far: a black level cut and an
    // early white clip.
    const double black = 0.05 * a_.hdr_clipping, white = 1.0 - 0.15 * a_.hdr_clipping;
    cv::Mat lut(1, 256, CV_8UC3);
    for (int v = 0; v < 256; ++v)
      for (int ch = 0; ch < 3; ++ch) {
        const double lin = std::pow(v / 255.0, 2.2) * gain * wb[ch];
        const double display = std::pow(std::max(0.0, lin), 1.0 / 2.2);
        const double y = std::clamp((display - black) / (white - black), 0.0, 1.0);
        lut.at<cv::Vec3b>(0, v)[ch] = cv::saturate_cast<uint8_t>(255.0 * y);
      }
    cv::LUT(bgr, lut, bgr);
  }
}

void CameraEffects::compress(cv::Mat& bgr, size_t camera, uint64_t frame_seed) const {
  if (a_.compression > 0.0f) {
    // The codec of a car's camera stream at a low bit rate: 8x8 blocks, chroma at half size.
    std::mt19937_64 rng(frame_seed ^ 0xb10c4ULL ^ camera);
    const int quality = std::clamp(
        static_cast<int>(std::lround(60.0 - 45.0 * a_.compression + uniform(rng, -4, 4))), 5, 95);
    std::vector<uint8_t> buffer;
    cv::imencode(".jpg", bgr, buffer, {cv::IMWRITE_JPEG_QUALITY, quality});
    bgr = cv::imdecode(buffer, cv::IMREAD_COLOR);
  }
}

}  // namespace parkloc::sim
