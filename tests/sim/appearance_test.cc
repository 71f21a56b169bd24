// The appearance factors: each garage factor changes the rendered image where it should and
// never the labels, each camera factor changes the image, and with every factor off the render
// is the plain one, byte for byte.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "common/error.h"
#include "sim/annotate.h"
#include "sim/camera_effects.h"
#include "sim/garage_appearance.h"
#include "sim/number_styles.h"
#include "sim/text_raster.h"
#include "sim_test_util.h"

namespace parkloc::sim {
namespace {

struct Frame {
  cv::Mat image;
  std::vector<io::LabelInstance> labels;
};

// A camera of a car in the small garage's aisle: by default the right one, looking at the south
// row's numbers. `every_number`: every parking number the camera projects is labelled,
// however small or far.
Frame renderCamera(const Garage& g, size_t camera = 3, bool every_number = false) {
  const geometry::Rig rig = testing::scaledRig(0.5);
  const geometry::Pose2 pose(14.0, g.aisle_y[0] + 0.5, 0.0);
  LightingOptions light = lightingForCondition("bright", 3);
  Renderer renderer(g, 0, rig, testing::raysOf(rig), light);
  AnnotateOptions options;
  if (every_number) {
    options.min_labelled_height_px = 0.0;
    options.min_inside_fraction = 0.0;
    options.max_distance = 1e3;
  }
  return {renderer.renderCamera(camera, pose, 11),
          annotateImage(g, 0, rig.cameras[camera], pose, options)};
}
Frame renderRight(const Garage& g) { return renderCamera(g); }

Garage smallGarage() {
  GarageSpec spec = testing::smallSpec();
  spec.occupancy = 0.3;
  return generateGarage(spec, 5);
}

void expectSameLabels(const std::vector<io::LabelInstance>& a,
                      const std::vector<io::LabelInstance>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].text, b[i].text);
    EXPECT_EQ(a[i].landmark_id, b[i].landmark_id);
    EXPECT_EQ(a[i].legible, b[i].legible) << a[i].text;
    for (int k = 0; k < 4; ++k) EXPECT_EQ(a[i].polygon[k], b[i].polygon[k]) << a[i].text;
  }
}

// Pixels (out of the whole image) where two renders differ by more than 2 levels.
cv::Mat changed(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat diff, grey;
  cv::absdiff(a, b, diff);
  cv::cvtColor(diff, grey, cv::COLOR_BGR2GRAY);
  return grey > 2;
}

TEST(Appearance, EveryFactorOffRendersThePlainImageByteForByte) {
  const Garage g = smallGarage();
  const Frame plain = renderRight(g);
  const Frame styled = renderRight(withAppearance(g, AppearanceOptions{}));
  EXPECT_EQ(cv::norm(plain.image, styled.image, cv::NORM_INF), 0.0);
  expectSameLabels(plain.labels, styled.labels);
  cv::Mat copy = plain.image.clone();
  const CameraEffects none(AppearanceOptions{}, testing::scaledRig(0.5), 7);
  EXPECT_FALSE(none.active());
  none.apply(copy, 3, 1.0, 99);
  EXPECT_EQ(cv::norm(plain.image, copy, cv::NORM_INF), 0.0);
}

TEST(Appearance, EachFloorFactorChangesTheFloorAndNotTheLabels) {
  const Garage g = smallGarage();
  const Frame plain = renderRight(g);
  for (const std::string factor : {"floor_wear", "gloss", "epoxy"}) {
    AppearanceOptions a;
    appearanceFactor(a, factor) = 1.0f;
    const Frame styled = renderRight(withAppearance(g, a));
    // The floor fills the lower half of a side camera's image.
    const cv::Mat lower =
        changed(plain.image, styled.image).rowRange(plain.image.rows / 2, plain.image.rows);
    EXPECT_GT(cv::countNonZero(lower), lower.total() / 50) << factor;
    expectSameLabels(plain.labels, styled.labels);
  }
}

