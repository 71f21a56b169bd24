#include "sim/dataset_writer.h"

#include <fmt/format.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <future>
#include <mutex>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <random>
#include <thread>

#include "common/error.h"
#include "geometry/rig.h"
#include "io/calibration_yaml.h"
#include "io/labels.h"
#include "io/levels_csv.h"
#include "io/map_geojson.h"
#include "io/odometry_csv.h"
#include "io/sequence.h"
#include "io/tum.h"
#include "sim/annotate.h"
#include "sim/birds_eye.h"
#include "sim/camera_effects.h"
#include "sim/dataset_rig.h"
#include "sim/drive.h"
#include "sim/garage.h"
#include "sim/garage_appearance.h"
#include "sim/ink_through_camera.h"
#include "sim/level_schedule.h"
#include "sim/ramp_level.h"
#include "sim/renderer.h"

namespace parkloc::sim {
namespace fs = std::filesystem;

namespace {

uint64_t mix(uint64_t x) {
  // splitmix64 finaliser: decorrelates nearby seeds.
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

// Writes `image` as a JPEG of `quality` to `path` and returns the file's bytes, so that what
// is measured on the image is what was written.
std::vector<uint8_t> writeJpeg(const std::string& path, const cv::Mat& image, int quality) {
  std::vector<uint8_t> bytes;
  if (!cv::imencode(".jpg", image, bytes, {cv::IMWRITE_JPEG_QUALITY, quality}))
    throw IoError(fmt::format("simulate: cannot encode {}", path));
  std::ofstream f(path, std::ios::binary);
  if (!f.write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size())))
    throw IoError(fmt::format("simulate: cannot write {}", path));
  return bytes;
}

std::string rotationSubset(double rotation_deg) {
  const double a = std::abs(rotation_deg);
  if (a >= 150.0) return "rot180";
  if (a >= 60.0 && a <= 120.0) return "rot90";
  if (a >= 30.0 && a < 60.0) return "rot45";
  return "";
}

struct SequenceResult {
  DatasetStats stats;
};

}  // namespace

// Below this share of its ink left, a faded number is not legible (AnnotateOptions::
// min_ink_kept): wearInk at the faded style's severities leaves 20-60 %, and at under 40 % whole
// strokes of most digits are gone.
constexpr double kMinInkKeptFaded = 0.4;

uint64_t garageSeed(uint64_t scenario_seed, size_t garage) {
  return mix(mix(scenario_seed) ^ (garage + 1));
}
uint64_t driveSeed(uint64_t scenario_seed, size_t garage, size_t drive) {
  return mix(garageSeed(scenario_seed, garage) ^ ((drive + 1) << 32));
}

std::vector<SequencePlan> planSequences(const Scenario& scenario) {
  std::vector<SequencePlan> plans;
  for (size_t gi = 0; gi < scenario.garages.size(); ++gi) {
    const GarageSpec& g = scenario.garages[gi];
    for (size_t di = 0; di < g.drives.size(); ++di) {
      SequencePlan p;
      p.garage = gi;
      p.drive = di;
      // A repeated drive drives on the level of the drive it repeats.
      const size_t own =
          g.drives[di].repeat_of >= 0 ? static_cast<size_t>(g.drives[di].repeat_of) : di;
      p.level = g.drives[di].level.empty() ? g.levels[own % g.levels.size()] : g.drives[di].level;
      p.to_level = g.drives[di].to_level;
      p.split = g.split;
      p.condition = g.drives[di].condition;
      p.name = p.to_level.empty() ? fmt::format("{}_{}_d{}", g.name, p.level, di)
                                  : fmt::format("{}_{}-{}_d{}", g.name, p.level, p.to_level, di);
      plans.push_back(p);
    }
  }
  return plans;
}

