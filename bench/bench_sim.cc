// Render speed of the simulator: a four-camera 1280x800 frame set (target <= 150 ms on
// 2 cores), garage generation and the labels of a frame set.
#include <benchmark/benchmark.h>

#include <memory>

#include "geometry/rig.h"
#include "sim/annotate.h"
#include "sim/drive.h"
#include "sim/garage.h"
#include "sim/renderer.h"
#include "sim/scenario.h"

namespace {

using namespace parkloc;

struct Fixture {
  sim::Garage garage;
  geometry::Rig rig = geometry::defaultRig();
  std::shared_ptr<const std::vector<sim::CameraRays>> rays;
  sim::Drive drive{{}};
  Fixture()
      : garage(sim::generateGarage(sim::defaultScenario().garages[0], 1)),
        rays(std::make_shared<const std::vector<sim::CameraRays>>(sim::buildRigRays(rig))),
        drive(sim::planDrive(garage, 0, sim::DriveSpec{"tour", "bright", "", 20.0}, 3)) {}
  static Fixture& get() {
    static Fixture f;
    return f;
  }
};

void BM_RenderFrameSet(benchmark::State& state) {
  Fixture& f = Fixture::get();
  const sim::Renderer renderer(f.garage, 0, f.rig, f.rays, sim::lightingForCondition("bright", 5));
  int k = 0;
  for (auto _ : state) {
    const auto images = renderer.render(f.drive.at(0.5 * (k % 30)).pose, k);
    benchmark::DoNotOptimize(images.front().data);
    ++k;
  }
}
BENCHMARK(BM_RenderFrameSet)->Unit(benchmark::kMillisecond)->UseRealTime()->MeasureProcessCPUTime();

void BM_AnnotateFrameSet(benchmark::State& state) {
  Fixture& f = Fixture::get();
  int k = 0;
  for (auto _ : state) {
    size_t n = 0;
    for (const auto& cam : f.rig.cameras)
      n += sim::annotateImage(f.garage, 0, cam, f.drive.at(0.5 * (k % 30)).pose).size();
    benchmark::DoNotOptimize(n);
    ++k;
  }
}
BENCHMARK(BM_AnnotateFrameSet)->Unit(benchmark::kMillisecond);

void BM_GenerateGarage(benchmark::State& state) {
  const sim::GarageSpec spec = sim::defaultScenario().garages[0];
  for (auto _ : state) benchmark::DoNotOptimize(sim::generateGarage(spec, 1).size);
}
BENCHMARK(BM_GenerateGarage)->Unit(benchmark::kMillisecond)->Iterations(2);

}  // namespace

BENCHMARK_MAIN();
