// End-to-end through the real PP-OCRv4 models: few, small images (these also run under ASan).
#include "ocr/ppocr/pp_ocr_spotter.h"

#include <gtest/gtest.h>

#include <memory>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "common/error.h"
#include "geometry/rig.h"
#include "ocr/ppocr/detection.h"
#include "ocr/ppocr/pp_ocr_networks.h"
#include "synthetic_text.h"

namespace parkloc::ocr {
namespace {

class PpOcrSpotterTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    PpOcrOptions options;
    options.models = PpOcrModelPaths::inDirectory(PARKLOC_MODEL_DIR);
    spotter_ = std::make_unique<PpOcrSpotter>(options);
  }
  static void TearDownTestSuite() { spotter_.reset(); }
  static std::unique_ptr<PpOcrSpotter> spotter_;
};
std::unique_ptr<PpOcrSpotter> PpOcrSpotterTest::spotter_;

double maxCornerError(const Quad& a, const Quad& b) {
  double worst = 0;
  for (int k = 0; k < 4; ++k) worst = std::max(worst, cv::norm(a[k] - b[k]));
  return worst;
}

// A request for an image of the default rig's left camera, which sees the floor-text scenes
// below, with `lexicon` as its lexicon and floor lexicon.
SpotRequest leftFloorRequest(const std::vector<std::string>& lexicon) {
  static const geometry::Rig rig = geometry::defaultRig();
  SpotRequest request;
  request.lexicon = request.floor_lexicon = lexicon;
  request.camera = rig.find("left");
  if (request.camera == nullptr) throw std::logic_error("the default rig has no left camera");
  return request;
}

TEST_F(PpOcrSpotterTest, ReadsARenderedLineUprightAndUpsideDown) {
  const int margin = 24, ink = 40;
  const cv::Mat upright = testing::renderTextLine("B2-117", ink, margin);
  cv::Mat turned;
  cv::rotate(upright, turned, cv::ROTATE_180);
  const float W = upright.cols, H = upright.rows;
  // The ink box in each image, reading order.
  const Quad ink_box = {cv::Point2f(margin - 0.5f, margin - 0.5f),
                        {W - margin - 0.5f, margin - 0.5f},
                        {W - margin - 0.5f, H - margin - 0.5f},
                        {margin - 0.5f, H - margin - 0.5f}};
  Quad turned_box;
  for (int k = 0; k < 4; ++k) turned_box[k] = cv::Point2f(W - 1, H - 1) - ink_box[k];

  for (const auto& [image, truth] : {std::pair{upright, ink_box}, std::pair{turned, turned_box}}) {
    const auto found = spotter_->spot(image, {});
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].text, "B2-117");
    EXPECT_FALSE(found[0].lexicon_match);
    EXPECT_GT(found[0].recognition_score, 0.8f);
    // Corners re-fitted to the ink.
    EXPECT_LT(maxCornerError(found[0].polygon, truth), 2.0);
  }
}

// Decoding both directions of every crop (no direction classifier) keeps the upright crop
// upright while its turned copy is made.
TEST(PpOcrSpotterDirections, DecodingBothWaysReadsUprightAndUpsideDownLines) {
  PpOcrOptions options;
  options.models = PpOcrModelPaths::inDirectory(PARKLOC_MODEL_DIR);
  options.reading.direction = DirectionMode::kDecodeBoth;
  PpOcrSpotter spotter(options);
  const cv::Mat upright = testing::renderTextLine("B2-117", 40, 24);
  cv::Mat turned;
  cv::rotate(upright, turned, cv::ROTATE_180);
  for (const cv::Mat& image : {upright, turned}) {
    const auto found = spotter.spot(image, {});
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].text, "B2-117");
  }
}

TEST_F(PpOcrSpotterTest, ReadsFloorTextThroughTheFisheyeAndMatchesTheLexicon) {
  const auto rig = geometry::defaultRig();
  const auto* left = rig.find("left");
  ASSERT_NE(left, nullptr);
  // A 1.2 x 0.45 m number on the floor 1.6 m left of the car, reading towards the rear:
  // upside down in the left camera.
  const auto scene = testing::renderFloorText(*left, "B2-117", {2.0, 2.6}, M_PI, 1.2, 0.45);
  SpotRequest request;
  request.lexicon = {"B2-112", "B2-117", "B1-117", "A023"};
  request.camera = left;  // corners fitted on the ground plane
  const auto found = spotter_->spot(scene.image, request);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].text, "B2-117");
  EXPECT_TRUE(found[0].lexicon_match);
  EXPECT_GT(found[0].recognition_score, 0.9f);
  EXPECT_LT(maxCornerError(found[0].polygon, scene.truth), 2.0);

  // Map-guided: a predicted region 8 px off reads the same text inside it only.
  RegionOfInterest region;
  for (int k = 0; k < 4; ++k) region.polygon[k] = scene.truth[k] + cv::Point2f(8, -5);
  region.expected_texts = {"B2-117", "B2-118"};
  SpotRequest guided;
  guided.regions = {region};
  guided.camera = left;
  const auto in_region = spotter_->spot(scene.image, guided);
  ASSERT_EQ(in_region.size(), 1u);
  EXPECT_EQ(in_region[0].text, "B2-117");
  EXPECT_TRUE(in_region[0].lexicon_match);
  EXPECT_LT(maxCornerError(in_region[0].polygon, scene.truth), 3.0);
}