namespace {

// splits.json: the sequences just written, by split. When only some splits were written, the
// others keep what an earlier run listed in the same folder (those whose folder is still
// there), so that `--split val` after `--split test` leaves a dataset with both.
nlohmann::json splitsJson(const fs::path& root, const std::vector<SequencePlan>& plans,
                          const std::vector<std::string>& written_splits) {
  nlohmann::json splits = {{"train", nlohmann::json::array()},
                           {"val", nlohmann::json::array()},
                           {"test", nlohmann::json::array()}};
  for (const auto& p : plans) splits[p.split].push_back(p.name);
  if (written_splits.empty()) return splits;
  std::ifstream in(root / "splits.json");
  const nlohmann::json earlier = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (!earlier.is_object()) return splits;  // none, or unreadable: rewritten whole
  for (auto& [split, names] : splits.items()) {
    const bool written =
        std::find(written_splits.begin(), written_splits.end(), split) != written_splits.end();
    if (written || !earlier.contains(split) || !earlier[split].is_array()) continue;
    for (const auto& name : earlier[split])
      if (name.is_string() && fs::is_directory(root / "sequences" / name.get<std::string>()))
        names.push_back(name);
  }
  return splits;
}

}  // namespace

DatasetStats writeDataset(const Scenario& scenario_in, const DatasetOptions& options,
                          const ProgressCallback& progress) {
  const auto wall_start = std::chrono::steady_clock::now();
  if (options.out_dir.empty()) throw InputError("simulate: --out is empty");
  if (options.jobs < 1 || options.jobs > 256)
    throw InputError(fmt::format("simulate: --jobs {} out of range", options.jobs));
  Scenario scenario = scenario_in;
  if (options.seed) scenario.seed = *options.seed;
  std::vector<SequencePlan> plans = planSequences(scenario);
  for (const auto& split : options.splits)
    if (split != "train" && split != "val" && split != "test")
      throw InputError(fmt::format("simulate: unknown split '{}' (train, val or test)", split));
  if (!options.splits.empty())
    plans.erase(std::remove_if(plans.begin(), plans.end(),
                               [&](const SequencePlan& p) {
                                 return std::find(options.splits.begin(), options.splits.end(),
                                                  p.split) == options.splits.end();
                               }),
                plans.end());
  if (options.max_sequences >= 0 && static_cast<size_t>(options.max_sequences) < plans.size())
    plans.resize(options.max_sequences);
  for (const auto& p : plans) {
    const GarageSpec& gs = scenario.garages[p.garage];
    for (const std::string& level : {p.level, p.to_level})
      if (!level.empty() && gs.levels.end() == std::find(gs.levels.begin(), gs.levels.end(), level))
        throw InputError(fmt::format("scenario: drive level '{}' is not a level of garage '{}'",
                                     level, gs.name));
    if (p.to_level == p.level)
      throw InputError(
          fmt::format("scenario: drive {} of garage '{}' goes from level '{}' to itself", p.drive,
                      gs.name, p.level));
  }

  const fs::path root(options.out_dir);
  std::error_code ec;
  fs::create_directories(root / "sequences", ec);
  if (ec)
    throw IoError(
        fmt::format("simulate: cannot create {}: {}", (root / "sequences").string(), ec.message()));

  const geometry::Rig rig = datasetRig(scenario, options);
  // A dataset that renders any drive with a look names every drive's, the clean ones too, so
  // that its evaluation has a subset per look; one without keeps the plain meta.json.
  bool any_look = false;
  for (const auto& p : plans)
    any_look = any_look || scenario.garages[p.garage].drives[p.drive].appearance.any();
  auto rays = std::make_shared<const std::vector<CameraRays>>(buildRigRays(rig));
  if (options.birdseye &&
      !(options.birdseye_metres_per_pixel >= 0.005 && options.birdseye_metres_per_pixel <= 0.1))
    throw InputError(fmt::format("simulate: --birdseye-scale {} out of range (0.005 to 0.1 m)",
                                 options.birdseye_metres_per_pixel));
  std::optional<BirdsEyeStitcher> birdseye;
  if (options.birdseye) {
    BirdsEyeOptions o;
    o.metres_per_pixel = options.birdseye_metres_per_pixel;
    birdseye.emplace(rig, o);
  }

  // Plan every drive first (cheap) so the progress total is known.
  std::mutex garage_mutex;
  std::map<size_t, std::shared_future<std::shared_ptr<const Garage>>> garages;
  std::map<size_t, int> garage_users;
  for (const auto& p : plans) ++garage_users[p.garage];
  auto getGarage = [&](size_t gi) {
    std::shared_future<std::shared_ptr<const Garage>> f;
    bool build = false;
    std::promise<std::shared_ptr<const Garage>> promise;
    {
      std::lock_guard<std::mutex> lock(garage_mutex);
      auto it = garages.find(gi);
      if (it == garages.end()) {
        f = promise.get_future().share();
        garages.emplace(gi, f);
        build = true;
      } else {
        f = it->second;
      }
    }
    if (build) {
      try {
        promise.set_value(std::make_shared<const Garage>(
            generateGarage(scenario.garages[gi], garageSeed(scenario.seed, gi))));
      } catch (...) {
        promise.set_exception(std::current_exception());
      }
    }
    return f.get();
  };
  auto releaseGarage = [&](size_t gi) {
    std::lock_guard<std::mutex> lock(garage_mutex);
    if (--garage_users[gi] == 0) garages.erase(gi);
  };

  // Progress total: the frame budget of each drive, corrected once its plan is known.
  std::vector<int> budget(plans.size());
  std::atomic<long> total{0};
  for (size_t i = 0; i < plans.size(); ++i) {
    const DriveSpec& ds = scenario.garages[plans[i].garage].drives[plans[i].drive];
    budget[i] = static_cast<int>(std::floor(ds.duration_s * scenario.frame_rate)) + 1;
    if (options.max_frames >= 0) budget[i] = std::min(budget[i], options.max_frames);
    total += budget[i];
  }
  std::atomic<size_t> done{0};
  std::mutex progress_mutex;
  std::mutex stats_mutex;
  DatasetStats stats;
  std::atomic<size_t> next{0};
  std::exception_ptr failure;

  auto runSequence = [&](size_t si) {
    const SequencePlan& plan = plans[si];
    const std::shared_ptr<const Garage> generated = getGarage(plan.garage);
    const GarageSpec& gs = scenario.garages[plan.garage];
    const DriveSpec& ds = gs.drives[plan.drive];
    // A repeated drive takes the seed of the drive it repeats: the same route, light and noise.
    const uint64_t seed =
        driveSeed(scenario.seed, plan.garage,
                  ds.repeat_of >= 0 ? static_cast<size_t>(ds.repeat_of) : plan.drive);
    // The drive's look: the garage restyled (its own copy) and the camera's effects.
    const AppearanceOptions& look = ds.appearance;
    const std::shared_ptr<const Garage> garage =
        look.changesGarage() ? std::make_shared<const Garage>(withAppearance(*generated, look))
                             : generated;
    const CameraEffects effects(look, rig, seed);
    const Drive drive = planDrive(*garage, garage->levelIndex(plan.level), ds, seed);
    const LevelSchedule schedule = levelSchedule(ds, plan.level, drive.duration());
    int n = static_cast<int>(std::floor(drive.duration() * scenario.frame_rate + 1e-9)) + 1;
    if (options.max_frames >= 0) n = std::min(n, options.max_frames);
    total += n - budget[si];
    const LightingOptions light = lightingForCondition(plan.condition, seed ^ 0xabcdefULL);
    // One renderer at a time: the start level's, the ramp's, the end level's, each built when
    // the drive reaches its stretch.
    const int start_level = garage->levelIndex(schedule.start_level);
    GarageLevel ramp;
    std::unique_ptr<Renderer> stretch_renderer;
    std::optional<Stretch> rendered_stretch;
    auto rendererFor = [&](Stretch stretch) -> const Renderer& {
      if (rendered_stretch == stretch) return *stretch_renderer;
      stretch_renderer.reset();
      if (stretch == Stretch::kRamp) {
        ramp = rampLevel(*garage, start_level);
        stretch_renderer = std::make_unique<Renderer>(*garage, ramp, rig, rays, light);
      } else {
        stretch_renderer = std::make_unique<Renderer>(
            *garage,
            garage->levelIndex(stretch == Stretch::kStartLevel ? schedule.start_level
                                                               : schedule.end_level),
            rig, rays, light);
      }
      rendered_stretch = stretch;
      return *stretch_renderer;
    };

    const fs::path dir = root / "sequences" / plan.name;
    fs::remove_all(dir);
    for (const auto& cam : rig.cameras) {
      fs::create_directories(dir / "images" / cam.name);
      fs::create_directories(dir / "labels" / cam.name);
    }
    if (birdseye) {
      fs::create_directories(dir / "birdseye" / "images");
      fs::create_directories(dir / "birdseye" / "labels");
    }
    io::saveCalibration(rig, (dir / "calib.yaml").string());
    io::saveMap(garage->map, (dir / "map.geojson").string());

    DatasetStats local;
    local.sequences = 1;
    std::vector<io::StampedPose> poses;
    std::vector<io::StampedLevel> levels;
    std::vector<std::string> levels_driven;
    // Cameras not triggered together: each camera's capture time in frame set k.
    const bool staggered = !ds.camera_delay_s.empty() || ds.camera_jitter_s > 0.0;
    if (staggered && birdseye)
      throw InputError(
          fmt::format("simulate: drive {} has camera delays; a stitched bird's-eye "
                      "image needs the cameras triggered together",
                      plan.name));
    std::mt19937_64 jitter_rng(seed ^ 0x7177e7ULL);
    std::uniform_real_distribution<double> jitter(0.0, ds.camera_jitter_s);
    const auto render_start = std::chrono::steady_clock::now();
    for (int k = 0; k < n; ++k) {
      const double t = k / scenario.frame_rate;
      const DriveState state = drive.at(t);
      // Each camera's capture time and the vehicle's pose then.
      std::vector<double> capture(rig.cameras.size(), t);
      std::vector<geometry::Pose2> camera_pose(rig.cameras.size(), state.pose);
      if (staggered)
        for (size_t c = 0; c < rig.cameras.size(); ++c) {
          const auto delay = ds.camera_delay_s.find(rig.cameras[c].name);
          capture[c] = t + (delay != ds.camera_delay_s.end() ? delay->second : 0.0) +
                       (ds.camera_jitter_s > 0.0 ? jitter(jitter_rng) : 0.0);
          camera_pose[c] = drive.at(capture[c]).pose;
        }
      // The truth at every capture time (the reader's frame set takes its earliest).
      std::vector<std::pair<double, geometry::Pose2>> stamps;
      for (size_t c = 0; c < capture.size(); ++c) stamps.emplace_back(capture[c], camera_pose[c]);
      std::sort(stamps.begin(), stamps.end(),
                [](const auto& a, const auto& b) { return a.first < b.first; });
      for (size_t i = 0; i < stamps.size(); ++i)
        if (i == 0 || stamps[i].first != stamps[i - 1].first)
          poses.push_back({stamps[i].first, stamps[i].second.toRigid3()});
      const Stretch stretch = schedule.stretchAt(t);
      levels.push_back({t, schedule.levelAt(t)});
      if (levels_driven.empty() || levels_driven.back() != levels.back().level)
        levels_driven.push_back(levels.back().level);
      const Renderer& renderer = rendererFor(stretch);
      const int level = garage->levelIndex(levels.back().level);
      const uint64_t frame_seed = mix(seed ^ (static_cast<uint64_t>(k) << 16));
      std::vector<cv::Mat> images;
      if (staggered) {
        for (size_t c = 0; c < rig.cameras.size(); ++c)
          images.push_back(renderer.renderCamera(c, camera_pose[c], frame_seed));
      } else {
        images = renderer.render(state.pose, frame_seed);
      }
      // The camera's processing, its stages kept when the labels' legibility is judged on the
      // image a reader gets (sim/ink_through_camera.h).
      const bool on_image = scenario.legibility_on_image;
      std::vector<CameraStages> stages(images.size());
      for (size_t c = 0; c < images.size(); ++c) {
        if (on_image) stages[c].scene = images[c].clone();
        effects.develop(images[c], c, capture[c]);
        if (on_image) stages[c].developed = images[c].clone();
        effects.compress(images[c], c, frame_seed);
      }
      const std::string frame_stem = io::timestampStem(t);
      std::vector<io::ImageLabels> frame_labels;
      for (size_t c = 0; c < rig.cameras.size(); ++c) {
        const auto& cam = rig.cameras[c];
        const std::string stem = io::timestampStem(capture[c]);
        const std::string image_path = (dir / "images" / cam.name / (stem + ".jpg")).string();
        const std::vector<uint8_t> jpeg = writeJpeg(image_path, images[c], scenario.jpeg_quality);
        if (on_image) stages[c].final = cv::imdecode(jpeg, cv::IMREAD_COLOR);
        io::ImageLabels labels;
        labels.camera = cam.name;
        labels.timestamp = capture[c];
        labels.width = cam.model.width;
        labels.height = cam.model.height;
        AnnotateOptions annotate;
        annotate.blur = imageBlur(light, cam);
        annotate.floor_ink_contrast = [&](int decal, const Eigen::Vector2d& pixel) {
          return renderer.floorInkContrast(c, pixel, decal);
        };
        annotate.channel_noise = light.noise_sigma;
        if (on_image)
          annotate.through_camera = [&](const InkContrast& ink, const geometry::TextPolygon& p) {
            return inkThroughCamera(ink, stages[c], p).contrast;
          };
        if (look.faded > 0.0f) annotate.min_ink_kept = kMinInkKeptFaded;
        // On the ramp no text is in view.
        if (stretch != Stretch::kRamp)
          labels.instances = annotateImage(*garage, level, cam, camera_pose[c], annotate);
        io::saveLabels(labels, (dir / "labels" / cam.name / (stem + ".json")).string());
        if (birdseye) frame_labels.push_back(labels);
        io::saveIcdarLabels(labels, (dir / "labels" / cam.name / (stem + ".txt")).string());
        ++local.images;
        ++local.images_per_condition[plan.condition];
        ++local.images_per_split[plan.split];
        for (const auto& inst : labels.instances) {
          if (!inst.legible) {
            ++local.illegible_instances;
            continue;
          }
          ++local.instances_per_class[static_cast<int>(inst.cls)];
          ++local.instances_per_condition[plan.condition];
          const std::string rot = rotationSubset(inst.rotation_deg);
          if (!rot.empty()) ++local.instances_per_rotation[rot];
          if (inst.occluded_fraction >= 0.5) ++local.occluded_instances;
          if (inst.truncated) ++local.truncated_instances;
        }
      }
      if (birdseye) {
        const std::string path = (dir / "birdseye" / "images" / (frame_stem + ".jpg")).string();
        writeJpeg(path, birdseye->stitch(images), scenario.jpeg_quality);
        io::ImageLabels avm_labels;
        if (stretch != Stretch::kRamp)
          avm_labels = birdsEyeLabels(*garage, level, *birdseye, state.pose, frame_labels);
        avm_labels.camera = "birdseye";
        avm_labels.timestamp = t;
        avm_labels.width = birdseye->size().width;
        avm_labels.height = birdseye->size().height;
        io::saveLabels(avm_labels, (dir / "birdseye" / "labels" / (frame_stem + ".json")).string());
      }
      ++local.frame_sets;
      const size_t d = ++done;
      if (progress) {
        std::lock_guard<std::mutex> lock(progress_mutex);
        progress(d, static_cast<size_t>(std::max<long>(total, static_cast<long>(d))));
      }
    }
    local.render_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - render_start).count();
    const double t_end = (n - 1) / scenario.frame_rate;
    stretch_renderer.reset();
    io::saveTum(poses, (dir / "poses.tum").string());
    io::saveLevels(levels, (dir / "levels.csv").string());
    std::vector<OdometrySample> odo =
        simulateOdometry(drive, scenario.odometry_rate, seed ^ 0x0d0e7ULL);
    while (!odo.empty() && odo.back().timestamp > t_end + 1e-9) odo.pop_back();
    io::saveOdometry(odo, (dir / "odometry.csv").string());

    nlohmann::json meta;
    meta["name"] = plan.name;
    meta["scenario"] = scenario.name;
    meta["garage"] = gs.name;
    meta["level"] = plan.level;
    meta["levels_driven"] = levels_driven;
    if (staggered) {
      meta["camera_delay_s"] = ds.camera_delay_s;
      meta["camera_jitter_s"] = ds.camera_jitter_s;
    }
    if (schedule.changesLevel())
      meta["level_change"] = {{"from", schedule.start_level},
                              {"to", schedule.end_level},
                              {"ramp_start_s", schedule.ramp_start},
                              {"ramp_end_s", schedule.ramp_end}};
    if (any_look) {
      nlohmann::json factors = nlohmann::json::object();
      for (const std::string& name : appearanceFactorNames())
        if (appearanceFactor(look, name) > 0.0f) factors[name] = appearanceFactor(look, name);
      meta["appearance"] = {{"subset", look.subset()}, {"factors", factors}};
    }
    meta["split"] = plan.split;
    meta["condition"] = plan.condition;
    meta["route"] = ds.route;
    meta["frame_rate"] = scenario.frame_rate;
    meta["odometry_rate"] = scenario.odometry_rate;
    meta["frames"] = n;
    meta["duration_s"] = t_end;
    meta["seed"] = scenario.seed;
    meta["garage_seed"] = garageSeed(scenario.seed, plan.garage);
    meta["drive_seed"] = seed;
    meta["numbering_scheme"] = toString(gs.numbering);
    meta["fonts"] = gs.fonts;
    meta["number_height_m"] = gs.number_height;
    meta["levels"] = gs.levels;
    meta["image_format"] = "jpg";
    meta["jpeg_quality"] = scenario.jpeg_quality;
    meta["light"] = {{"ambient", light.ambient},
                     {"lamp_power", light.lamp_power},
                     {"lamps_on_share", light.lamps_on_share},
                     {"exposure", light.exposure},
                     {"noise_sigma", light.noise_sigma},
                     {"defocus_sigma", light.defocus_sigma},
                     {"motion_blur_px", light.motion_blur_px}};
    meta["garage_size_m"] = {garage->size.x(), garage->size.y()};
    meta["ceiling_height_m"] = garage->ceiling_height;
    std::ofstream(dir / "meta.json") << meta.dump(2) << "\n";
    releaseGarage(plan.garage);

    std::lock_guard<std::mutex> lock(stats_mutex);
    stats.sequences += local.sequences;
    stats.frame_sets += local.frame_sets;
    stats.images += local.images;
    for (int c = 0; c < 3; ++c) stats.instances_per_class[c] += local.instances_per_class[c];
    for (const auto& [k, v] : local.images_per_condition) stats.images_per_condition[k] += v;
    for (const auto& [k, v] : local.instances_per_condition) stats.instances_per_condition[k] += v;
    for (const auto& [k, v] : local.instances_per_rotation) stats.instances_per_rotation[k] += v;
    for (const auto& [k, v] : local.images_per_split) stats.images_per_split[k] += v;
    stats.occluded_instances += local.occluded_instances;
    stats.truncated_instances += local.truncated_instances;
    stats.illegible_instances += local.illegible_instances;
    stats.render_seconds += local.render_seconds;
  };

  auto worker = [&] {
    for (;;) {
      const size_t si = next++;
      if (si >= plans.size()) return;
      try {
        runSequence(si);
      } catch (...) {
        std::lock_guard<std::mutex> lock(stats_mutex);
        if (!failure) failure = std::current_exception();
        next = plans.size();
        return;
      }
    }
  };
  const int jobs = std::min<int>(options.jobs, static_cast<int>(std::max<size_t>(1, plans.size())));
  std::vector<std::thread> threads;
  for (int j = 1; j < jobs; ++j) threads.emplace_back(worker);
  worker();
  for (auto& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);

  const nlohmann::json splits = splitsJson(root, plans, options.splits);  // reads the old file
  std::ofstream(root / "splits.json") << splits.dump(2) << "\n";
  stats.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  return stats;
}

}  // namespace parkloc::sim
