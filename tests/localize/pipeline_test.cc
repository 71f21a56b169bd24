#include "localize/pipeline.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <chrono>
#include <functional>
#include <future>
#include <atomic>
#include <map>
#include <random>
#include <set>
#include <opencv2/imgproc.hpp>
#include <thread>

#include "localize/box_plot_filter.h"
#include "localize/capture_time.h"
#include "synthetic_scene.h"

namespace parkloc::localize {
namespace {

constexpr double kFrameRate = 10.0;

// A drive down the aisle at 2 m/s with a gentle weave; `jump` moves the true vehicle
// forward by `jump_m` at `jump_time` without the odometry noticing (kidnapping).
struct Drive {
  double jump_time = 1e9;
  double jump_m = 0.0;

  geometry::Pose2 truth(double t) const {
    const double x = 2.0 * t + (t >= jump_time ? jump_m : 0.0);
    const double y = 0.3 * std::sin(0.4 * t);
    const double yaw = std::atan2(0.12 * std::cos(0.4 * t), 2.0);
    return {x, y, yaw};
  }
  OdometrySample odometry(double t) const {
    const double h = 1e-4;
    const auto a = truth(t - h), b = truth(t + h);
    OdometrySample s;
    s.timestamp = t;
    s.speed = (b.translation() - a.translation()).norm() / (2 * h);
    s.yaw_rate = geometry::wrapAngle(b.yaw - a.yaw) / (2 * h);
    if (t >= jump_time - h && t < jump_time + h) s.speed = 2.0;  // the jump is not driven
    return s;
  }
};

// The first instance of the first camera that sees a parking number, or null.
ocr::TextInstance* firstParkingNumber(std::vector<CameraInput>& cameras) {
  for (auto& c : cameras)
    for (auto& t : *c.instances)
      if (t.cls == map::TextClass::kParkingNumber) return &t;
  return nullptr;
}

class PipelineTest : public ::testing::Test {
 protected:
  geometry::Rig rig = geometry::defaultRig();
  map::HdMap map = testing::aisleMap();
  std::mt19937 rng{21};
  testing::SpotOptions spot;

  PipelineTest() { spot.max_range_m = 10.0; }

  // Frame k of a drive, with oracle instances (plus what `edit` does to them).
  FrameInput frame(const Drive& drive, int k,
                   const std::function<void(std::vector<CameraInput>&)>& edit = {}) {
    FrameInput in;
    in.timestamp = k / kFrameRate;
    for (const auto& camera : rig.cameras) {
      CameraInput c;
      c.camera = camera.name;
      c.instances = testing::spotExactly(camera, map, drive.truth(in.timestamp), spot, &rng);
      in.cameras.push_back(std::move(c));
    }
    // Odometry at 50 Hz in (previous frame, this frame].
    for (int j = 1; j <= 5; ++j)
      in.odometry.push_back(drive.odometry(in.timestamp - 0.1 + j * 0.02));
    if (edit) edit(in.cameras);
    return in;
  }

  // An image of camera c at its calibrated size, its first channel c (SceneSpotter tells
  // the cameras apart by it).
  cv::Mat cameraImage(size_t c) const {
    const auto& model = rig.cameras[c].model;
    return cv::Mat(model.height, model.width, CV_8UC3, cv::Scalar(static_cast<double>(c), 0, 0));
  }

  // 20 tracked frames, then one with a misreading of a number that is in the map, at its
  // far end.
  FrameResult withAFarMisreading(Pipeline& pipeline, const Drive& drive) {
    for (int k = 0; k < 20; ++k) pipeline.process(frame(drive, k));
    return pipeline.process(frame(drive, 20, [&](std::vector<CameraInput>& cameras) {
      auto* real = firstParkingNumber(cameras);
      ASSERT_NE(real, nullptr);
      ocr::TextInstance wrong = *real;
      wrong.text = "B2-164";
      cameras.front().instances->push_back(wrong);
    }));
  }

