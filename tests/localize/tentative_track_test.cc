// A wrong first fix from one misread number, through the whole pipeline: under the wrong
// pose the map predicts numbers where other numbers are painted, fitting their ink at the
// predicted place seems to confirm it, and decoding a region against its predicted text
// alone forces that text on the ink. The tentative track (track_lifecycle.h) reads those
// regions against the whole map and re-initialises on the reads that disagree.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "localize/pipeline.h"
#include "synthetic_scene.h"

namespace parkloc::localize {
namespace {

// The aisle repeats every 7.5 m (a pillar every third bay, numbers every 2.5 m on both
// sides): the number 6 further on is painted 7.5 m further, where the plan looks the same.
std::string sixFurther(const std::string& text) {
  return "B2-" + std::to_string(std::stoi(text.substr(3)) + 6);
}

// Reads the synthetic aisle the way the OCR engine does. A full frame shows what the camera
// sees; the first one that sees a parking number shows only its largest one, misread as
// sixFurther(text) when `misread`. A region finds the ink nearest its predicted text (within
// half the text's width): fitted, it carries the expected text unread; read, it carries the
// ink's own text when the request's lexicon holds it, else the expected text (decoding
// against the predicted text alone forces it on whatever ink is there).
class EngineLikeSpotter : public ocr::TextSpotter {
 public:
  EngineLikeSpotter(const map::HdMap& map, bool misread) : map_(map), misread_(misread) {}
  std::string name() const override { return "engine-like"; }
  std::vector<ocr::TextInstance> spot(const cv::Mat&, const ocr::SpotRequest& request) override {
    std::vector<ocr::TextInstance> all = testing::spotExactly(*request.camera, map_, pose, {});
    if (request.regions.empty()) {
      const auto number = [](const ocr::TextInstance& t) {
        return t.cls == map::TextClass::kParkingNumber;
      };
      if (first_text_seen || std::none_of(all.begin(), all.end(), number)) return all;
      first_text_seen = true;
      all.erase(std::remove_if(all.begin(), all.end(), [&](const auto& t) { return !number(t); }),
                all.end());
      const auto size = [](const ocr::TextInstance& t) {
        return cv::norm(t.polygon[1] - t.polygon[0]) * cv::norm(t.polygon[3] - t.polygon[0]);
      };
      const auto largest = std::max_element(
          all.begin(), all.end(), [&](const auto& a, const auto& b) { return size(a) < size(b); });
      ocr::TextInstance only = *largest;
      if (misread_) only.text = only.raw_text = sixFurther(only.text);
      first_text = only.text;
      return {only};
    }
    std::vector<ocr::TextInstance> out;
    for (const ocr::RegionOfInterest& r : request.regions) {
      const cv::Point2f centre = (r.predicted[0] + r.predicted[1] + r.predicted[2] + r.predicted[3]) / 4.f;
      const double width = cv::norm(r.predicted[1] - r.predicted[0]);
      const ocr::TextInstance* ink = nullptr;
      double nearest = 0.5 * width;
      for (const auto& t : all) {
        const cv::Point2f c = (t.polygon[0] + t.polygon[1] + t.polygon[2] + t.polygon[3]) / 4.f;
        if (cv::norm(c - centre) < nearest) {
          nearest = cv::norm(c - centre);
          ink = &t;
        }
      }
      if (!ink) continue;
      ocr::TextInstance t = *ink;
      t.read = r.read;
      const bool in_lexicon =
          std::find(request.lexicon.begin(), request.lexicon.end(), t.text) != request.lexicon.end();
      if (!r.read || !in_lexicon) t.text = t.raw_text = r.expected_texts.front();
      out.push_back(t);
    }
    return out;
  }
  geometry::Pose2 pose;
  bool first_text_seen = false;
  std::string first_text;

 private:
  const map::HdMap& map_;
  bool misread_;
};

struct Drive {
  int first_pose_frame = -1;
  bool first_pose_tentative = false;
  double first_pose_error_m = 0.0;
  std::vector<double> error_m;  // per frame set from the first pose on
  std::vector<bool> tentative;
};

// 6 s along the aisle at 1.5 m/s, 10 frame sets a second.
Drive drive(const PipelineOptions& options, bool misread, std::string* first_text = nullptr) {
  const geometry::Rig rig = geometry::defaultRig();
  const map::HdMap map = testing::aisleMap();
  EngineLikeSpotter spotter(map, misread);
  Pipeline pipeline(rig, map, options, &spotter);
  Drive d;
  for (int k = 0; k < 60; ++k) {
    const double t = k / 10.0;
    spotter.pose = geometry::Pose2(1.5 * t, 0.1, 0.0);
    const FrameResult r = pipeline.process(testing::placeholderFrame(rig, t, 1.5));
    if (!r.has_pose) continue;
    const double error = (r.pose.translation() - spotter.pose.translation()).norm();
    if (d.first_pose_frame < 0) {
      d.first_pose_frame = k;
      d.first_pose_tentative = r.tentative;
      d.first_pose_error_m = error;
    }
    d.error_m.push_back(error);
    d.tentative.push_back(r.tentative);
  }
  if (first_text) *first_text = spotter.first_text;
  return d;
}

TEST(TentativeTrack, AWrongFirstFixFromOneMisreadNumberIsLeftWithinAFewFrameSets) {
  std::string misread;
  const Drive d = drive(PipelineOptions{}, true, &misread);
  ASSERT_GE(d.first_pose_frame, 0);
  ASSERT_FALSE(misread.empty());
  // The misreading placed the first pose 7.5 m off, and said so.
  EXPECT_NEAR(d.first_pose_error_m, 7.5, 0.2) << misread;
  EXPECT_TRUE(d.first_pose_tentative);
  // Within three frame sets the reads moved the track to the right place, and it stayed.
  ASSERT_GT(d.error_m.size(), 10u);
  for (size_t k = 3; k < d.error_m.size(); ++k) EXPECT_LT(d.error_m[k], 0.05) << "frame " << k;
  EXPECT_FALSE(d.tentative.back());
}

TEST(TentativeTrack, WithoutItTheFitsAndForcedReadsHoldTheWrongPose) {
  PipelineOptions options;
  options.tracking.confirm_read_landmarks = 1;  // every track confirmed from its start
  const Drive d = drive(options, true);
  ASSERT_GT(d.error_m.size(), 30u);
  EXPECT_FALSE(d.first_pose_tentative);
  // The forced reads agree with the wrong pose; the sweep's texts that disagree never add
  // up to three consecutive frame sets.
  EXPECT_NEAR(d.error_m[30], 7.5, 0.2);
}

TEST(TentativeTrack, ARightFirstFixFromOneNumberIsConfirmedAndKeepsItsPose) {
  const Drive d = drive(PipelineOptions{}, false);
  const Drive plain = [] {
    PipelineOptions options;
    options.tracking.confirm_read_landmarks = 1;
    return drive(options, false);
  }();
  ASSERT_GE(d.first_pose_frame, 0);
  EXPECT_EQ(d.first_pose_frame, plain.first_pose_frame);  // the first pose as early
  EXPECT_TRUE(d.first_pose_tentative);
  EXPECT_LT(d.first_pose_error_m, 0.05);
  ASSERT_GT(d.tentative.size(), 5u);
  EXPECT_FALSE(d.tentative[3]);  // a second number read within three frame sets
  for (size_t k = 0; k < d.error_m.size(); ++k) EXPECT_LT(d.error_m[k], 0.05) << "frame " << k;
}

}  // namespace
}  // namespace parkloc::localize