TEST_F(PpOcrSpotterTest, ReadsATrackedTextAtItsPredictionWithoutDetection) {
  const auto rig = geometry::defaultRig();
  const auto* left = rig.find("left");
  ASSERT_NE(left, nullptr);
  const auto scene = testing::renderFloorText(*left, "B2-117", {2.0, 2.6}, M_PI, 1.2, 0.45);
  RegionOfInterest region;
  for (int k = 0; k < 4; ++k) {
    region.predicted[k] = scene.truth[k] + cv::Point2f(4, -3);  // the map's prediction
    region.polygon[k] = region.predicted[k];
  }
  region.expected_texts = {"B2-117"};
  SpotRequest request;
  request.regions = {region};
  request.camera = left;
  const auto found = spotter_->spot(scene.image, request);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].text, "B2-117");
  EXPECT_TRUE(found[0].lexicon_match);
  EXPECT_TRUE(found[0].read);
  EXPECT_LT(maxCornerError(found[0].polygon, scene.truth), 3.0);

  // Another text expected there: the reading does not vouch for it, nothing is reported.
  request.regions[0].expected_texts = {"B2-181"};
  EXPECT_TRUE(spotter_->spot(scene.image, request).empty());

  // Not to be read: only the ink is fitted, the expected text and class come back unread.
  request.regions[0].expected_texts = {"B2-117"};
  request.regions[0].read = false;
  request.regions[0].expected_class = map::TextClass::kParkingNumber;
  const auto fitted = spotter_->spot(scene.image, request);
  ASSERT_EQ(fitted.size(), 1u);
  EXPECT_FALSE(fitted[0].read);
  EXPECT_EQ(fitted[0].text, "B2-117");
  EXPECT_EQ(fitted[0].cls, map::TextClass::kParkingNumber);
  EXPECT_LT(maxCornerError(fitted[0].polygon, scene.truth), 2.0);
}

TEST_F(PpOcrSpotterTest, RejectsEmptyAndWronglyTypedImages) {
  EXPECT_THROW(spotter_->spot(cv::Mat(), {}), InputError);
  EXPECT_THROW(spotter_->spot(cv::Mat(32, 32, CV_8UC1, cv::Scalar(0)), {}), InputError);
  EXPECT_THROW(spotter_->spot(cv::Mat(32, 32, CV_32FC3, cv::Scalar::all(0)), {}), InputError);
}

// An image whose size is not its camera's calibration is refused, naming the camera, for the
// full frame and for regions alike: never read as a raw image of unknown geometry.
TEST_F(PpOcrSpotterTest, AnImageOfAnotherSizeThanItsCalibrationIsAnInputError) {
  SpotRequest request = leftFloorRequest({"A023"});
  const cv::Mat resized(400, 640, CV_8UC3, cv::Scalar::all(90));
  try {
    spotter_->spot(resized, request);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "camera 'left': image 640x400 differs from its calibration's 1280x800");
  }
  request.regions.push_back({});
  request.regions[0].polygon = {cv::Point2f(10, 10), {60, 10}, {60, 30}, {10, 30}};
  EXPECT_THROW(spotter_->spot(resized, request), InputError);
  // Without a camera the image is any image.
  EXPECT_NO_THROW(spotter_->spot(resized, SpotRequest{}));
}

