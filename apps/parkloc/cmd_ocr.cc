// parkloc ocr IMAGE... : spot text in camera images with the PP-OCRv4 engine.
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "apps/parkloc/command.h"
#include "apps/parkloc/config_args.h"
#include "common/error.h"
#include "geometry/rig.h"
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
};

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
  request.camera = camera;
  ocr::PpOcrSpotter spotter(options);

  nlohmann::json all = nlohmann::json::array();
  for (size_t i = 0; i < args.images.size(); ++i) {
    const cv::Mat image = ocr::readImage(args.images[i]);
    const auto instances = spotter.spot(image, request);
    if (args.json) {
      all.push_back({{"image", args.images[i]}, {"instances", ocr::toJson(instances)}});
    } else {
      std::cout << args.images[i] << ": " << instances.size() << " text instances\n";
      for (const auto& inst : instances) std::cout << "  " << ocr::describe(inst) << "\n";
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
  cmd->callback([args] { run(*args); });
});

}  // namespace
