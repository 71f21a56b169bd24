// Per-stage timings of the localization pipeline (OCR excluded): box-plot filter, SE(2)
// solver, EKF step, association gate, map-guided region prediction, and a whole frame set
// on oracle instances.
#include <benchmark/benchmark.h>

#include <random>

#include "../tests/localize/synthetic_scene.h"
#include "localize/association_gate.h"
#include "localize/box_plot_filter.h"
#include "localize/pipeline.h"
#include "localize/pose_ekf.h"
#include "localize/pose_solver.h"
#include "localize/roi_prediction.h"

namespace {

using namespace parkloc;
using namespace parkloc::localize;

const geometry::Pose2 kTruth(12.0, 0.2, 0.15);

std::vector<LandmarkObservation> scene(int max_observations, double noise) {
  static const auto rig = geometry::defaultRig();
  static const auto map = testing::aisleMap();
  testing::SpotOptions spot;
  spot.pixel_noise = noise;
  spot.max_range_m = 10.0;
  std::mt19937 rng(3);
  auto obs = testing::observeExactly(rig, map, kTruth, spot, &rng);
  if (static_cast<int>(obs.size()) > max_observations) obs.resize(max_observations);
  return obs;
}

void BM_BoxPlotFilterAccept(benchmark::State& state) {
  BoxPlotFilter filter;
  for (int i = 0; i < 30; ++i) filter.accept(100 + i);
  int n = 0;
  for (auto _ : state) benchmark::DoNotOptimize(filter.accept(100 + (n++ % 30)));
}
BENCHMARK(BM_BoxPlotFilterAccept);

void BM_SolvePoseNoPrior(benchmark::State& state) {
  const auto rig = geometry::defaultRig();
  const auto obs = scene(static_cast<int>(state.range(0)), 1.0);
  for (auto _ : state) benchmark::DoNotOptimize(solvePose(rig, obs));
  state.counters["observations"] = static_cast<double>(obs.size());
}
BENCHMARK(BM_SolvePoseNoPrior)->Arg(1)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMicrosecond);

void BM_SolvePoseWithPrior(benchmark::State& state) {
  const auto rig = geometry::defaultRig();
  const auto obs = scene(static_cast<int>(state.range(0)), 1.0);
  const geometry::Pose2 prior(kTruth.x + 0.05, kTruth.y - 0.03, kTruth.yaw + 0.01);
  for (auto _ : state) benchmark::DoNotOptimize(solvePose(rig, obs, prior));
  state.counters["observations"] = static_cast<double>(obs.size());
}
BENCHMARK(BM_SolvePoseWithPrior)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMicrosecond);

void BM_RefinePose(benchmark::State& state) {
  const auto rig = geometry::defaultRig();
  const auto obs = scene(8, 1.0);
  const geometry::Pose2 initial(kTruth.x + 0.05, kTruth.y - 0.03, kTruth.yaw + 0.01);
  for (auto _ : state) benchmark::DoNotOptimize(refinePose(rig, obs, initial));
}
BENCHMARK(BM_RefinePose)->Unit(benchmark::kMicrosecond);

void BM_EkfPredictUpdate(benchmark::State& state) {
  PoseEkf ekf;
  ekf.initialise(kTruth, Eigen::Matrix3d::Identity() * 1e-3, 0.0);
  const Eigen::Matrix3d R = Eigen::Matrix3d::Identity() * 1e-4;
  for (auto _ : state) {
    for (int i = 0; i < 5; ++i) ekf.predictWithOdometry(2.0, 0.05, 0.02);
    ekf.update(ekf.pose(), R);
    benchmark::DoNotOptimize(ekf.covariance());
  }
}
BENCHMARK(BM_EkfPredictUpdate);

void BM_GateObservation(benchmark::State& state) {
  const auto rig = geometry::defaultRig();
  const auto obs = scene(1, 0.0);
  const Eigen::Matrix3d P = Eigen::Vector3d(0.01, 0.01, 1e-4).asDiagonal();
  for (auto _ : state)
    benchmark::DoNotOptimize(gateObservation(rig.cameras[obs[0].camera], obs[0], kTruth, P));
}
BENCHMARK(BM_GateObservation);

void BM_PredictRegionsFourCameras(benchmark::State& state) {
  const auto rig = geometry::defaultRig();
  const auto map = testing::aisleMap();
  const FloorHeights floors(map);
  const Eigen::Matrix3d P = Eigen::Vector3d(0.01, 0.01, 1e-4).asDiagonal();
  size_t regions = 0;
  for (auto _ : state) {
    const auto nearby = map.withinRadius(kTruth.translation(), 12.0);
    regions = 0;
    for (const auto& camera : rig.cameras)
      regions += predictRegions(camera, nearby, floors, kTruth, P).size();
    benchmark::DoNotOptimize(regions);
  }
  state.counters["regions"] = static_cast<double>(regions);
}
BENCHMARK(BM_PredictRegionsFourCameras)->Unit(benchmark::kMicrosecond);

// One frame set through the whole pipeline on oracle instances (no OCR), while tracking.
void BM_PipelineFrameOracle(benchmark::State& state) {
  const auto rig = geometry::defaultRig();
  const auto map = testing::aisleMap();
  testing::SpotOptions spot;
  spot.max_range_m = 10.0;
  PipelineOptions options;
  options.paper_modules.afm = false;  // the same numbers every iteration would fill the queue oddly
  Pipeline pipeline(rig, map, options);
  FrameInput frame;
  for (const auto& camera : rig.cameras) {
    CameraInput c;
    c.camera = camera.name;
    c.instances = testing::spotExactly(camera, map, kTruth, spot);
    frame.cameras.push_back(c);
  }
  double t = 0.0;
  for (auto _ : state) {
    frame.timestamp = (t += 0.1);
    benchmark::DoNotOptimize(pipeline.process(frame));
  }
}
BENCHMARK(BM_PipelineFrameOracle)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
