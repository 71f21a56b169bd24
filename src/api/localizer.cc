// The embedding facade (include/parkloc/parkloc.h) over the localize pipeline: files read at
// the edge, the shipped spotter built from the configuration, images grouped into frame sets
// (api/frame_assembly.h), and the pipeline's result reduced to std types.
#include "parkloc/parkloc.h"

#include <cstdlib>
#include <exception>

#include "api/frame_assembly.h"
#include "api/model_location.h"
#include "common/error.h"
#include "config/config.h"
#include "io/calibration_yaml.h"
#include "io/map_geojson.h"
#include "localize/pipeline.h"
#include "config/spotters.h"

namespace parkloc {
namespace {

TrackingStatus publicStatus(localize::TrackingStatus status) {
  switch (status) {
    case localize::TrackingStatus::kNotInitialised:
      return TrackingStatus::kNoFix;
    case localize::TrackingStatus::kOk:
      return TrackingStatus::kTracking;
    case localize::TrackingStatus::kDeadReckoning:
      return TrackingStatus::kDeadReckoning;
    case localize::TrackingStatus::kLost:
      return TrackingStatus::kLost;
  }
  return TrackingStatus::kLost;
}

// The model folder in LocalizerSettings' order; an empty models.dir leaves the environment
// and the build tree to config::modelDirectory.
void chooseModelDir(const LocalizerSettings& settings, config::ModelOptions& models) {
  if (!settings.models_dir.empty()) {
    models.dir = settings.models_dir;
    return;
  }
  const char* env = std::getenv("PARKLOC_MODEL_DIR");
  if (models.dir.empty() && (env == nullptr || *env == '\0'))
    models.dir = api::installedModelDir();
}

std::vector<std::string> cameraNames(const geometry::Rig& rig) {
  std::vector<std::string> names;
  for (const auto& camera : rig.cameras) names.push_back(camera.name);
  return names;
}

}  // namespace

std::string toString(TrackingStatus status) {
  switch (status) {
    case TrackingStatus::kNoFix:
      return "no_fix";
    case TrackingStatus::kTracking:
      return "tracking";
    case TrackingStatus::kDeadReckoning:
      return "dead_reckoning";
    case TrackingStatus::kLost:
      return "lost";
  }
  return "unknown";
}

struct Localizer::Impl {
  // Declared before the pipeline, which holds pointers to them: destroyed after it.
  std::unique_ptr<ocr::TextSpotter> spotter;
  config::WorkerSpotterSet workers;
  localize::Pipeline pipeline;
  api::FrameAssembly assembly;
  std::string models_dir;

  Impl(std::unique_ptr<ocr::TextSpotter> s, config::WorkerSpotterSet w, geometry::Rig rig,
       map::HdMap map, const localize::PipelineOptions& options, double tolerance_s,
       std::string models)
      : spotter(std::move(s)),
        workers(std::move(w)),
        pipeline(rig, std::move(map), options, spotter.get(), workers.pointers()),
        assembly(cameraNames(rig), tolerance_s),
        models_dir(std::move(models)) {}

  PoseEstimate process(const localize::FrameInput& frame) {
    PoseEstimate out;
    out.warnings = assembly.takeWarnings();
    for (const auto& camera : frame.cameras) out.cameras.push_back(camera.camera);
    localize::FrameResult result;
    try {
      result = pipeline.process(frame);
    } catch (const std::exception& e) {
      // An image the spotter cannot take (e.g. not 8-bit BGR) costs this frame set only.
      out.warnings.push_back(std::string("frame set skipped: ") + e.what());
      return out;
    }
    out.timestamp = result.timestamp;
    out.status = publicStatus(result.status);
    out.has_pose = result.has_pose;
    out.x = result.pose.x;
    out.y = result.pose.y;
    out.yaw = result.pose.yaw;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) out.covariance[static_cast<size_t>(3 * r + c)] =
          result.covariance(r, c);
    out.level = result.level;
    out.level_probability = result.level_probability;
    out.level_decided = result.level_decided;
    out.tentative = result.tentative;
    out.warnings.insert(out.warnings.end(), result.warnings.begin(), result.warnings.end());
    return out;
  }
};

LocalizerOrError Localizer::create(const LocalizerSettings& settings) {
  LocalizerOrError out;
  try {
    if (settings.calibration_file.empty()) throw InputError("no calibration file given");
    if (settings.map_file.empty()) throw InputError("no map file given");
    if (!(settings.frame_set_tolerance_s >= 0.0))
      throw InputError("frame_set_tolerance_s must be a non-negative number of seconds");
    config::Config config =
        settings.config_file.empty() ? config::Config{} : config::loadConfig(settings.config_file);
    if (!settings.level.empty()) config.pipeline.level = settings.level;
    chooseModelDir(settings, config.models);
    geometry::Rig rig = io::loadCalibration(settings.calibration_file);
    map::HdMap map = io::loadMap(settings.map_file);
    auto spotter = config::makeSpotter(config);
    auto workers = config::makeWorkerSpotters(config);
    out.localizer.emplace(Localizer(std::make_unique<Impl>(
        std::move(spotter), std::move(workers), std::move(rig), std::move(map), config.pipeline,
        settings.frame_set_tolerance_s, config::modelDirectory(config.models))));
  } catch (const std::exception& e) {
    out.localizer.reset();
    out.error = e.what();
  }
  return out;
}

Localizer::Localizer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Localizer::~Localizer() = default;
Localizer::Localizer(Localizer&&) noexcept = default;
Localizer& Localizer::operator=(Localizer&&) noexcept = default;

std::vector<std::string> Localizer::cameras() const { return cameraNames(impl_->pipeline.rig()); }

const std::string& Localizer::modelsDir() const { return impl_->models_dir; }

void Localizer::addOdometry(double timestamp, double speed, double yaw_rate) {
  impl_->assembly.addOdometry({timestamp, speed, yaw_rate});
}

std::vector<PoseEstimate> Localizer::addImage(const std::string& camera, double timestamp,
                                              const cv::Mat& image) {
  std::vector<PoseEstimate> out;
  for (const auto& frame : impl_->assembly.addImage(camera, timestamp, image))
    out.push_back(impl_->process(frame));
  return out;
}

std::optional<PoseEstimate> Localizer::flush() {
  const auto frame = impl_->assembly.flush();
  if (!frame) return std::nullopt;
  return impl_->process(*frame);
}

void Localizer::reset() {
  impl_->assembly.reset();
  impl_->pipeline.reset();
}

}  // namespace parkloc