TEST(Appearance, EachNumberStyleChangesOnlyAroundTheNumbers) {
  const Garage g = smallGarage();
  const Frame plain = renderCamera(g, 3, true);
  for (const std::string factor : {"stencil", "outlined", "boxed", "faded"}) {
    AppearanceOptions a;
    appearanceFactor(a, factor) = 1.0f;
    const Garage styled_garage = withAppearance(g, a);
    const Frame styled = renderCamera(styled_garage, 3, true);
    expectSameLabels(plain.labels, styled.labels);
    EXPECT_EQ(styled_garage.map.landmarks().size(), g.map.landmarks().size());
    // Around each number: its polygon grown about its centre (frames and patches reach out).
    cv::Mat around(plain.image.size(), CV_8U, cv::Scalar(0));
    for (const io::LabelInstance& l : plain.labels) {
      if (l.cls != map::TextClass::kParkingNumber) continue;
      const Eigen::Vector2d c = 0.25 * (l.polygon[0] + l.polygon[1] + l.polygon[2] + l.polygon[3]);
      std::vector<cv::Point> grown;
      for (const auto& p : l.polygon) {
        const Eigen::Vector2d q = c + 2.2 * (p - c);
        grown.emplace_back(static_cast<int>(q.x()), static_cast<int>(q.y()));
      }
      cv::fillConvexPoly(around, grown, cv::Scalar(255));
    }
    const cv::Mat diff = changed(plain.image, styled.image);
    EXPECT_GT(cv::countNonZero(diff & around), 50) << factor;
    EXPECT_EQ(cv::countNonZero(diff & ~around), 0) << factor;
  }
}

TEST(Appearance, FadedNumbersPastReadingAreLabelledIllegible) {
  GarageSpec spec = testing::smallSpec();
  spec.aisles = 2;
  spec.slots_per_row = 20;
  const Garage g = generateGarage(spec, 9);
  AppearanceOptions a;
  a.faded = 1.0f;
  const Garage faded = withAppearance(g, a);
  int past_reading = 0, legible_left = 0;
  for (const GarageLevel& level : faded.levels)
    for (const TextItem& item : level.texts) {
      if (item.floor_decal < 0 || item.landmark.cls != map::TextClass::kParkingNumber) continue;
      const Decal& d = level.floor_decals[static_cast<size_t>(item.floor_decal)];
      EXPECT_GT(d.wear, 0.0f);
      (d.ink_kept < 0.4f ? past_reading : legible_left)++;
    }
  EXPECT_GT(past_reading, 0);
  EXPECT_GT(legible_left, 0);
  // The labels of a camera: a number with under 40 % of its ink is never legible.
  const geometry::Rig rig = testing::scaledRig(0.5);
  AnnotateOptions options;
  options.min_ink_kept = 0.4;
  for (double x = 6.0; x < 40.0; x += 6.0) {
    const geometry::Pose2 pose(x, faded.aisle_y[0] + 0.5, 0.0);
    for (const io::LabelInstance& l : annotateImage(faded, 0, rig.cameras[3], pose, options)) {
      if (l.cls != map::TextClass::kParkingNumber) continue;
      for (const TextItem& item : faded.levels[0].texts) {
        if (item.landmark.id == l.landmark_id &&
            faded.levels[0].floor_decals[static_cast<size_t>(item.floor_decal)].ink_kept < 0.4f) {
          EXPECT_FALSE(l.legible) << l.text;
        }
      }
    }
  }
}

TEST(Appearance, EachCameraFactorChangesTheImage) {
  // The front camera: it sees the lamps down the aisle, which flare and the lens dirt scatter.
  const Garage g = smallGarage();
  const Frame plain = renderCamera(g, 0);
  double brightest = 0.0;
  cv::minMaxLoc(plain.image.reshape(1), nullptr, &brightest);
  ASSERT_GE(brightest, 250.0);
  const geometry::Rig rig = testing::scaledRig(0.5);
  for (const std::string factor :
       {"auto_exposure", "white_balance", "hdr_clipping", "lens_dirt", "flare", "compression"}) {
    AppearanceOptions a;
    appearanceFactor(a, factor) = 1.0f;
    const CameraEffects effects(a, rig, 21);
    EXPECT_TRUE(effects.active());
    cv::Mat image = plain.image.clone();
    effects.apply(image, 0, 2.0, 77);
    EXPECT_EQ(image.size(), plain.image.size());
    EXPECT_GT(cv::countNonZero(changed(plain.image, image)), 100) << factor;
  }
}

