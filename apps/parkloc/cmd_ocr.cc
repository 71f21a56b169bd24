// parkloc ocr IMAGE... : spot text in camera images with the PP-OCRv4 engine.
#include <fmt/format.h>

#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "apps/parkloc/command.h"
#include "apps/parkloc/config_args.h"
#include "common/error.h"
#include "geometry/rig.h"
#include "geometry/text_polygon.h"
#include "io/calibration_yaml.h"
#include "io/map_geojson.h"
#include "map/hd_map.h"
#include "map/placed_texts.h"
#include "ocr/ocr_io.h"
#include "ocr/ppocr/pp_ocr_spotter.h"

namespace {

struct OcrArgs {
  std::vector<std::string> images;
  bool json = false;
  std::string draw;
  std::string lexicon;
  std::string map;
  parkloc::app::ConfigArgs config;  // the spotter's options and models, as for eval and run
  std::string camera;
  std::string calib;
  std::vector<double> pose;  // x, y, yaw of the vehicle in the map; empty: none
  std::string level;
  bool birdseye = false;
  double metres_per_pixel = 0.0;  // 0: not given
};

// The size on the floor of a text found in a top-down image of `metres_per_pixel`: its
// glyph height (polygon area over reading length) and its reading length, in metres.
std::pair<double, double> floorSize(const parkloc::ocr::Quad& q, double metres_per_pixel) {
  parkloc::geometry::TextPolygon p;
  for (int k = 0; k < 4; ++k) p[k] = Eigen::Vector2d(q[k].x, q[k].y);
  return {parkloc::geometry::apparentHeightPx(p) * metres_per_pixel,
          parkloc::geometry::readingLengthPx(p) * metres_per_pixel};
}

void run(const OcrArgs& args) {
  using namespace parkloc;
  const ocr::PpOcrOptions options = config::spotterOptions(args.config.load());
  const geometry::Rig rig =
      args.calib.empty() ? geometry::defaultRig() : io::loadCalibration(args.calib);
  const geometry::RigCamera* camera = nullptr;
  if (!args.camera.empty()) {
    camera = rig.find(args.camera);
    if (camera == nullptr)
      throw InputError("--camera: no camera named '" + args.camera + "' in the rig");
  }
  ocr::SpotRequest request;
  if (!args.lexicon.empty()) request.lexicon = ocr::loadLexiconFile(args.lexicon);
  if (!args.map.empty()) {
    const map::HdMap map = io::loadMap(args.map);
    request.lexicon = map::distinctTexts(map);
    request.floor_lexicon = map::distinctTexts(map, /*floor_only=*/true);
    if (!args.pose.empty()) {
      // A predicted pose: floor boxes read against the texts the map places near them.
      const geometry::Pose2 map_from_vehicle(args.pose[0], args.pose[1], args.pose[2]);
      request.placed_floor_texts =
          map::placeFloorTexts(map, map_from_vehicle, map::kFloorViewReachM, args.level);
    }
  }
  if (!args.pose.empty() && (args.map.empty() || args.camera.empty()))
    throw InputError("--pose needs --map and --camera");
  if (args.birdseye && (camera != nullptr || !args.pose.empty()))
    throw InputError(
        "--birdseye takes no --camera or --pose: the image is the floor seen from above");
  if (args.metres_per_pixel > 0.0 && !args.birdseye)
    throw InputError("--metres-per-pixel needs --birdseye");
  request.camera = camera;
  // Every image decoded before the models load: a bad file is reported at once.
  std::vector<cv::Mat> images;
  for (const std::string& path : args.images) {
    images.push_back(ocr::readImage(path));
    // An image of another size is another camera's, or resized: its floor view and ground
    // fit would read garbage, so it is refused, not read as a raw image.
    if (camera != nullptr &&
        (images.back().cols != camera->model.width || images.back().rows != camera->model.height))
      throw InputError(fmt::format("{}: image {}x{} differs from camera '{}' of the calibration "
                                   "({}x{})",
                                   path, images.back().cols, images.back().rows, camera->name,
                                   camera->model.width, camera->model.height));
  }
  ocr::PpOcrSpotter spotter(options);

  nlohmann::json all = nlohmann::json::array();
  for (size_t i = 0; i < args.images.size(); ++i) {
    const cv::Mat& image = images[i];
    std::optional<double> scale;
    if (args.metres_per_pixel > 0.0) scale = args.metres_per_pixel;
    const auto instances =
        args.birdseye ? spotter.spotBirdsEye(image, request, scale) : spotter.spot(image, request);
    if (args.json) {
      nlohmann::json found = ocr::toJson(instances);
      if (scale)
        for (size_t k = 0; k < instances.size(); ++k) {
          const auto [height, length] = floorSize(instances[k].polygon, *scale);
          found[k]["height_m"] = height;
          found[k]["length_m"] = length;
        }
      all.push_back({{"image", args.images[i]}, {"instances", found}});
    } else {
      std::cout << args.images[i] << ": " << instances.size() << " text instances\n";
      for (const auto& inst : instances) {
        std::cout << "  " << ocr::describe(inst);
        if (scale) {
          const auto [height, length] = floorSize(inst.polygon, *scale);
          std::cout << fmt::format("  {:.2f} m tall, {:.2f} m long", height, length);
        }
        std::cout << "\n";
      }
    }
    if (!args.draw.empty()) {
      std::string out = args.draw;
      if (args.images.size() > 1) {
        const auto dot = out.rfind('.');
        out = out.substr(0, dot) + "_" + std::to_string(i) + out.substr(dot);
      }
      if (!cv::imwrite(out, ocr::drawInstances(image, instances)))
        throw IoError("cannot write " + out);
    }
  }
  if (args.json) std::cout << all.dump(2) << "\n";
}

const bool registered = parkloc::app::registerCommand([](CLI::App& parent) {
  auto args = std::make_shared<OcrArgs>();
  auto* cmd = parent.add_subcommand("ocr", "Spot text (polygon, reading, class) in camera images");
  cmd->add_option("images", args->images, "Camera images (8-bit colour)")->required();
  cmd->add_flag("--json", args->json, "Print JSON instead of text");
  cmd->add_option("--draw", args->draw, "Write the image with instances drawn (PNG)");
  cmd->add_option("--lexicon", args->lexicon, "Candidate texts, one a line");
  cmd->add_option("--map", args->map, "Candidate texts from an HD map (GeoJSON)");
  args->config.addTo(cmd);
  cmd->add_option("--camera", args->camera,
                  "Rig camera that took the images (front, rear, left, right): enables the "
                  "floor view and ground-plane corner fit");
  cmd->add_option("--calib", args->calib, "Rig calibration YAML (default: the built-in rig)");
  cmd->add_option("--pose", args->pose,
                  "Predicted vehicle pose X Y YAW (metres, radians) in --map: each floor box is "
                  "read against the texts placed near it, the way round they read")
      ->expected(3);
  cmd->add_option("--level", args->level, "With --pose: the garage level (default: every level)");
  cmd->add_flag("--birdseye", args->birdseye,
                "The images are stitched top-down views of the floor (AVM): floor text is read "
                "in any orientation with the floor view's detector and reading cascade");
  cmd->add_option("--metres-per-pixel", args->metres_per_pixel,
                  "With --birdseye: the image's scale; the image is resampled to the floor "
                  "view's and each text's size on the floor is printed")
      ->check(CLI::Range(0.001, 0.5));
  cmd->callback([args] { run(*args); });
});

}  // namespace