// Loading `models` throws an InputError that names `path`.
void expectInputErrorNaming(const PpOcrModelPaths& models, const std::string& path) {
  PpOcrOptions options;
  options.models = models;
  try {
    PpOcrSpotter spotter(options);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

TEST(PpOcrSpotterModels, MissingModelFileIsAnInputErrorNamingThePath) {
  expectInputErrorNaming(PpOcrModelPaths::inDirectory("/nonexistent/models"),
                         "/nonexistent/models/ch_PP-OCRv4_det_infer.onnx");
}

TEST(PpOcrSpotterModels, MissingFloorDetectorIsAnInputErrorNamingThePath) {
  auto models = PpOcrModelPaths::inDirectory(PARKLOC_MODEL_DIR);
  models.floor_detection = "/nonexistent/parkloc_floor_det.onnx";
  expectInputErrorNaming(models, "/nonexistent/parkloc_floor_det.onnx");
}

// "B2-117" painted on the floor 2.6 m beside the left camera, upside down in its image, spotted
// with `models` (PaddleOCR's with one model replaced) and the scene's true corners.
// Text found in the floor view decodes against the floor's texts only: a pillar's text
// stands upright and never shows there as text, so a floor number is not forced onto it.
TEST_F(PpOcrSpotterTest, FloorTextDecodesAgainstTheFloorLexiconWhenGiven) {
  SpotRequest request;
  request.lexicon = {"B2-117", "A023"};
  request.floor_lexicon = {"A023"};  // here B2-117 would be a pillar's text
  const auto rig = geometry::defaultRig();
  request.camera = rig.find("left");
  ASSERT_NE(request.camera, nullptr);
  // The same number as above, upside down beside the car.
  const cv::Mat image =
      testing::renderFloorText(*request.camera, "B2-117", {2.0, 2.6}, M_PI, 1.2, 0.45).image;
  auto found = spotter_->spot(image, request);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_FALSE(found[0].lexicon_match);
  EXPECT_NE(found[0].text, "A023");

  request.floor_lexicon = {"B2-117", "A023"};
  found = spotter_->spot(image, request);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_TRUE(found[0].lexicon_match);
  EXPECT_EQ(found[0].text, "B2-117");
}

// Under a predicted pose a floor box decodes against the texts placed near it only: with
// its own text placed a bay away and another placed where it is painted, the number matches
// nothing (nor is forced onto the other); placed where it is painted, it matches.
TEST_F(PpOcrSpotterTest, FloorTextDecodesAgainstTheTextsPlacedNearItUnderAPredictedPose) {
  SpotRequest request = leftFloorRequest({"B2-117", "A023"});
  const auto scene =
      testing::renderFloorText(*request.camera, "B2-117", {2.0, 2.6}, M_PI, 1.2, 0.45);
  const cv::Mat& image = scene.image;
  const Eigen::Vector2d reading(-1.0, 0.0);  // the number's heading of pi
  request.placed_floor_texts = {{"B2-117", {2.0, 5.1}, reading}, {"A023", {2.0, 2.6}, reading}};
  auto found = spotter_->spot(image, request);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_FALSE(found[0].lexicon_match);
  EXPECT_NE(found[0].text, "A023");

  request.placed_floor_texts = {{"A023", {2.0, 5.1}, reading}, {"B2-117", {2.1, 2.5}, reading}};
  found = spotter_->spot(image, request);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_TRUE(found[0].lexicon_match);
  EXPECT_EQ(found[0].text, "B2-117");
  // Its polygon reads the way the number does (turned, its corners would be 250 px off).
  EXPECT_LT(maxCornerError(found[0].polygon, scene.truth), 10.0);
}

// The texts placed near a floor box say which way round it reads, and it is read that way
// only: placed as reading the other way, the same number is read upside down and matches
// nothing.
TEST_F(PpOcrSpotterTest, FloorTextIsReadOnlyTheWayTheTextsPlacedNearItRead) {
  SpotRequest request = leftFloorRequest({"B2-117"});
  const cv::Mat image =
      testing::renderFloorText(*request.camera, "B2-117", {2.0, 2.6}, M_PI, 1.2, 0.45).image;
  request.placed_floor_texts = {{"B2-117", {2.0, 2.6}, {1.0, 0.0}}};
  auto found = spotter_->spot(image, request);
  for (const TextInstance& inst : found) EXPECT_FALSE(inst.lexicon_match);
  request.placed_floor_texts = {{"B2-117", {2.0, 2.6}, {-1.0, 0.0}}};
  found = spotter_->spot(image, request);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_TRUE(found[0].lexicon_match);
}

// A floor box read as a text placed near it is held to that text's size on the floor: kept at
// the map's true size, tightened about its centre when the map's text is thinner than the box,
// and refused as that text when the map's text is far longer than the box.
TEST_F(PpOcrSpotterTest, AFloorBoxReadAsAPlacedTextIsHeldToItsSize) {
  SpotRequest request = leftFloorRequest({"B2-117"});
  const auto scene =
      testing::renderFloorText(*request.camera, "B2-117", {2.0, 2.6}, M_PI, 1.2, 0.45);
  const Eigen::Vector2d reading(-1.0, 0.0);
  auto placedOfSize = [&](double width, double height) {
    return std::vector<map::PlacedText>{
        {"B2-117", {2.0, 2.6}, reading, map::TextClass::kParkingNumber, width, height}};
  };
  request.placed_floor_texts = placedOfSize(1.2, 0.45);
  auto found = spotter_->spot(scene.image, request);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_TRUE(found[0].lexicon_match);
  EXPECT_FALSE(found[0].sized_by_map);
  EXPECT_LT(maxCornerError(found[0].polygon, scene.truth), 10.0);

  request.placed_floor_texts = placedOfSize(1.2, 0.2);
  found = spotter_->spot(scene.image, request);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_TRUE(found[0].lexicon_match);
  EXPECT_TRUE(found[0].sized_by_map);
  EXPECT_LT(quadHeight(found[0].polygon), 0.7 * quadHeight(scene.truth));
  EXPECT_LT(cv::norm(quadCentre(found[0].polygon) - quadCentre(scene.truth)), 5.0);

  request.placed_floor_texts = placedOfSize(3.0, 0.45);
  found = spotter_->spot(scene.image, request);
  for (const TextInstance& inst : found) {
    EXPECT_FALSE(inst.lexicon_match);
    EXPECT_NE(inst.text, "B2-117");
  }

  PpOcrOptions without;
  without.models = PpOcrModelPaths::inDirectory(PARKLOC_MODEL_DIR);
  without.map_prior.placed_size.reset();
  found = PpOcrSpotter(without).spot(scene.image, request);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_TRUE(found[0].lexicon_match);  // the same box, unchecked
}

// A floor box whose centre lies on a text placed there decodes under the lexicon options for
// such boxes; one beside the placed text, or with no margin to lie in, under the placed ones.
TEST_F(PpOcrSpotterTest, AFloorBoxOnAPlacedTextDecodesUnderItsOwnLexiconOptions) {
  SpotRequest request = leftFloorRequest({"B2-117"});
  const auto scene =
      testing::renderFloorText(*request.camera, "B2-117", {2.0, 2.6}, M_PI, 1.2, 0.45);
  const Eigen::Vector2d reading(-1.0, 0.0);
  auto placedAt = [&](const Eigen::Vector2d& xy) {
    return std::vector<map::PlacedText>{
        {"B2-117", xy, reading, map::TextClass::kParkingNumber, 1.2, 0.45}};
  };
  PpOcrOptions options;
  options.models = PpOcrModelPaths::inDirectory(PARKLOC_MODEL_DIR);
  options.map_prior.on_placed_text_lexicon.min_posterior = 2.0;  // no reading could pass
  PpOcrSpotter spotter(options);

  request.placed_floor_texts = placedAt({2.0, 2.6});  // under the box
  for (const TextInstance& inst : spotter.spot(scene.image, request))
    EXPECT_FALSE(inst.lexicon_match);
  // 0.5 m across its reading direction: near the box (placement radius 1 m), not under it.
  request.placed_floor_texts = placedAt({2.0, 3.1});
  auto found = spotter.spot(scene.image, request);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_TRUE(found[0].lexicon_match);
  EXPECT_EQ(found[0].text, "B2-117");

  options.map_prior.on_placed_text_margin_m = -1.0;  // no box lies on a text
  request.placed_floor_texts = placedAt({2.0, 2.6});
  found = PpOcrSpotter(options).spot(scene.image, request);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_TRUE(found[0].lexicon_match);
}

// A box on a placed text whose confident free reading is one end of that text is that text,
// partly seen: the end of B2-117, where the map places B2-117.
TEST_F(PpOcrSpotterTest, AFreeReadingOfOneEndOfThePlacedTextUnderTheBoxIsThatText) {
  SpotRequest request = leftFloorRequest({"B2-117"});
  const auto scene = testing::renderFloorText(*request.camera, "-117", {2.0, 2.6}, M_PI, 0.8, 0.45);
  request.placed_floor_texts = {
      {"B2-117", {2.0, 2.6}, {-1.0, 0.0}, map::TextClass::kParkingNumber, 1.2, 0.45}};
  auto found = spotter_->spot(scene.image, request);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].raw_text, "-117");
  EXPECT_EQ(found[0].text, "B2-117");
  EXPECT_TRUE(found[0].lexicon_match);
  EXPECT_TRUE(found[0].partial);

  PpOcrOptions options;
  options.models = PpOcrModelPaths::inDirectory(PARKLOC_MODEL_DIR);
  options.map_prior.on_placed_text_margin_m = -1.0;  // no box lies on a text
  found = PpOcrSpotter(options).spot(scene.image, request);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].text, "-117");
  EXPECT_FALSE(found[0].lexicon_match);
}