  static double positionError(const FrameResult& r, const geometry::Pose2& truth) {
    return (r.pose.translation() - truth.translation()).norm();
  }
};

TEST_F(PipelineTest, TracksADriveWithNoisyOracleDetections) {
  spot.pixel_noise = 0.5;
  Pipeline pipeline(rig, map);
  Drive drive;
  double sum = 0.0, worst = 0.0, yaw_sum = 0.0;
  int frames = 0;
  for (int k = 0; k < 60; ++k) {
    const auto r = pipeline.process(frame(drive, k));
    ASSERT_TRUE(r.has_pose) << "frame " << k;  // the first frame already sees numbers
    EXPECT_EQ(r.status, TrackingStatus::kOk);
    const double e = positionError(r, drive.truth(r.timestamp));
    sum += e;
    worst = std::max(worst, e);
    yaw_sum += std::abs(geometry::wrapAngle(r.pose.yaw - drive.truth(r.timestamp).yaw));
    ++frames;
    EXPECT_GT(r.covariance(0, 0), 0.0);
  }
  EXPECT_LT(sum / frames, 0.01);
  EXPECT_LT(worst, 0.03);
  EXPECT_LT(yaw_sum / frames, 0.1 * M_PI / 180);
}

TEST_F(PipelineTest, AFixWhoseCornersFitWorseThanThePixelNoiseCountsForLess) {
  // The same first frame with exact corners and with corners 6 px off (1.5 px assumed):
  // the solver's covariance assumes the pixel noise, the filter's must not.
  const Drive drive;
  auto fixCovariance = [&](double pixel_noise) {
    spot.pixel_noise = pixel_noise;
    std::mt19937 fixed(5);
    std::swap(rng, fixed);
    // The synthetic map is exact and says so: the fix's covariance is its pixel part alone.
    PipelineOptions options;
    options.solver.assumed_map_position_sigma_m = options.solver.assumed_map_heading_sigma_deg = 0;
    options.solver.map_size_sigma = 0.0;
    Pipeline pipeline(rig, map, options);
    const FrameResult r = pipeline.process(frame(drive, 0));
    EXPECT_TRUE(r.measurement_covariance.has_value());
    return r.measurement_covariance.value_or(Eigen::Matrix3d::Zero());
  };
  const Eigen::Matrix3d exact = fixCovariance(0.0), noisy = fixCovariance(6.0);
  // Grown by about (rms / pixel_sigma)^2 = 16 in position and yaw.
  EXPECT_GT(noisy(0, 0), 8.0 * exact(0, 0));
  EXPECT_GT(noisy(1, 1), 8.0 * exact(1, 1));
  EXPECT_GT(noisy(2, 2), 8.0 * exact(2, 2));
}

TEST_F(PipelineTest, AnUncertainFirstFixFromOneTextWaitsForMoreTexts) {
  // Frame 0 sees a single parking number, its corners 3 px off: its fix is about a metre
  // uncertain. The filter must not start from it, unless the gate is switched off.
  const Drive drive;
  auto first = [&](double max_sigma) {
    std::mt19937 fixed(9);
    std::swap(rng, fixed);
    spot.pixel_noise = 3.0;
    PipelineOptions options;
    options.tracking.first_fix_max_sigma_m = max_sigma;
    Pipeline pipeline(rig, map, options);
    return pipeline.process(frame(drive, 0, [](std::vector<CameraInput>& cameras) {
      // Keep the first parking number, in the camera that saw it, and nothing else.
      const ocr::TextInstance* number = firstParkingNumber(cameras);
      ASSERT_NE(number, nullptr);
      for (auto& c : cameras) {
        std::vector<ocr::TextInstance> kept;
        for (const auto& t : *c.instances)
          if (&t == number) kept.push_back(t);
        *c.instances = std::move(kept);
      }
    }));
  };
  const FrameResult ungated = first(0.0);
  ASSERT_TRUE(ungated.has_pose);
  ASSERT_TRUE(ungated.measurement_covariance.has_value());
  const Eigen::Matrix2d position = ungated.measurement_covariance->topLeftCorner<2, 2>();
  const double sigma =
      std::sqrt(Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(position).eigenvalues().maxCoeff());
  const double gate = PipelineOptions{}.tracking.first_fix_max_sigma_m;
  ASSERT_GT(sigma, gate);  // the premise: one noisy text is an uncertain fix

  const FrameResult gated = first(gate);
  EXPECT_FALSE(gated.has_pose);
  EXPECT_TRUE(gated.measurement_covariance.has_value());  // reported, not fused
  bool warned = false;
  for (const auto& w : gated.warnings)
    warned |= w.find("first fix too uncertain") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST_F(PipelineTest, DeadReckonsWithGrowingCovarianceWhenNothingIsSeen) {
  Pipeline pipeline(rig, map);
  Drive drive;
  double previous_sigma = 0.0;
  for (int k = 0; k < 50; ++k) {
    const bool blind = k >= 20 && k < 40;
    const auto r = pipeline.process(frame(drive, k, [&](std::vector<CameraInput>& cameras) {
      if (blind)
        for (auto& c : cameras) c.instances->clear();
    }));
    ASSERT_TRUE(r.has_pose);
    if (blind) {
      EXPECT_EQ(r.status, TrackingStatus::kDeadReckoning) << "frame " << k;
      EXPECT_GT(r.covariance(1, 1), previous_sigma);
      EXPECT_LT(positionError(r, drive.truth(r.timestamp)), 0.2);
    } else {
      EXPECT_EQ(r.status, TrackingStatus::kOk) << "frame " << k;
    }
    previous_sigma = r.covariance(1, 1);
  }
}

TEST_F(PipelineTest, RejectsAFalseNumberAtTheWrongPlaceANumberNotInTheMapAndAFlippedReading) {
  // Without the AFM, which would already drop a number this far off the recent ones: the
  // gate must catch it on its own.
  PipelineOptions options;
  options.paper_modules.afm = false;
  Pipeline pipeline(rig, map, options);
  Drive drive;
  for (int k = 0; k < 20; ++k) pipeline.process(frame(drive, k));
  // Three extra instances: copies of a real one with a wrong text (in the map, in the
  // AFM's range, 20 m away), a text not in the map, and the real text with the polygon
  // turned by 180 degrees (reading order reversed).
  std::string real_text;
  const auto r = pipeline.process(frame(drive, 20, [&](std::vector<CameraInput>& cameras) {
    auto* real = firstParkingNumber(cameras);
    ASSERT_NE(real, nullptr);
    real_text = real->text;
    const auto* landmark = map.findByText(real->text).front();
    const auto far =
        map.withinRadius(landmark->position.head<2>() + Eigen::Vector2d(20.0, 0.0), 1.5);
    ASSERT_FALSE(far.empty());
    ocr::TextInstance wrong = *real, unknown = *real, flipped = *real;
    wrong.text = far.front()->text;
    // In the AFM's range (same number), but no such text in the map.
    unknown.text = "C7-" + std::to_string(*parkingNumberValue(real->text));
    flipped.polygon = {real->polygon[2], real->polygon[3], real->polygon[0], real->polygon[1]};
    cameras.front().instances->push_back(wrong);
    cameras.front().instances->push_back(unknown);
    cameras.front().instances->push_back(flipped);
  }));
  ASSERT_EQ(r.status, TrackingStatus::kOk);
  int gated = 0, not_in_map = 0, flipped = 0, accepted = 0;
  for (const auto& a : r.associations) {
    if (a.verdict == AssociationVerdict::kGated) ++gated;
    if (a.verdict == AssociationVerdict::kNotInMap) ++not_in_map;
    if (a.verdict == AssociationVerdict::kFlipped) {
      ++flipped;
      EXPECT_EQ(a.text, real_text);
    }
    if (a.verdict == AssociationVerdict::kAccepted) ++accepted;
  }
  EXPECT_EQ(gated, 1);
  EXPECT_EQ(not_in_map, 1);
  EXPECT_EQ(flipped, 1);
  EXPECT_GT(accepted, 2);
  EXPECT_LT(positionError(r, drive.truth(r.timestamp)), 0.02);
}

// A misreading far from the numbers around the vehicle: in the paper's pipeline the
// box plot drops it; while parkloc tracks, the pose gate does (the box plot would also drop
// the new numbers after a turn into another aisle).
int countVerdicts(const FrameResult& r, AssociationVerdict verdict) {
  int n = 0;
  for (const auto& a : r.associations) n += a.verdict == verdict;
  return n;
}

TEST_F(PipelineTest, ThePaperAnomalyFilterDropsANumberFarFromTheRecentOnes) {
  Pipeline pipeline(rig, map, PipelineOptions::paper());
  const auto r = withAFarMisreading(pipeline, Drive{});
  EXPECT_EQ(countVerdicts(r, AssociationVerdict::kAnomaly), 1);
}

TEST_F(PipelineTest, WhileTrackingThePoseGateDropsANumberFarFromTheRecentOnes) {
  Pipeline pipeline(rig, map);
  const auto r = withAFarMisreading(pipeline, Drive{});
  EXPECT_EQ(r.status, TrackingStatus::kOk);
  EXPECT_EQ(countVerdicts(r, AssociationVerdict::kAnomaly), 0);
  int misreadings = 0;
  for (const auto& a : r.associations)
    if (a.text == "B2-164") {
      ++misreadings;
      // The gate's verdicts: far from its landmark, or reading the wrong way round there.
      EXPECT_TRUE(a.verdict == AssociationVerdict::kGated ||
                  a.verdict == AssociationVerdict::kFlipped)
          << toString(a.verdict);
    }
  EXPECT_EQ(misreadings, 1);
}

TEST_F(PipelineTest, AFlippedReadingAmongOthersDoesNotTurnTheFirstFix) {
  Pipeline pipeline(rig, map);
  Drive drive;
  const auto r = pipeline.process(frame(drive, 0, [&](std::vector<CameraInput>& cameras) {
    auto* real = firstParkingNumber(cameras);
    ASSERT_NE(real, nullptr);
    real->polygon = {real->polygon[2], real->polygon[3], real->polygon[0], real->polygon[1]};
  }));
  ASSERT_TRUE(r.has_pose);
  EXPECT_LT(positionError(r, drive.truth(0.0)), 0.01);
  int outliers = 0;
  for (const auto& a : r.associations) outliers += a.verdict == AssociationVerdict::kSolverOutlier;
  EXPECT_EQ(outliers, 1);
}

// The fallback recognizer's matches (second opinions) once put a first fix 16.6 m off: they
// may confirm a tracked pose, never start one.
TEST_F(PipelineTest, SecondOpinionsStartNoFixButConfirmATrackedPose) {
  Pipeline pipeline(rig, map);
  Drive drive;
  const auto allSecondOpinions = [](std::vector<CameraInput>& cameras) {
    for (auto& c : cameras)
      for (auto& t : *c.instances) t.second_opinion = true;
  };
  const FrameResult searching = pipeline.process(frame(drive, 0, allSecondOpinions));
  EXPECT_FALSE(searching.has_pose);
  EXPECT_GT(countVerdicts(searching, AssociationVerdict::kUnconfirmed), 1);
  EXPECT_EQ(countVerdicts(searching, AssociationVerdict::kAccepted), 0);

  for (int k = 1; k < 20; ++k) pipeline.process(frame(drive, k));
  const FrameResult tracked = pipeline.process(frame(drive, 20, allSecondOpinions));
  ASSERT_EQ(tracked.status, TrackingStatus::kOk);
  EXPECT_EQ(countVerdicts(tracked, AssociationVerdict::kUnconfirmed), 0);
  EXPECT_GT(countVerdicts(tracked, AssociationVerdict::kAccepted), 1);
  EXPECT_LT(positionError(tracked, drive.truth(tracked.timestamp)), 0.02);
}

// A text read by the part the image shows (a cut number) has a polygon on that part only:
// its corners are not the landmark's, and nothing uses them.
TEST_F(PipelineTest, APartialReadingIsNotUsed) {
  Pipeline pipeline(rig, map);
  Drive drive;
  int marked = 0;
  const FrameResult r = pipeline.process(frame(drive, 0, [&](std::vector<CameraInput>& cameras) {
    auto* real = firstParkingNumber(cameras);
    ASSERT_NE(real, nullptr);
    real->partial = true;
    ++marked;
  }));
  ASSERT_EQ(marked, 1);
  ASSERT_TRUE(r.has_pose);
  EXPECT_EQ(countVerdicts(r, AssociationVerdict::kPartial), 1);
  EXPECT_LT(positionError(r, drive.truth(0.0)), 0.01);
}

TEST_F(PipelineTest, RecoversFromKidnappingWithinThreeSeconds) {
  Pipeline pipeline(rig, map);
  Drive drive;
  drive.jump_time = 4.0;
  drive.jump_m = 15.0;
  bool reinitialised = false;
  double recovered_at = -1.0;
  for (int k = 0; k < 100; ++k) {
    const auto r = pipeline.process(frame(drive, k));
    ASSERT_TRUE(r.has_pose);
    reinitialised = reinitialised || (r.reinitialised && r.timestamp >= drive.jump_time);
    const double e = positionError(r, drive.truth(r.timestamp));
    if (r.timestamp >= drive.jump_time && recovered_at < 0.0 && e < 0.05)
      recovered_at = r.timestamp;
    if (recovered_at >= 0.0) {
      EXPECT_LT(e, 0.05) << "at " << r.timestamp;
    }
  }
  EXPECT_TRUE(reinitialised);
  ASSERT_GE(recovered_at, 0.0);
  EXPECT_LE(recovered_at - drive.jump_time, 3.0);
}

TEST_F(PipelineTest, PaperModeGivesAPositionFromCentresAndHomography) {
  Pipeline pipeline(rig, map, PipelineOptions::paper());
  Drive drive;
  double sum = 0.0;
  int n = 0;
  for (int k = 0; k < 40; ++k) {
    const auto r = pipeline.process(frame(drive, k));
    ASSERT_TRUE(r.has_pose);
    sum += positionError(r, drive.truth(r.timestamp));
    ++n;
    for (const auto& a : r.associations) EXPECT_NE(a.verdict, AssociationVerdict::kGated);
  }
  // The centre of a distorted polygon is not the image of the text's centre: decimetres.
  EXPECT_LT(sum / n, 0.3);
}

// Per landmark whose observations the SE(2) solve used (it reports a residual for each),
// the cameras that saw it.
using Used = std::map<std::string, std::set<std::string>>;
Used usedBySolve(const FrameResult& r) {
  Used used;
  for (const auto& a : r.associations)
    if (a.residual_px >= 0.0) used[a.landmark_id].insert(a.camera);
  return used;
}

// What the default pipeline and one with `ablated` options used over the first 10 frames.
std::vector<std::pair<Used, Used>> usedWithAndWithout(const geometry::Rig& rig,
                                                      const map::HdMap& map,
                                                      const PipelineOptions& ablated,
                                                      const std::function<FrameInput(int)>& frame) {
  Pipeline with(rig, map), without(rig, map, ablated);
  std::vector<std::pair<Used, Used>> out;
  for (int k = 0; k < 10; ++k) {
    const FrameInput in = frame(k);
    out.emplace_back(usedBySolve(with.process(in)), usedBySolve(without.process(in)));
  }
  return out;
}

TEST_F(PipelineTest, WithoutMcapOnlyOneLandmarkIsUsed) {
  PipelineOptions ablated;
  ablated.paper_modules.mcap = false;
  size_t most_with = 0;
  for (const auto& [with, without] :
       usedWithAndWithout(rig, map, ablated, [&](int k) { return frame(Drive{}, k); })) {
    most_with = std::max(most_with, with.size());
    EXPECT_EQ(without.size(), 1u);
  }
  EXPECT_GT(most_with, 2u);
}

TEST_F(PipelineTest, WithoutMcrpEachLandmarkIsUsedFromOneCamera) {
  PipelineOptions ablated;
  ablated.paper_modules.mcrp = false;
  size_t most_cameras_with = 0;
  for (const auto& [with, without] :
       usedWithAndWithout(rig, map, ablated, [&](int k) { return frame(Drive{}, k); })) {
    for (const auto& [id, cameras] : with)
      most_cameras_with = std::max(most_cameras_with, cameras.size());
    for (const auto& [id, cameras] : without) EXPECT_EQ(cameras.size(), 1u) << id;
  }
  EXPECT_GT(most_cameras_with, 1u);  // with MCRP, some landmark is averaged over cameras
}

TEST_F(PipelineTest, WithoutAfmTheFarMisreadingReachesExactMatching) {
  PipelineOptions options = PipelineOptions::paper();
  options.paper_modules.afm = false;
  Pipeline pipeline(rig, map, options);
  const auto r = withAFarMisreading(pipeline, Drive{});
  EXPECT_EQ(countVerdicts(r, AssociationVerdict::kAnomaly), 0);
  int misreadings = 0;
  for (const auto& a : r.associations)
    if (a.text == "B2-164") {
      ++misreadings;
      EXPECT_EQ(a.verdict, AssociationVerdict::kAccepted);
    }
  EXPECT_EQ(misreadings, 1);
}

TEST_F(PipelineTest, WithoutMcapThePaperPositionRestsOnOneLandmark) {
  // The paper's nominal covariance shrinks with the landmarks averaged: 10 cm for one.
  PipelineOptions single = PipelineOptions::paper();
  single.paper_modules.mcap = false;
  Pipeline with(rig, map, PipelineOptions::paper()), without(rig, map, single);
  const auto in = frame(Drive{}, 10);
  const auto r_with = with.process(in), r_without = without.process(in);
  ASSERT_TRUE(r_with.measurement_covariance && r_without.measurement_covariance);
  EXPECT_DOUBLE_EQ((*r_without.measurement_covariance)(0, 0), 0.1 * 0.1);
  EXPECT_LT((*r_with.measurement_covariance)(0, 0), 0.5 * 0.1 * 0.1);
}

TEST_F(PipelineTest, BadInputIsReportedAndTheRestIsUsed) {
  Pipeline pipeline(rig, map);
  Drive drive;
  for (int k = 0; k < 5; ++k) pipeline.process(frame(drive, k));
  // A missing camera, a corrupt one (no image, no instances), an unknown camera and a NaN
  // odometry sample.
  auto in = frame(drive, 5);
  in.cameras.erase(in.cameras.begin());
  in.cameras.front().instances.reset();
  in.cameras.push_back(CameraInput{"roof", cv::Mat(), std::nullopt, std::nullopt});
  in.odometry.push_back({0.55, std::nan(""), 0.0});
  const auto r = pipeline.process(in);
  EXPECT_EQ(r.status, TrackingStatus::kOk);
  EXPECT_LT(positionError(r, drive.truth(r.timestamp)), 0.02);
  std::string all;
  for (const auto& w : r.warnings) all += w + "\n";
  EXPECT_NE(all.find("'front': no input"), std::string::npos) << all;
  EXPECT_NE(all.find("missing or corrupt"), std::string::npos) << all;
  EXPECT_NE(all.find("'roof' is not in the rig"), std::string::npos) << all;
  EXPECT_NE(all.find("not finite"), std::string::npos) << all;
  // A frame from the past: processed, reported, no prediction.
  const auto old = pipeline.process(frame(drive, 3));
  bool reported = false;
  for (const auto& w : old.warnings)
    reported = reported || w.find("not after") != std::string::npos;
  EXPECT_TRUE(reported);
  EXPECT_TRUE(old.has_pose);
}

// A spotter that sees exactly what the synthetic scene shows, inside the requested regions.
class SceneSpotter : public ocr::TextSpotter {
 public:
  SceneSpotter(const geometry::Rig& rig, const map::HdMap& map) : rig_(rig), map_(map) {}
  std::string name() const override { return "scene"; }
  std::vector<ocr::TextInstance> spot(const cv::Mat& image,
                                      const ocr::SpotRequest& request) override {
    requests.push_back(request);
    std::this_thread::sleep_for(delay);
    const auto& camera = rig_.cameras[static_cast<size_t>(image.at<cv::Vec3b>(0, 0)[0])];
    auto all = testing::spotExactly(camera, map_, pose, {});
    return testing::inRequestedRegions(all, request);
  }
  geometry::Pose2 pose;
  std::vector<ocr::SpotRequest> requests;
  std::chrono::milliseconds delay{0};  // time each call takes on top

 private:
  const geometry::Rig& rig_;
  const map::HdMap& map_;
};

TEST_F(PipelineTest, MapGuidedSpottingAsksForPredictedRegionsAndFullFramesNowAndThen) {
  SceneSpotter spotter(rig, map);
  PipelineOptions options;
  options.reading.full_frame_interval = 5;
  options.reading.max_regions_per_frame = 0;       // every predicted region (no budget)
  options.reading.full_frame_round_robin = false;  // all cameras on the same frame
  Pipeline pipeline(rig, map, options, &spotter);
  Drive drive;
  int guided_frames = 0, full_frames = 0;
  for (int k = 0; k < 20; ++k) {
    FrameInput in = frame(drive, k);
    for (size_t c = 0; c < in.cameras.size(); ++c) {
      in.cameras[c].instances.reset();
      in.cameras[c].image = cameraImage(c);
    }
    spotter.pose = drive.truth(in.timestamp);
    spotter.requests.clear();
    const auto r = pipeline.process(in);
    ASSERT_TRUE(r.has_pose);
    EXPECT_LT(positionError(r, spotter.pose), 0.01);
    if (r.cameras.front().full_frame) {
      ++full_frames;
      for (const auto& q : spotter.requests) EXPECT_TRUE(q.regions.empty());
    } else {
      ++guided_frames;
      int regions = 0;
      for (const auto& c : r.cameras) regions += c.regions;
      EXPECT_GT(regions, 3);
      for (const auto& q : spotter.requests)
        for (const auto& region : q.regions) EXPECT_EQ(region.expected_texts.size(), 1u);
    }
  }
  EXPECT_EQ(full_frames, 4);  // frames 0 (not initialised), 5, 10 and 15
  EXPECT_EQ(guided_frames, 16);
}

TEST_F(PipelineTest, AsksForSecondOpinionsOnFullFramesOnlyWhenTold) {
  for (const bool wanted : {false, true}) {
    SceneSpotter spotter(rig, map);
    PipelineOptions options;
    options.reading.second_opinions = wanted;
    Pipeline pipeline(rig, map, options, &spotter);
    FrameInput in = frame(Drive{}, 0);
    for (size_t c = 0; c < in.cameras.size(); ++c) {
      in.cameras[c].instances.reset();
      in.cameras[c].image = cameraImage(c);
    }
    pipeline.process(in);
    ASSERT_FALSE(spotter.requests.empty());
    for (const auto& q : spotter.requests) {
      ASSERT_TRUE(q.regions.empty());  // not initialised: full frames
      EXPECT_EQ(q.second_opinions, wanted);
    }
  }
}

double sumOfStages(const StageTimings& t) {
  return t.roi_ms + t.spotting_ms + t.association_ms + t.solver_ms + t.filter_ms;
}

TEST_F(PipelineTest, StageTimingsAddUpAndShowTheStagesThatRan) {
  // Instances that come with the frame: no spotter runs, and spotting takes no time.
  Pipeline oracle(rig, map);
  const Drive drive;
  for (int k = 0; k < 5; ++k) {
    const auto r = oracle.process(frame(drive, k));
    ASSERT_EQ(r.status, TrackingStatus::kOk);
    EXPECT_EQ(r.timings.spotting_ms, 0.0);
    EXPECT_GT(r.timings.association_ms, 0.0);
    EXPECT_GT(r.timings.solver_ms, 0.0);
    EXPECT_GT(r.timings.filter_ms, 0.0);
    EXPECT_GE(r.timings.total_ms, sumOfStages(r.timings));
  }
  // A spotter that takes 5 ms a call: its time is spotting time, inside the total.
  SceneSpotter spotter(rig, map);
  spotter.delay = std::chrono::milliseconds(5);
  Pipeline spotted(rig, map, {}, &spotter);
  FrameInput in = frame(drive, 0);
  for (size_t c = 0; c < in.cameras.size(); ++c) {
    in.cameras[c].instances.reset();
    in.cameras[c].image = cameraImage(c);
  }
  spotter.pose = drive.truth(in.timestamp);
  const auto r = spotted.process(in);
  ASSERT_FALSE(spotter.requests.empty());
  EXPECT_GE(r.timings.spotting_ms, 5.0 * static_cast<double>(spotter.requests.size()));
  EXPECT_GE(r.timings.total_ms, sumOfStages(r.timings));
}

TEST_F(PipelineTest, AnImageWhoseSizeIsNotItsCalibrationsIsSkippedWithAWarning) {
  // A resized recording or another camera's image: that camera is skipped (the spotter never
  // sees it), the others are read.
  SceneSpotter spotter(rig, map);
  Pipeline pipeline(rig, map, {}, &spotter);
  Drive drive;
  FrameInput in = frame(drive, 0);
  for (size_t c = 0; c < in.cameras.size(); ++c) {
    in.cameras[c].instances.reset();
    in.cameras[c].image = cameraImage(c);
  }
  cv::resize(in.cameras[0].image, in.cameras[0].image, {}, 0.5, 0.5);
  spotter.pose = drive.truth(in.timestamp);
  const auto r = pipeline.process(in);
  ASSERT_EQ(r.cameras.size(), rig.cameras.size());
  EXPECT_FALSE(r.cameras[0].image_ok);
  for (size_t c = 1; c < r.cameras.size(); ++c) EXPECT_TRUE(r.cameras[c].image_ok);
  for (const auto& request : spotter.requests) EXPECT_NE(request.camera, &rig.cameras[0]);
  std::string all;
  for (const auto& w : r.warnings) all += w + "\n";
  const auto& model = rig.cameras[0].model;
  EXPECT_NE(all.find(fmt::format("'{}': image is {}x{} but its calibration is {}x{}",
                                 rig.cameras[0].name, model.width / 2, model.height / 2,
                                 model.width, model.height)),
            std::string::npos)
      << all;
}

TEST_F(PipelineTest, CamerasCapturedOffTheFrameSetsTimeAreMovedToIt) {
  // The rear and left cameras capture 40 ms and 25 ms after the frame set's time (at 2 m/s:
  // 8 and 5 cm further on). Told so, the pipeline places the vehicle at the frame set's time;
  // not told, it lands between the capture times.
  const std::map<std::string, double> late{{"rear", 0.040}, {"left", 0.025}};
  Drive drive;
  const auto run = [&](bool told) {
    Pipeline pipeline(rig, map);
    double sum = 0.0;
    int frames = 0;
    for (int k = 0; k < 40; ++k) {
      FrameInput in = frame(drive, k);
      for (CameraInput& c : in.cameras) {
        const auto offset = late.find(c.camera);
        if (offset == late.end()) continue;
        const double t = in.timestamp + offset->second;
        c.instances = testing::spotExactly(*rig.find(c.camera), map, drive.truth(t), spot, &rng);
        if (told) c.capture_time = t;
      }
      const FrameResult r = pipeline.process(in);
      if (k < 5 || !r.has_pose) continue;
      sum += positionError(r, drive.truth(in.timestamp));
      ++frames;
    }
    EXPECT_GT(frames, 30);
    return sum / std::max(frames, 1);
  };
  const double told = run(true), not_told = run(false);
  EXPECT_LT(told, 0.005);
  EXPECT_GT(not_told, 2.0 * told);
  EXPECT_EQ(Pipeline(rig, map).rig().cameras[1].vehicle_from_camera.matrix(),
            rig.cameras[1].vehicle_from_camera.matrix());
}

// A spotter that sees exactly what the synthetic drive shows, the frame set and the camera
// told by the image (channel 0: the camera, channel 1: the frame set): it keeps no state, so
// the critical path and the search worker may each have one. `gate`, when set, holds every
// full-frame call until it is opened (or 20 s pass, which `timed_out` records).
class DriveSpotter : public ocr::TextSpotter {
 public:
  DriveSpotter(const geometry::Rig& rig, const map::HdMap& map, const Drive& drive)
      : rig_(rig), map_(map), drive_(drive) {}
  std::string name() const override { return "drive"; }
  std::vector<ocr::TextInstance> spot(const cv::Mat& image,
                                      const ocr::SpotRequest& request) override {
    if (request.regions.empty()) ++full_frames;
    for (const auto& region : request.regions) reads += region.read;
    if (request.regions.empty() && gate) {
      if (gate->wait_for(std::chrono::seconds(20)) != std::future_status::ready) timed_out = true;
    }
    if (request.regions.empty()) std::this_thread::sleep_for(full_frame_delay);
    const cv::Vec3b tag = image.at<cv::Vec3b>(0, 0);
    const auto& camera = rig_.cameras[tag[0]];
    auto all = testing::spotExactly(camera, map_, drive_.truth(tag[1] / kFrameRate), {});
    return testing::inRequestedRegions(all, request);
  }
  std::optional<std::shared_future<void>> gate;
  std::chrono::milliseconds full_frame_delay{0};  // a full frame takes at least this long
  std::atomic<bool> timed_out{false};
  std::atomic<int> full_frames{0};
  std::atomic<int> reads{0};  // regions asked to be read, not only fitted

 private:
  const geometry::Rig& rig_;
  const map::HdMap& map_;
  const Drive& drive_;
};

// Frame k of the drive as images that DriveSpotter reads.
FrameInput driveImages(const geometry::Rig& rig, int k, const FrameInput& oracle) {
  FrameInput in = oracle;
  for (size_t c = 0; c < in.cameras.size(); ++c) {
    in.cameras[c].instances.reset();
    const auto& model = rig.cameras[c].model;
    in.cameras[c].image = cv::Mat(model.height, model.width, CV_8UC3,
                                  cv::Scalar(static_cast<double>(c), static_cast<double>(k), 0));
  }
  return in;
}

TEST_F(PipelineTest, ASlowSearchWorkerDelaysNoFrameSet) {
  // The worker's spotter is stuck on its full frame until the test lets it go. Were process()
  // to wait for it, the frame sets below would not come back before the gate's 20 s ran out.
  Drive drive;
  DriveSpotter critical(rig, map, drive), worker(rig, map, drive);
  std::promise<void> open;
  worker.gate = open.get_future().share();
  PipelineOptions options;
  options.initial_pose = drive.truth(0.0);
  options.reading.full_frame_interval = 4;  // a sweep every frame set, one camera in turn
  options.realtime.background_search = true;
  options.realtime.wait_for_worker = false;
  Pipeline pipeline(rig, map, options, &critical, {&worker, nullptr});
  int handed_over = 0;
  for (int k = 0; k < 12; ++k) {
    const FrameResult r = pipeline.process(driveImages(rig, k, frame(drive, k)));
    ASSERT_TRUE(r.has_pose) << k;
    EXPECT_LT(positionError(r, drive.truth(k / kFrameRate)), 0.01) << k;
    EXPECT_FALSE(r.background.has_value()) << k;  // the worker has not finished
    handed_over += static_cast<int>(r.background_cameras.size());
    for (const auto& c : r.cameras) EXPECT_FALSE(c.full_frame);
  }
  EXPECT_EQ(handed_over, 1);  // one job at a time: the sweeps due meanwhile were skipped
  EXPECT_EQ(critical.full_frames, 0);
  EXPECT_EQ(worker.full_frames, 1);  // the worker holds the first sweep
  open.set_value();
  // Let go, the worker's texts are fused in a frame set soon after.
  std::optional<BackgroundFusion> fused;
  for (int k = 12; k < 200 && !fused; ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    const FrameResult r = pipeline.process(driveImages(rig, k, frame(drive, k)));
    ASSERT_TRUE(r.has_pose);
    EXPECT_LT(positionError(r, drive.truth(k / kFrameRate)), 0.01) << k;
    fused = r.background;
  }
  ASSERT_TRUE(fused.has_value());
  EXPECT_FALSE(worker.timed_out);
  EXPECT_NEAR(fused->capture_timestamp, 0.0, 0.15);  // the first sweep's frame set
  ASSERT_TRUE(fused->measurement.has_value());
  // The fix is where the vehicle was when the images were taken, not where it is now.
  EXPECT_LT((fused->measurement->translation() -
             drive.truth(fused->capture_timestamp).translation()).norm(),
            0.01);
}

TEST_F(PipelineTest, BeforeTheFirstFixAFrameSetWaitsForTheSearchInHand) {
  // Live, the worker spots frame set 0's full frame for a second while frame set 1 comes at
  // once. Allowed to wait for it (first_fix_wait_ms), frame set 1 fuses its texts and has the
  // first pose; not allowed, it returns without one.
  Drive drive;
  const auto second_frame_set = [&](double wait_ms) {
    DriveSpotter critical(rig, map, drive), worker(rig, map, drive);
    worker.full_frame_delay = std::chrono::milliseconds(1000);
    PipelineOptions options;
    options.realtime.background_search = true;
    options.realtime.wait_for_worker = false;
    options.realtime.first_fix_wait_ms = wait_ms;
    Pipeline pipeline(rig, map, options, &critical, {&worker, nullptr});
    const FrameResult first = pipeline.process(driveImages(rig, 0, frame(drive, 0)));
    EXPECT_FALSE(first.has_pose);
    EXPECT_EQ(first.background_cameras.size(), 1u);
    return pipeline.process(driveImages(rig, 1, frame(drive, 1)));
  };
  const FrameResult waited = second_frame_set(20000.0);
  ASSERT_TRUE(waited.has_pose);
  ASSERT_TRUE(waited.background.has_value());
  EXPECT_NEAR(waited.background->capture_timestamp, 0.0, 1e-9);
  EXPECT_LT(positionError(waited, drive.truth(1 / kFrameRate)), 0.01);
  const FrameResult not_waited = second_frame_set(0.0);
  EXPECT_FALSE(not_waited.has_pose);
  EXPECT_FALSE(not_waited.background.has_value());
}

TEST_F(PipelineTest, WaitingForTheSearchWorkerGivesTheSamePosesEveryRun) {
  // Offline, the worker's texts are fused a fixed number of frame sets after their images,
  // and two runs give the same poses to the last bit.
  Drive drive;
  const auto run = [&](bool background) {
    DriveSpotter critical(rig, map, drive), worker(rig, map, drive);
    PipelineOptions options;
    options.realtime.background_search = background;
    Pipeline pipeline(rig, map, options, &critical, {&worker, nullptr});
    std::vector<FrameResult> out;
    for (int k = 0; k < 40; ++k) out.push_back(pipeline.process(driveImages(rig, k, frame(drive, k))));
    return out;
  };
  const auto inside = run(false), first = run(true), second = run(true);
  int first_inside = -1, first_background = -1;
  for (int k = 0; k < 40; ++k) {
    if (first_inside < 0 && inside[k].has_pose) first_inside = k;
    if (first_background < 0 && first[k].has_pose) first_background = k;
    ASSERT_EQ(first[k].has_pose, second[k].has_pose);
    if (!first[k].has_pose) continue;
    EXPECT_EQ(first[k].pose.x, second[k].pose.x);
    EXPECT_EQ(first[k].pose.yaw, second[k].pose.yaw);
    EXPECT_LT(positionError(first[k], drive.truth(k / kFrameRate)), 0.01) << k;
  }
  // The first fix (from frame set 0's search) starts the track one frame set later.
  EXPECT_EQ(first_inside, 0);
  EXPECT_EQ(first_background, 1);
  int fused = 0;
  for (int k = 1; k < 40; ++k) {
    if (!first[k].background) continue;
    ++fused;
    EXPECT_NEAR(first[k].background->capture_timestamp, (k - 1) / kFrameRate, 1e-9) << k;
    EXPECT_EQ(first[k].status, TrackingStatus::kOk) << k;
  }
  EXPECT_GT(fused, 0);
}

TEST_F(PipelineTest, ReadsOnTheirWorkerLeaveTheFrameSetOnlyFits) {
  // With background_reads, every read at a predicted place goes to the read worker and comes
  // back a frame set later; the critical path only fits texts it read lately. The poses stay
  // as exact, and two runs give the same poses (wait_for_worker).
  Drive drive;
  const auto run = [&](std::vector<FrameResult>& out) {
    DriveSpotter critical(rig, map, drive), search(rig, map, drive), reads(rig, map, drive);
    PipelineOptions options;
    options.realtime.background_search = true;
    options.realtime.background_reads = true;
    Pipeline pipeline(rig, map, options, &critical, {&search, &reads});
    for (int k = 0; k < 40; ++k) out.push_back(pipeline.process(driveImages(rig, k, frame(drive, k))));
    EXPECT_EQ(critical.reads, 0);
    EXPECT_GT(search.full_frames, 0);
    return reads.reads.load();
  };
  std::vector<FrameResult> first, second;
  EXPECT_GT(run(first), 5);
  run(second);
  int fused = 0, deferred = 0;
  for (int k = 0; k < 40; ++k) {
    ASSERT_EQ(first[k].has_pose, second[k].has_pose) << k;
    if (!first[k].has_pose) continue;
    EXPECT_EQ(first[k].pose.x, second[k].pose.x) << k;
    EXPECT_LT(positionError(first[k], drive.truth(k / kFrameRate)), 0.01) << k;
    deferred += static_cast<int>(first[k].deferred_read_cameras.size());
    if (!first[k].deferred_reads) continue;
    ++fused;
    // Fused one frame set after the images it read.
    EXPECT_NEAR(first[k].deferred_reads->capture_timestamp, (k - 1) / kFrameRate, 1e-9) << k;
  }
  EXPECT_GT(deferred, 5);
  EXPECT_GT(fused, 5);
  EXPECT_TRUE(first[1].has_pose);
}

TEST_F(PipelineTest, BeforeTheFirstFixBothWorkersSearchThenTheReadWorkerReads) {
  // With no track to read for, the read worker searches beside the search worker: two
  // cameras' full frames per frame set instead of one. Once tracking, it takes only reads.
  Drive drive;
  DriveSpotter critical(rig, map, drive), search(rig, map, drive), reads(rig, map, drive);
  PipelineOptions options;
  options.realtime.background_search = true;
  options.realtime.background_reads = true;
  Pipeline pipeline(rig, map, options, &critical, {&search, &reads});
  std::vector<FrameResult> results;
  std::vector<int> read_worker_full_frames;  // after each frame set
  for (int k = 0; k < 30; ++k) {
    results.push_back(pipeline.process(driveImages(rig, k, frame(drive, k))));
    read_worker_full_frames.push_back(reads.full_frames);
  }
  EXPECT_EQ(critical.full_frames, 0);
  EXPECT_GT(search.full_frames, 0);
  ASSERT_EQ(results[0].background_cameras.size(), 2u);
  EXPECT_NE(results[0].background_cameras[0], results[0].background_cameras[1]);
  EXPECT_GT(read_worker_full_frames[1], 0);  // frame set 1 waited for both workers
  std::optional<int> first_tracked;
  for (int k = 0; k < 30; ++k) {
    if (!results[k].has_pose) continue;
    EXPECT_LT(positionError(results[k], drive.truth(k / kFrameRate)), 0.01) << k;
    if (results[k].status != TrackingStatus::kOk) continue;
    if (!first_tracked) first_tracked = k;
    // A tracked frame set hands over at most one sweep camera, to the search worker, and the
    // read worker reads.
    EXPECT_LE(results[k].background_cameras.size(), 1u) << k;
    EXPECT_EQ(read_worker_full_frames[k], read_worker_full_frames[*first_tracked]) << k;
  }
  ASSERT_TRUE(first_tracked);
  EXPECT_GT(reads.reads, 0);
  EXPECT_TRUE(results[1].has_pose);  // the texts of frame set 0's two cameras, fused in 1
}

// Counts the full frames it is given, and the cameras they were for.
class CountingSpotter : public ocr::TextSpotter {
 public:
  std::string name() const override { return "counting"; }
  std::vector<ocr::TextInstance> spot(const cv::Mat& image,
                                      const ocr::SpotRequest& request) override {
    if (request.regions.empty() && request.camera && image.cols == request.camera->model.width)
      ++full_frames;
    return {};
  }
  std::atomic<int> full_frames{0};
};

TEST_F(PipelineTest, WarmingUpSpotsEveryCameraOnEverySpotterBeforeTheFirstFrameSet) {
  CountingSpotter critical, search, reads, cold;
  PipelineOptions options;
  options.realtime.background_search = true;
  options.realtime.background_reads = true;
  options.realtime.warm_up = true;
  {
    Pipeline pipeline(rig, map, options, &critical, {&search, &reads});
    const int cameras = static_cast<int>(rig.cameras.size());
    EXPECT_EQ(critical.full_frames, cameras);
    EXPECT_EQ(search.full_frames, cameras);
    EXPECT_EQ(reads.full_frames, cameras);
  }
  options.realtime.warm_up = false;
  Pipeline pipeline(rig, map, options, &cold);
  EXPECT_EQ(cold.full_frames, 0);
}

TEST(CaptureTime, TheVehicleMovesAlongAnArc) {
  OdometrySample motion;
  motion.speed = 2.0;
  motion.yaw_rate = 0.5;
  const geometry::Rigid3 T = vehicleMotionOver(motion, 0.1);
  // 0.2 m of arc turning 0.05 rad: the chord is 0.2 m long (to 1e-4) along half the turn.
  EXPECT_NEAR(T.translation().norm(), 0.2, 1e-4);
  EXPECT_NEAR(std::atan2(T.translation().y(), T.translation().x()), 0.025, 1e-9);
  EXPECT_NEAR(std::atan2(T.linear()(1, 0), T.linear()(0, 0)), 0.05, 1e-12);
  EXPECT_TRUE(vehicleMotionOver(motion, 0.0).isApprox(geometry::Rigid3::Identity()));
}

}  // namespace
}  // namespace parkloc::localize
