#include "mapping/map_problem.h"

#include <gtest/gtest.h>

#include <random>

#include "common/error.h"
#include "mapping/corner_factor.h"
#include "mapping/map_builder.h"
#include "synthetic_survey.h"

namespace parkloc::mapping {
namespace {

using testing::biasedOdometry;
using testing::makeSurvey;

TEST(CornerFactor, JacobiansMatchCentralDifferences) {
  const geometry::Rig rig = geometry::defaultRig();
  const double pose[3] = {0.3, -0.2, 0.1};
  const double landmark[5] = {3.0, 2.8, 2.5, 0.9, 0.45};
  const double margin[1] = {1.5};
  // A sighting's quad, turned: the margin's directions come from it.
  const std::array<Eigen::Vector2d, 4> quad = {
      Eigen::Vector2d(600, 400), {660, 390}, {664, 420}, {604, 431}};
  const int sizes[3] = {3, 5, 1};
  for (size_t c = 0; c < rig.cameras.size(); ++c) {
    for (int k = 0; k < 4; ++k) {
      const CornerFactor factor(rig.cameras[c], k, quad, 1.5);
      const double* params[3] = {pose, landmark, margin};
      double r[2], J_pose[6], J_landmark[10], J_margin[2];
      double* jacobians[3] = {J_pose, J_landmark, J_margin};
      double* analytic[3] = {J_pose, J_landmark, J_margin};
      if (!factor.Evaluate(params, r, jacobians)) continue;  // not seen by this camera
      for (int block = 0; block < 3; ++block) {
        const int n = sizes[block];
        for (int i = 0; i < n; ++i) {
          double plus[5], minus[5];
          std::copy(params[block], params[block] + n, plus);
          std::copy(params[block], params[block] + n, minus);
          const double h = 1e-6;
          plus[i] += h;
          minus[i] -= h;
          double rp[2], rm[2];
          const double* pp[3] = {pose, landmark, margin};
          const double* pm[3] = {pose, landmark, margin};
          pp[block] = plus;
          pm[block] = minus;
          ASSERT_TRUE(factor.Evaluate(pp, rp, nullptr));
          ASSERT_TRUE(factor.Evaluate(pm, rm, nullptr));
          for (int row = 0; row < 2; ++row) {
            const double numeric = (rp[row] - rm[row]) / (2 * h);
            EXPECT_NEAR(analytic[block][row * n + i], numeric,
                        1e-4 * std::max(1.0, std::fabs(numeric)))
                << "camera " << c << " corner " << k << " block " << block << " param " << i;
          }
        }
      }
    }
  }
}

// The largest error of the built landmarks against the truth: position (m), heading (rad),
// size (m).
struct WorstError {
  double position = 0.0, heading = 0.0, size = 0.0;
};

WorstError worstError(const MapBuild& build, const testing::SyntheticSurvey& survey) {
  WorstError w;
  for (const LandmarkEstimate& l : build.landmarks)
    for (const auto& t : survey.truth) {
      if (t.text != l.text) continue;
      w.position = std::max(w.position, std::hypot(l.parameters[kX] - t.parameters[kX],
                                                   l.parameters[kY] - t.parameters[kY]));
      w.heading =
          std::max(w.heading,
                   std::fabs(geometry::wrapAngle(l.parameters[kHeading] - t.parameters[kHeading])));
      w.size = std::max({w.size, std::fabs(l.parameters[kWidth] - t.parameters[kWidth]),
                         std::fabs(l.parameters[kHeight] - t.parameters[kHeight])});
    }
  return w;
}

TEST(MapProblem, RecoversKnownLandmarksToTheMillimetre) {
  const auto survey = makeSurvey();
  ASSERT_GT(survey.sightings.size(), 100u);
  // Odometry as the simulator's: 0.5 % long, its yaw rate biased by 0.1 degrees a second.
  const SurveyPoses odometry = biasedOdometry(survey.poses, 1.005, 0.01 * M_PI / 180.0);
  const MapBuild build = estimateMap({&survey.rig}, {odometry}, survey.sightings, {});
  ASSERT_EQ(build.landmarks.size(), survey.truth.size());
  EXPECT_TRUE(build.estimation.converged) << build.estimation.message;
  const WorstError w = worstError(build, survey);
  EXPECT_LT(w.position, 1e-3);
  EXPECT_LT(w.heading, 1e-3);
  EXPECT_LT(w.size, 1e-3);
  for (const LandmarkEstimate& l : build.landmarks) {
    EXPECT_LT(l.rms_px, 0.05) << l.text;
    ASSERT_TRUE(l.position_sigma) << l.text;
    EXPECT_GT(*l.position_sigma, 0.0);
    EXPECT_LT(*l.position_sigma, 0.05);
  }
  EXPECT_TRUE(build.problems.empty());
}

// The corners of every sighting (of every `every`-th) moved outward from its text by `px`
// pixels along the text's width and height, as an ink fit's threshold on blurred paint does.
void growCorners(std::vector<Sighting>& sightings, double px, size_t every = 1) {
  for (size_t i = 0; i < sightings.size(); i += every) {
    Sighting& s = sightings[i];
    const auto q = s.pixels;
    const Eigen::Vector2d along = (q[1] - q[0] + q[2] - q[3]).normalized();
    const Eigen::Vector2d down = (q[3] - q[0] + q[2] - q[1]).normalized();
    s.pixels[0] += px * (-along - down);
    s.pixels[1] += px * (along - down);
    s.pixels[2] += px * (along + down);
    s.pixels[3] += px * (-along + down);
  }
}

TEST(MapProblem, LearnsTheCornerMarginInsteadOfGrowingTheTexts) {
  auto survey = makeSurvey();
  growCorners(survey.sightings, 1.5);
  // Every third sighting a detector's box without an ink fit, 2.5 pixels wider still.
  growCorners(survey.sightings, 2.5, 3);
  for (size_t i = 0; i < survey.sightings.size(); i += 3) survey.sightings[i].box_only = true;
  const SurveyPoses odometry = biasedOdometry(survey.poses, 1.0, 0.0);
  const MapBuild build = estimateMap({&survey.rig}, {odometry}, survey.sightings, {});
  ASSERT_EQ(build.landmarks.size(), survey.truth.size());
  EXPECT_NEAR(build.drives[0].fitted_margin_px, 1.5, 0.05);
  EXPECT_NEAR(build.drives[0].unfitted_margin_px, 4.0, 0.1);
  EXPECT_LT(worstError(build, survey).size, 0.005);
  // Taken as the glyphs' own corners, the same sightings make every text larger.
  MapBuildOptions no_margin;
  no_margin.estimation.estimate_corner_margin = false;
  const MapBuild grown = estimateMap({&survey.rig}, {odometry}, survey.sightings, no_margin);
  EXPECT_EQ(grown.drives[0].fitted_margin_px, 0.0);
  EXPECT_GT(worstError(grown, survey).size, 0.02);
  for (const LandmarkEstimate& l : grown.landmarks)
    EXPECT_GT(l.parameters[kHeight], 0.45) << l.text;
}

TEST(MapProblem, SaysWhenTheOdometryDisagreesWithTheCameras) {
  const auto survey = makeSurvey();
  // A wheel radius 20 % off.
  const SurveyPoses odometry = biasedOdometry(survey.poses, 1.2, 0.0);
  const MapBuild build = estimateMap({&survey.rig}, {odometry}, survey.sightings, {});
  bool told = false;
  for (const std::string& p : build.problems) told |= p.find("odometry") != std::string::npos;
  EXPECT_TRUE(told);
  // The cameras win: the landmarks stay within centimetres all the same.
  EXPECT_LT(worstError(build, survey).position, 0.03);
}

TEST(MapProblem, LearnsTheOdometrysDistanceScaleAndGyroBias) {
  const auto survey = makeSurvey();
  // Wheels 3 % long, the gyro biased by 0.5 degrees a second (0.05 degrees per 0.1 s step).
  const double bias_per_step = 0.05 * M_PI / 180.0;
  const SurveyPoses odometry = biasedOdometry(survey.poses, 1.03, bias_per_step);
  // The made-up drive is 10 m long: the calibration is asked for over any distance.
  MapBuildOptions calibrated;
  calibrated.estimation.calibration_min_distance_m = 0.0;
  const MapBuild build = estimateMap({&survey.rig}, {odometry}, survey.sightings, calibrated);
  ASSERT_EQ(build.drives.size(), 1u);
  // True distance over measured, less 1: 1 / 1.03 - 1.
  EXPECT_NEAR(build.drives[0].distance_scale, 1.0 / 1.03 - 1.0, 1e-3);
  EXPECT_NEAR(build.drives[0].yaw_rate_bias, bias_per_step / 0.1, 1e-3);
  EXPECT_LT(worstError(build, survey).position, 1e-4);

  // Taken as measured, the same odometry bends and stretches the drive, and the landmarks with
  // it, as far as the corner noise lets the odometry's sigmas give.
  MapBuildOptions as_measured;
  as_measured.estimation.estimate_odometry_calibration = false;
  const MapBuild measured = estimateMap({&survey.rig}, {odometry}, survey.sightings, as_measured);
  EXPECT_EQ(measured.drives[0].distance_scale, 0.0);
  EXPECT_GT(worstError(measured, survey).position, 10.0 * worstError(build, survey).position);
  // By default a drive this short keeps its odometry as measured.
  const MapBuild short_drive = estimateMap({&survey.rig}, {odometry}, survey.sightings, {});
  EXPECT_EQ(short_drive.drives[0].distance_scale, 0.0);
  EXPECT_EQ(short_drive.drives[0].yaw_rate_bias, 0.0);
}

TEST(MapProblem, RefusesASigmaThatIsNotPositive) {
  const auto survey = makeSurvey();
  const SurveyPoses odometry = biasedOdometry(survey.poses, 1.0, 0.0);
  MapBuildOptions options;
  options.estimation.yaw_rate_bias_prior_sigma = 0.0;
  try {
    estimateMap({&survey.rig}, {odometry}, survey.sightings, options);
    FAIL() << "a zero prior sigma was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("yaw_rate_bias_prior_sigma must be positive"),
              std::string::npos)
        << e.what();
  }
  options = {};
  options.estimation.pixel_sigma = -1.0;
  EXPECT_THROW(estimateMap({&survey.rig}, {odometry}, survey.sightings, options), InputError);
}

// A sighting whose corners do not project into its camera where the estimation starts (here a
// landmark's sighting given to the camera facing the other way) is left out, not the solve.
TEST(MapProblem, ACornerBehindItsCameraIsLeftOutAndTheRestSolves) {
  const auto survey = makeSurvey();
  const SurveyPoses odometry = biasedOdometry(survey.poses, 1.0, 0.0);
  const MapBuild build = estimateMap({&survey.rig}, {odometry}, survey.sightings, {});
  ASSERT_FALSE(build.consensus.tracks.empty());
  std::vector<Sighting> sightings = survey.sightings;
  std::vector<TextTrack> tracks = build.consensus.tracks;
  Sighting away = sightings[tracks[0].sightings.front()];
  // The camera whose optical axis points most nearly opposite the sighting's own.
  const auto axis = [&](int c) {
    return survey.rig.cameras[static_cast<size_t>(c)].vehicle_from_camera.rotation().col(2);
  };
  int opposite = away.camera;
  for (int c = 0; c < static_cast<int>(survey.rig.cameras.size()); ++c)
    if (axis(c).dot(axis(away.camera)) < axis(opposite).dot(axis(away.camera))) opposite = c;
  ASSERT_NE(away.camera, opposite);
  away.camera = opposite;
  sightings.push_back(away);
  tracks[0].sightings.push_back(sightings.size() - 1);

  std::vector<DriveState> drives(1);
  drives[0].rig = &survey.rig;
  for (const geometry::Pose2& p : odometry.map_from_vehicle)
    drives[0].poses.push_back({p.x, p.y, p.yaw});
  drives[0].motion = odometry.motion;
  for (size_t i = 0; i + 1 < odometry.timestamps.size(); ++i)
    drives[0].seconds.push_back(odometry.timestamps[i + 1] - odometry.timestamps[i]);
  std::vector<LandmarkEstimate> landmarks = build.landmarks;
  MapProblem problem(drives, landmarks, sightings, tracks, {});
  const EstimationSummary summary = problem.solve();
  EXPECT_TRUE(summary.converged) << summary.message;
  EXPECT_GT(summary.unprojected_corners, 0);
  EXPECT_LE(summary.unprojected_corners, 4);
  for (const LandmarkEstimate& l : landmarks)
    for (const auto& t : survey.truth)
      if (t.text == l.text)
        EXPECT_LT(
            std::hypot(l.parameters[kX] - t.parameters[kX], l.parameters[kY] - t.parameters[kY]),
            1e-3)
            << l.text;
}

TEST(MapProblem, RobustLossKeepsAMisplacedCornerFromMovingTheLandmark) {
  auto survey = makeSurvey();
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, 0.5);
  for (auto& s : survey.sightings)
    for (auto& p : s.pixels) p += Eigen::Vector2d(noise(rng), noise(rng));
  // One corner in ten lands on something else, 25 pixels away.
  for (size_t i = 0; i < survey.sightings.size(); i += 10)
    survey.sightings[i].pixels[i % 4] += Eigen::Vector2d(25.0, -15.0);
  const SurveyPoses odometry = biasedOdometry(survey.poses, 1.0, 0.0);
  const MapBuild build = estimateMap({&survey.rig}, {odometry}, survey.sightings, {});
  ASSERT_EQ(build.landmarks.size(), survey.truth.size());
  int outliers = 0;
  for (const LandmarkEstimate& l : build.landmarks) {
    for (const auto& t : survey.truth)
      if (t.text == l.text) {
        EXPECT_LT(
            std::hypot(l.parameters[kX] - t.parameters[kX], l.parameters[kY] - t.parameters[kY]),
            0.01)
            << l.text;
        EXPECT_NEAR(l.parameters[kWidth], t.parameters[kWidth], 0.01) << l.text;
      }
    outliers += l.outlier_corners;
  }
  EXPECT_GT(outliers, 0);
}

}  // namespace
}  // namespace parkloc::mapping