TEST(Appearance, StencilAndOutlineKeepTheInkBox) {
  TextRasterizer raster;
  const cv::Mat ink = raster.render(resolveFontPath("DejaVuSans-Bold.ttf"), "808", 120);
  for (int style = 0; style < 2; ++style) {
    cv::Mat styled = ink.clone();
    style == 0 ? cutStencilBridges(styled) : hollowOutGlyphs(styled);
    EXPECT_EQ(cv::boundingRect(styled > 24), cv::boundingRect(ink > 24)) << style;
    EXPECT_LT(cv::sum(styled)[0], (style == 0 ? 0.97 : 0.8) * cv::sum(ink)[0]) << style;
    EXPECT_GT(cv::sum(styled)[0], 0.3 * cv::sum(ink)[0]) << style;
  }
  // A stencil "8" is cut at its top, waist and bottom: its centre column keeps little ink.
  cv::Mat stencil = ink.clone();
  cutStencilBridges(stencil);
  int x0 = 0, x1 = 0;
  while (cv::countNonZero(ink.col(x0) >= 128) == 0) ++x0;
  for (x1 = x0; x1 < ink.cols && cv::countNonZero(ink.col(x1) >= 128) > 0;) ++x1;
  const int mid = (x0 + x1) / 2;
  EXPECT_GT(cv::countNonZero(ink.col(mid) >= 128), 20);
  EXPECT_LT(cv::countNonZero(stencil.col(mid) >= 128), 0.3 * cv::countNonZero(ink.col(mid) >= 128));
}

TEST(Appearance, ScenarioKeysPresetsAndRepeats) {
  const std::string yaml = R"(
garages:
  - name: g
    appearance: {floor_wear: true, gloss: 0.5}
    drives:
      - {route: tour, condition: weak, duration_s: 4}
      - {repeat_of: 0, appearance: realistic}
      - {repeat_of: 0, appearance: {gloss: false, flare: 0.25}}
      - {route: park, condition: blur, appearance: clean}
)";
  const Scenario s = parseScenario(yaml, "test.yaml");
  const auto& d = s.garages[0].drives;
  EXPECT_EQ(d[0].appearance.subset(), "floor_wear+gloss");
  EXPECT_EQ(d[1].appearance.subset(), "realistic");
  EXPECT_EQ(d[1].condition, "weak");  // repeats drive 0's route and light
  EXPECT_EQ(d[1].repeat_of, 0);
  EXPECT_EQ(d[2].appearance.subset(), "floor_wear+flare");
  EXPECT_FLOAT_EQ(d[2].appearance.flare, 0.25f);
  EXPECT_EQ(d[3].appearance.subset(), "clean");
  EXPECT_EQ(DriveSpec{}.appearance.subset(), "clean");

  auto message = [](const std::string& text) {
    try {
      parseScenario(text, "bad.yaml");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(message("garages: [{name: g, appearance: {shine: 1}}]"),
            "bad.yaml garage 0: unknown appearance key 'shine'");
  EXPECT_EQ(message("garages: [{name: g, appearance: {flare: 2}}]"),
            "bad.yaml garage 0: appearance key 'flare' out of range (0 to 1)");
  EXPECT_EQ(message("garages: [{name: g, appearance: {flare: bright}}]"),
            "bad.yaml garage 0: appearance key 'flare' has an invalid value 'bright'");
  EXPECT_NE(message("garages: [{name: g, appearance: shiny}]").find("field 'appearance'"),
            std::string::npos);
  EXPECT_EQ(message("garages: [{name: g, drives: [{repeat_of: 0}]}]"),
            "bad.yaml garage 0 drive 0: field 'repeat_of' must name an earlier drive of its own");
}

}  // namespace
}  // namespace parkloc::sim