// Under a predicted pose the map's classes weigh in: the same floor number is a parking
// number where the map paints one, and other floor text where the map paints its "STOP".
TEST(PpOcrSpotterModels, AFloorBoxTakesTheClassOfTheTextsPlacedNearIt) {
  PpOcrOptions options;
  options.models = PpOcrModelPaths::inDirectory(PARKLOC_MODEL_DIR);
  options.models.classifier = std::string(PARKLOC_SOURCE_DIR) + "/models/text_classifier.yml";
  PpOcrSpotter spotter(options);
  const auto rig = geometry::defaultRig();
  SpotRequest request;
  request.camera = rig.find("left");
  ASSERT_NE(request.camera, nullptr);
  request.lexicon = request.floor_lexicon = {"B2-117", "STOP"};
  const cv::Mat image =
      testing::renderFloorText(*request.camera, "B2-117", {2.0, 2.6}, M_PI, 1.2, 0.45).image;
  const Eigen::Vector2d reading(-1.0, 0.0);
  request.placed_floor_texts = {{"B2-117", {2.0, 2.6}, reading, map::TextClass::kParkingNumber}};
  auto found = spotter.spot(image, request);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].cls, map::TextClass::kParkingNumber);
  request.placed_floor_texts = {{"STOP", {2.0, 2.6}, reading, map::TextClass::kOther}};
  found = spotter.spot(image, request);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].cls, map::TextClass::kOther);
}

// A number cut by the image border shows only its end: read against the texts placed near it,
// the part matches and stands for its whole text, marked partial, its polygon on the part.
TEST_F(PpOcrSpotterTest, ACutFloorNumberMatchesThePlacedTextByThePartThatShows) {
  SpotRequest request = leftFloorRequest({"B2-117", "A023"});
  // A camera on no car: reading away from it, the number's first character lies below the
  // image's bottom edge.
  geometry::RigCamera bare = *request.camera;
  bare.body.reset();
  request.camera = &bare;
  const Eigen::Vector2d centre(2.0, 0.7), reading(0.0, 1.0);
  const auto scene =
      testing::renderFloorText(*request.camera, "B2-117", centre, M_PI / 2, 1.2, 0.45);
  ASSERT_GT(scene.truth[0].y, request.camera->model.height);  // the start is cut
  ASSERT_LT(scene.truth[1].y, request.camera->model.height);  // the end shows
  request.placed_floor_texts = {{"B2-117", centre, reading}, {"A023", {2.0, 3.2}, reading}};
  const auto found = spotter_->spot(scene.image, request);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_TRUE(found[0].lexicon_match);
  EXPECT_TRUE(found[0].partial);
  EXPECT_EQ(found[0].text, "B2-117");
  for (const auto& p : found[0].polygon) EXPECT_LE(p.y, request.camera->model.height);
}

TEST_F(PpOcrSpotterTest, AFloorNumberCutByTheCarsBodyMatchesThePlacedTextByThePartThatShows) {
  static const geometry::Rig rig = geometry::defaultRig();
  SpotRequest request;
  request.lexicon = request.floor_lexicon = {"B2-117", "A023"};
  request.camera = rig.find("front");
  const geometry::RigCamera& camera = *request.camera;
  ASSERT_TRUE(camera.body);
  // Beside the car, reading forwards, its first characters behind the front bumper's plane
  // (x < 3.7 m), where the car hides them from the front camera.
  const Eigen::Vector2d centre(3.85, 2.2), reading(1.0, 0.0);
  auto scene = testing::renderFloorText(camera, "B2-117", centre, 0.0, 1.2, 0.45);
  // The image shows the car where the body is in the way, as a camera on it sees it.
  for (int y = 0; y < scene.image.rows; ++y)
    for (int x = 0; x < scene.image.cols; ++x) {
      const auto ray = camera.model.unproject(Eigen::Vector2d(x, y));
      if (ray && geometry::bodyHitsRay(*camera.body, camera.vehicle_from_camera.translation(),
                                       camera.vehicle_from_camera.linear() * *ray))
        scene.image.at<cv::Vec3b>(y, x) = cv::Vec3b(70, 66, 62);
    }
  request.placed_floor_texts = {{"B2-117", centre, reading}, {"A023", {8.0, 2.2}, reading}};
  const auto found = spotter_->spot(scene.image, request);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_TRUE(found[0].lexicon_match);
  EXPECT_EQ(found[0].text, "B2-117");
  // The box holds the part that shows: shorter than the whole number.
  const auto length = [](const Quad& q) {
    return static_cast<double>(cv::norm(0.5f * (q[1] + q[2]) - 0.5f * (q[0] + q[3])));
  };
  EXPECT_LT(length(found[0].polygon), 0.85 * length(scene.truth));
}

