// Cost of the evaluation metrics, so that scoring a dataset never dominates running it:
// polygon IoU and ICDAR matching of one image's instances, trajectory error of a drive.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "eval/text_matching.h"
#include "eval/trajectory_metrics.h"
#include "geometry/image_polygon.h"
#include "geometry/pose.h"

namespace {

using parkloc::geometry::Quad;

Quad rotatedBox(float cx, float cy, float w, float h, float angle) {
  const float c = std::cos(angle), s = std::sin(angle);
  Quad q;
  const float dx[4] = {-w / 2, w / 2, w / 2, -w / 2}, dy[4] = {-h / 2, -h / 2, h / 2, h / 2};
  for (int i = 0; i < 4; ++i)
    q[i] = cv::Point2f(cx + c * dx[i] - s * dy[i], cy + s * dx[i] + c * dy[i]);
  return q;
}

void BM_PolygonIoU(benchmark::State& state) {
  const Quad a = rotatedBox(100, 100, 80, 30, 0.3f), b = rotatedBox(104, 98, 78, 32, 0.35f);
  for (auto _ : state) benchmark::DoNotOptimize(parkloc::geometry::polygonIoU(a, b));
}
BENCHMARK(BM_PolygonIoU);

// One camera image with `n` labelled instances and as many noisy detections.
void BM_MatchImage(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> pos(0, 1200), jitter(-3, 3), angle(-3.1f, 3.1f);
  std::vector<Quad> truths, detections;
  for (int i = 0; i < n; ++i) {
    const float x = pos(rng), y = pos(rng) * 0.6f, a = angle(rng);
    truths.push_back(rotatedBox(x, y, 80, 30, a));
    detections.push_back(rotatedBox(x + jitter(rng), y + jitter(rng), 78, 31, a + 0.02f));
  }
  const std::vector<bool> dont_care(truths.size(), false);
  for (auto _ : state) {
    benchmark::DoNotOptimize(parkloc::eval::matchDetections(truths, dont_care, detections));
  }
}
BENCHMARK(BM_MatchImage)->Arg(10)->Arg(40);

// A 5-minute drive at 10 Hz.
void BM_TrajectoryError(benchmark::State& state) {
  std::vector<parkloc::io::StampedPose> truth, estimate;
  for (int i = 0; i < 3000; ++i) {
    const double t = i * 0.1;
    truth.push_back({t, parkloc::geometry::Pose2(t, std::sin(t), 0.1 * t).toRigid3()});
    estimate.push_back(
        {t + 0.001, parkloc::geometry::Pose2(t + 0.02, std::sin(t), 0.1 * t).toRigid3()});
  }
  for (auto _ : state) benchmark::DoNotOptimize(parkloc::eval::trajectoryError(estimate, truth));
}
BENCHMARK(BM_TrajectoryError);

}  // namespace

BENCHMARK_MAIN();