struct LeftFloorSpot {
  std::vector<TextInstance> found;
  Quad truth;
};
LeftFloorSpot spotOnTheLeftFloor(const PpOcrModelPaths& models, PpOcrOptions options = {}) {
  options.models = models;
  PpOcrSpotter spotter(options);
  const auto rig = geometry::defaultRig();
  const auto* left = rig.find("left");
  const auto scene = testing::renderFloorText(*left, "B2-117", {2.0, 2.6}, M_PI, 1.2, 0.45);
  SpotRequest request;
  request.lexicon = {"B2-112", "B2-117", "B1-117", "A023"};
  request.camera = left;
  return {spotter.spot(scene.image, request), scene.truth};
}

// The corner fit's tolerance on this 250 x 45 px number: the fit thresholds the ink inside
// the detected box grown a little, so a different box moves it by a pixel or two. Measured:
// 0.38 px with PaddleOCR's detector, 2.08 px with parkloc's floor detector (whose corners give
// the lower position error on the test split).
constexpr double kFloorCornerTolerancePx = 2.5;

// One instance, "B2-117" as the lexicon's entry, its corners within the tolerance.
void expectTheNumberMatchedAndFitted(const LeftFloorSpot& spot) {
  ASSERT_EQ(spot.found.size(), 1u);
  EXPECT_EQ(spot.found[0].text, "B2-117");
  EXPECT_TRUE(spot.found[0].lexicon_match);
  EXPECT_LT(maxCornerError(spot.found[0].polygon, spot.truth), kFloorCornerTolerancePx);
}

TEST(PpOcrSpotterModels, TheTunedFloorDetectorReadsFloorTextThroughTheFisheye) {
  auto models = PpOcrModelPaths::inDirectory(PARKLOC_MODEL_DIR);
  models.floor_detection = floorDetectorIn(PARKLOC_MODEL_DIR);
  const auto spot = spotOnTheLeftFloor(models);
  expectTheNumberMatchedAndFitted(spot);
}

// B2-117 on the left camera's floor, placed there, its box read from a crop that cuts a third
// of the number off, its top and bottom too; the spotter's instances without and with
// kRereadMargins.
struct RereadOutcome {
  std::vector<TextInstance> without, with;
};
RereadOutcome spotACutCropWithoutAndWithRereading(PpOcrOptions options) {
  options.models.floor_detection = floorDetectorIn(PARKLOC_MODEL_DIR);
  options.detection.floor_read_expand_x = 0.7f;
  options.detection.floor_read_expand_y = 0.6f;
  SpotRequest request = leftFloorRequest({"B2-117", "A023"});
  const cv::Mat image =
      testing::renderFloorText(*request.camera, "B2-117", {2.0, 2.6}, M_PI, 1.2, 0.45).image;
  request.placed_floor_texts = {{"B2-117", {2.0, 2.6}, {-1.0, 0.0}}};
  RereadOutcome out;
  options.reading.reread_margins.clear();
  out.without = PpOcrSpotter(options).spot(image, request);
  options.reading.reread_margins = kRereadMargins;
  out.with = PpOcrSpotter(options).spot(image, request);
  return out;
}

// A placed box that no reading matched is read again with the margins of reread_margins: the
// number matches only when read again.
TEST(PpOcrSpotterModels, AnUnmatchedPlacedBoxIsReadAgainWithOtherMargins) {
  PpOcrOptions options;
  options.models = PpOcrModelPaths::inDirectory(PARKLOC_MODEL_DIR);
  const auto spot = spotACutCropWithoutAndWithRereading(options);
  for (const TextInstance& inst : spot.without) EXPECT_FALSE(inst.lexicon_match);
  ASSERT_EQ(spot.with.size(), 1u);
  EXPECT_TRUE(spot.with[0].lexicon_match);
  EXPECT_EQ(spot.with[0].text, "B2-117");
  EXPECT_FALSE(spot.with[0].second_opinion);  // no fallback recognizer: the first read them
}

// With a fallback recognizer the margins are read by it alone (reread_by_fallback_only): the
// match is its second opinion. Without the margins neither recognizer matches the cut crop.
TEST(PpOcrSpotterModels, TheFallbackRecognizerAloneReadsTheMarginsWhenThereIsOne) {
  PpOcrOptions options;
  options.models = PpOcrModelPaths::inDirectory(PARKLOC_MODEL_DIR);
  options.models.fallback_recognition = tunedRecognizerIn(PARKLOC_MODEL_DIR);
  ASSERT_TRUE(options.reading.reread_by_fallback_only);
  const auto spot = spotACutCropWithoutAndWithRereading(options);
  for (const TextInstance& inst : spot.without) EXPECT_FALSE(inst.lexicon_match);
  ASSERT_EQ(spot.with.size(), 1u);
  EXPECT_TRUE(spot.with[0].lexicon_match);
  EXPECT_EQ(spot.with[0].text, "B2-117");
  EXPECT_TRUE(spot.with[0].second_opinion);
}

// A number 4.5 m along the right camera's side, beyond a +-3 m floor view: found and read in
// a window around where the map places it, by the fallback recognizer alone, and only there.
// (Farther out, as in the garage's drives, this test's point-sampled rendering of the paint
// aliases into noise.)
TEST(PpOcrSpotterModels, ANumberPlacedBeyondTheFloorViewIsFoundInAWindowAroundIt) {
  PpOcrOptions options;
  options.models = PpOcrModelPaths::inDirectory(PARKLOC_MODEL_DIR);
  options.models.floor_detection = floorDetectorIn(PARKLOC_MODEL_DIR);
  options.models.fallback_recognition = tunedRecognizerIn(PARKLOC_MODEL_DIR);
  options.detection.floor_view.half_width = 3.0;
  const auto rig = geometry::defaultRig();
  const geometry::RigCamera* right = rig.find("right");
  ASSERT_NE(right, nullptr);
  const Eigen::Vector2d centre(right->vehicle_from_camera.translation().x() + 4.5, -2.95);
  const auto scene = testing::renderFloorText(*right, "D009", centre, M_PI, 1.2, 0.45);
  SpotRequest request;
  request.lexicon = request.floor_lexicon = {"D008", "D009", "D010"};
  request.camera = right;
  request.placed_floor_texts = {{"D009", centre, {-1.0, 0.0}}};
  auto spotWith = [&](const PpOcrOptions& o, bool look_beyond) {
    PpOcrSpotter spotter(o);
    request.look_beyond_the_view = look_beyond;
    std::vector<TextInstance> found;
    for (const TextInstance& inst : spotter.spot(scene.image, request))
      if (inst.text == "D009") found.push_back(inst);
    return found;
  };
  const auto found = spotWith(options, true);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_TRUE(found[0].lexicon_match);
  EXPECT_TRUE(found[0].second_opinion);
  EXPECT_LT(maxCornerError(found[0].polygon, scene.truth), 3.0);
  EXPECT_TRUE(spotWith(options, false).empty());
  PpOcrOptions without = options;
  without.detection.placed_reach.half_width = 0.0;
  EXPECT_TRUE(spotWith(without, true).empty());
}

// A box read against the texts placed near it decodes under MapPriorOptions::placed_lexicon, one
// read against the whole floor lexicon under ReadingOptions::lexicon.
TEST(PpOcrSpotterModels, APlacedBoxDecodesUnderThePlacedLexiconsOptions) {
  PpOcrOptions options;
  options.models = PpOcrModelPaths::inDirectory(PARKLOC_MODEL_DIR);
  options.map_prior.placed_lexicon.min_posterior = 1.01;  // no placed match can pass
  PpOcrSpotter spotter(options);
  SpotRequest request = leftFloorRequest({"B2-117", "A023"});
  const cv::Mat image =
      testing::renderFloorText(*request.camera, "B2-117", {2.0, 2.6}, M_PI, 1.2, 0.45).image;
  auto found = spotter.spot(image, request);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_TRUE(found[0].lexicon_match);
  request.placed_floor_texts = {{"B2-117", {2.0, 2.6}, {-1.0, 0.0}}};
  found = spotter.spot(image, request);
  for (const TextInstance& inst : found) EXPECT_FALSE(inst.lexicon_match);
}

// The floor detector's box is read from a crop with a margin, and reported as detected.
TEST(PpOcrSpotterModels, TheFloorDetectorsBoxIsReadWithAMarginAndReportedAsDetected) {
  auto models = PpOcrModelPaths::inDirectory(PARKLOC_MODEL_DIR);
  models.floor_detection = floorDetectorIn(PARKLOC_MODEL_DIR);
  PpOcrOptions options;
  options.corners.refine = false;  // the reported polygon is the detected box itself
  ASSERT_GT(options.detection.floor_read_expand_x, 1.f);
  ASSERT_GT(options.detection.floor_read_expand_y, 1.f);
  const auto with_margin = spotOnTheLeftFloor(models, options);
  options.detection.floor_read_expand_x = options.detection.floor_read_expand_y = 1.f;
  const auto without = spotOnTheLeftFloor(models, options);
  ASSERT_EQ(with_margin.found.size(), 1u);
  ASSERT_EQ(without.found.size(), 1u);
  EXPECT_EQ(with_margin.found[0].text, "B2-117");
  EXPECT_TRUE(with_margin.found[0].lexicon_match);
  EXPECT_LT(maxCornerError(with_margin.found[0].polygon, without.found[0].polygon), 0.01);
}

// In the raw image's role (a photo, `parkloc eval photos`) the floor detector comes with its
// own post-processing: its thin kernels grown by floor_db's ratio and read with its margins
// find the words of a line of ordinary text, each box on one word or the whole line.
TEST(PpOcrSpotterModels, TheFloorDetectorReadsALineOfOrdinaryTextWithItsOwnPostProcessing) {
  const cv::Mat line = testing::renderTextLine("EXIT 42 HARBOUR", 22, 30);
  PpOcrOptions options;
  options.models = PpOcrModelPaths::inDirectory(PARKLOC_MODEL_DIR);
  options.models.detection = floorDetectorIn(PARKLOC_MODEL_DIR);
  options.detection = withRawImagesReadAs(DetectorRole::kFloorView, options.detection);
  ASSERT_FLOAT_EQ(options.detection.scene_db.box_threshold,
                  options.detection.floor_db.box_threshold);
  ASSERT_FLOAT_EQ(options.detection.scene_read_expand_y, options.detection.floor_read_expand_y);
  PpOcrSpotter spotter(options);
  std::string read;
  for (const TextInstance& inst : spotter.spot(line, {})) read += inst.text + " ";
  for (const char* word : {"EXIT", "42", "HARBOUR"})
    EXPECT_NE(read.find(word), std::string::npos) << word << " not in: " << read;
}

// A floor box whose ink fit is off or fails says so (box_only), and is reported grown from the
// detector's kernel by floor_unfitted_unclip_ratio when that is set: smaller than DB's box.
TEST(PpOcrSpotterModels, AFloorBoxWithoutAnInkFitSaysSoAndTakesTheUnfittedMargin) {
  auto models = PpOcrModelPaths::inDirectory(PARKLOC_MODEL_DIR);
  models.floor_detection = floorDetectorIn(PARKLOC_MODEL_DIR);
  PpOcrOptions options;
  const auto fitted = spotOnTheLeftFloor(models, options);
  ASSERT_EQ(fitted.found.size(), 1u);
  EXPECT_FALSE(fitted.found[0].box_only);

  options.corners.refine = false;
  const auto wide = spotOnTheLeftFloor(models, options);
  options.detection.floor_unfitted_unclip_ratio = 1.3;
  const auto tight = spotOnTheLeftFloor(models, options);
  ASSERT_EQ(wide.found.size(), 1u);
  ASSERT_EQ(tight.found.size(), 1u);
  EXPECT_TRUE(wide.found[0].box_only);
  EXPECT_TRUE(tight.found[0].box_only);
  EXPECT_EQ(tight.found[0].text, "B2-117");
  EXPECT_LT(quadWidth(tight.found[0].polygon), 0.97f * quadWidth(wide.found[0].polygon));
  EXPECT_LT(quadHeight(tight.found[0].polygon), 0.97f * quadHeight(wide.found[0].polygon));
}

// No reading is sure enough here (min_text_confidence above 1): the floor detector's box,
// clean and confident, is still reported, as unread text; a box under confident_box_score
// is not.
TEST(PpOcrSpotterModels, AConfidentFloorBoxIsReportedUnreadWhenNoReadingIsSure) {
  PpOcrOptions options;
  options.models = PpOcrModelPaths::inDirectory(PARKLOC_MODEL_DIR);
  options.models.floor_detection = floorDetectorIn(PARKLOC_MODEL_DIR);
  options.reading.min_text_confidence = 1.5f;
  const auto rig = geometry::defaultRig();
  const auto* left = rig.find("left");
  const auto scene = testing::renderFloorText(*left, "B2-117", {2.0, 2.6}, M_PI, 1.2, 0.45);
  SpotRequest request;
  request.camera = left;
  {
    PpOcrSpotter spotter(options);
    const auto found = spotter.spot(scene.image, request);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_TRUE(found[0].text.empty());
    EXPECT_FALSE(found[0].lexicon_match);
    EXPECT_EQ(found[0].raw_text, "B2-117");
    EXPECT_GE(found[0].detection_score, options.detection.confident_box_score);
    EXPECT_LT(maxCornerError(found[0].polygon, scene.truth), kFloorCornerTolerancePx);
  }
  options.detection.confident_box_score = 1.5f;
  PpOcrSpotter spotter(options);
  EXPECT_TRUE(spotter.spot(scene.image, request).empty());
}

TEST(PpOcrSpotterModels, AFallbackRecognizerLeavesWhatTheFirstMatchedAsItWas) {
  auto models = PpOcrModelPaths::inDirectory(PARKLOC_MODEL_DIR);
  models.fallback_recognition = tunedRecognizerIn(PARKLOC_MODEL_DIR);
  const auto spot = spotOnTheLeftFloor(models);
  expectTheNumberMatchedAndFitted(spot);
  EXPECT_FALSE(spot.found[0].second_opinion);  // the first reader matched it

  models.fallback_recognition = "/nonexistent/fallback_rec.onnx";
  expectInputErrorNaming(models, "/nonexistent/fallback_rec.onnx");
}

TEST(PpOcrSpotterModels, TheTunedRecognizerReadsFloorTextThroughTheFisheye) {
  auto models = PpOcrModelPaths::inDirectory(PARKLOC_MODEL_DIR);
  models.recognition = tunedRecognizerIn(PARKLOC_MODEL_DIR);
  const auto spot = spotOnTheLeftFloor(models);
  ASSERT_EQ(spot.found.size(), 1u);
  EXPECT_EQ(spot.found[0].text, "B2-117");
  EXPECT_EQ(spot.found[0].raw_text, "B2-117");
  EXPECT_TRUE(spot.found[0].lexicon_match);
}

// A sign "LIFT B2" upright in the left camera's image, above the floor (where the floor view
// cannot show it) and inside the horizon band: only the band detection finds it, and reports
// it in raw pixels. PaddleOCR's detector serves as the band detector here (any DB model can);
// the set-up's tuned one is measured by `parkloc eval ocr --band-detector tuned`.
TEST(PpOcrSpotterModels, TheBandDetectorFindsTextAboveTheFloorInRawPixels) {
  const auto rig = geometry::defaultRig();
  const auto* left = rig.find("left");
  cv::Mat image = testing::renderFloorText(*left, "A023", {2.0, 2.6}, M_PI, 1.0, 0.4).image;
  const cv::Mat sign = testing::renderTextLine("LIFT B2", 20, 10);
  const cv::Rect at(560, 64, sign.cols, sign.rows);
  ASSERT_GE(at.y, bandRect(RawBand{}, left->model).y);
  // Far beyond the floor view, or above the horizon: nothing of it in the floor view.
  const GroundView view(*left);
  const auto bottom = view.viewFromRaw(cv::Point2f(at.x + at.width / 2.f, at.br().y));
  ASSERT_FALSE(bottom && cv::Rect({0, 0}, view.size()).contains(*bottom));
  sign.copyTo(image(at));
  SpotRequest request;
  request.camera = left;

  auto found_at_sign = [&](const std::vector<TextInstance>& found) -> const TextInstance* {
    for (const auto& inst : found) {
      const cv::Point2f c =
          0.25f * (inst.polygon[0] + inst.polygon[1] + inst.polygon[2] + inst.polygon[3]);
      if (at.contains(cv::Point(cvRound(c.x), cvRound(c.y)))) return &inst;
    }
    return nullptr;
  };
  PpOcrOptions options;
  options.models = PpOcrModelPaths::inDirectory(PARKLOC_MODEL_DIR);
  {
    PpOcrSpotter floor_only(options);
    EXPECT_EQ(found_at_sign(floor_only.spot(image, request)), nullptr);
  }
  options.models.band_detection = options.models.detection;
  PpOcrSpotter with_band(options);
  const auto found = with_band.spot(image, request);
  const TextInstance* sign_found = found_at_sign(found);
  ASSERT_NE(sign_found, nullptr);
  EXPECT_EQ(sign_found->text, "LIFT B2");
  // In raw pixels: it overlaps the ink box (10 px inside the pasted line on every side) as a
  // match of the metrics must, IoU >= 0.5; a box left in band pixels would be 64 px too high.
  const std::vector<cv::Point2f> ink = {cv::Point2f(at.x + 10.f, at.y + 10.f),
                                        {at.br().x - 10.f, at.y + 10.f},
                                        {at.br().x - 10.f, at.br().y - 10.f},
                                        {at.x + 10.f, at.br().y - 10.f}};
  std::vector<cv::Point2f> box(sign_found->polygon.begin(), sign_found->polygon.end()), common;
  const double inter = cv::intersectConvexConvex(ink, box, common, true);
  const double iou = inter / (cv::contourArea(ink) + cv::contourArea(box) - inter);
  EXPECT_GE(iou, 0.5);
}

// The set-up writes the recognizer from PaddleOCR's with parkloc's tuned head: its output
// for the same crop must differ from the stock recognizer's.
TEST(PpOcrSpotterModels, TheTunedRecognizerIsNotPaddleOcrsOwn) {
  const auto paths = PpOcrModelPaths::inDirectory(PARKLOC_MODEL_DIR);
  const CtcRecognizer stock(paths.recognition, {}), tuned(tunedRecognizerIn(PARKLOC_MODEL_DIR), {});
  cv::Mat crop(CtcRecognizer::kHeight, 160, CV_8UC3, cv::Scalar(90, 90, 90));
  cv::putText(crop, "B2-117", {8, 38}, cv::FONT_HERSHEY_SIMPLEX, 1.2, cv::Scalar(220, 220, 220), 3);
  const auto a = stock.recognize({crop}, 1), b = tuned.recognize({crop}, 1);
  ASSERT_EQ(a[0].probs.size(), b[0].probs.size());
  double diff = 0.0;
  for (size_t i = 0; i < a[0].probs.size(); ++i) diff += std::abs(a[0].probs[i] - b[0].probs[i]);
  EXPECT_GT(diff / a[0].steps, 1e-4);  // the same model gives exactly 0
}

// The set-up writes the band detector from PaddleOCR's with parkloc's tuned tensors: its
// probability map of the same horizon band must differ from the stock detector's.
TEST(PpOcrSpotterModels, TheBandDetectorIsNotPaddleOcrsOwn) {
  const auto paths = PpOcrModelPaths::inDirectory(PARKLOC_MODEL_DIR);
  const DbDetector stock(paths.detection, {}), band(bandDetectorIn(PARKLOC_MODEL_DIR), {});
  cv::Mat image(800, 1280, CV_8UC3, cv::Scalar(110, 110, 110));
  const cv::Mat sign = testing::renderTextLine("B1", 40, 12);
  sign.copyTo(image(cv::Rect({600, 150}, sign.size())));
  const cv::Mat rows = image(bandRect(RawBand{}, geometry::defaultRig().cameras[0].model));
  const cv::Mat a = stock.probability({rows})[0], b = band.probability({rows})[0];
  ASSERT_EQ(a.size(), b.size());
  EXPECT_GT(cv::norm(a, b, cv::NORM_L1) / a.total(), 1e-4);
}

// The set-up writes the floor detector from PaddleOCR's with parkloc's tuned tensors: its
// probability map of the same floor view must differ from the stock detector's.
TEST(PpOcrSpotterModels, TheFloorDetectorIsNotPaddleOcrsOwn) {
  const auto paths = PpOcrModelPaths::inDirectory(PARKLOC_MODEL_DIR);
  const DbDetector stock(paths.detection, {}), floor(floorDetectorIn(PARKLOC_MODEL_DIR), {});
  const auto rig = geometry::defaultRig();
  const auto scene =
      testing::renderFloorText(*rig.find("left"), "B2-117", {2.0, 2.6}, M_PI, 1.2, 0.45);
  const cv::Mat view = GroundView(*rig.find("left")).render(scene.image);
  const cv::Mat a = stock.probability({view})[0], b = floor.probability({view})[0];
  ASSERT_EQ(a.size(), b.size());
  EXPECT_GT(cv::norm(a, b, cv::NORM_L1) / a.total(), 1e-3);
}

}  // namespace
}  // namespace parkloc::ocr
