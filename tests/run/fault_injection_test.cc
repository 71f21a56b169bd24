#include "run/fault_injection.h"

#include <gtest/gtest.h>

#include "common/error.h"

namespace parkloc::run {
namespace {

ocr::TextInstance instance(const std::string& text) {
  ocr::TextInstance t;
  t.text = text;
  t.raw_text = text;
  return t;
}

// A frame set of two cameras with a grey image and one oracle instance each, and five
// odometry samples in the 0.1 s before `t`.
localize::FrameInput frame(double t, const std::string& text = "B1-112") {
  localize::FrameInput f;
  f.timestamp = t;
  for (const char* name : {"front", "rear"}) {
    localize::CameraInput c;
    c.camera = name;
    c.image = cv::Mat(40, 60, CV_8UC3, cv::Scalar(100, 120, 140));
    c.instances = std::vector<ocr::TextInstance>{instance(text)};
    f.cameras.push_back(c);
  }
  for (int i = 0; i < 5; ++i) f.odometry.push_back({t - 0.08 + 0.02 * i, 2.0, 0.1});
  return f;
}

FaultInjector injector(const std::string& spec, size_t frames = 20) {
  std::vector<double> timestamps;
  for (size_t i = 0; i < frames; ++i) timestamps.push_back(0.1 * static_cast<double>(i));
  return FaultInjector(parseFaults(spec), timestamps, {}, {});
}

bool hasWarning(const std::vector<std::string>& warnings, const std::string& part) {
  for (const auto& w : warnings)
    if (w.find(part) != std::string::npos) return true;
  return false;
}

TEST(FaultSpec, ParsesEveryKind) {
  const auto f = parseFaults(
      "dark:front:3-8,freeze:left:3-8.5,missing:rear,drop:0.1,corrupt:0.05,odo-dropout:4-7,"
      "yaw-bias:0.02,spoof:B1-105@B1-112,kidnap:6,kidnap:9:15,seed:3");
  ASSERT_EQ(f.dark.size(), 1u);
  EXPECT_EQ(f.dark[0].camera, "front");
  EXPECT_DOUBLE_EQ(f.dark[0].range.begin, 3.0);
  EXPECT_DOUBLE_EQ(f.dark[0].range.end, 8.0);
  ASSERT_EQ(f.frozen.size(), 1u);
  EXPECT_DOUBLE_EQ(f.frozen[0].range.end, 8.5);
  EXPECT_EQ(f.missing_cameras, std::vector<std::string>{"rear"});
  EXPECT_DOUBLE_EQ(f.drop_probability, 0.1);
  EXPECT_DOUBLE_EQ(f.corrupt_probability, 0.05);
  ASSERT_EQ(f.odometry_dropouts.size(), 1u);
  EXPECT_DOUBLE_EQ(f.odometry_dropouts[0].begin, 4.0);
  EXPECT_DOUBLE_EQ(f.yaw_rate_bias, 0.02);
  ASSERT_EQ(f.spoofs.size(), 1u);
  EXPECT_EQ(f.spoofs[0].fake, "B1-105");
  EXPECT_EQ(f.spoofs[0].real, "B1-112");
  ASSERT_EQ(f.kidnaps.size(), 2u);
  EXPECT_DOUBLE_EQ(f.kidnaps[0].distance_m, 20.0);
  EXPECT_DOUBLE_EQ(f.kidnaps[1].distance_m, 15.0);
  EXPECT_EQ(f.seed, 3u);
  EXPECT_FALSE(f.empty());
  EXPECT_TRUE(InputFaults{}.empty());
}

TEST(FaultSpec, RepeatedSpecsMerge) {
  const auto f = parseFaults(std::vector<std::string>{"dark:front:1-2", "dark:rear:3-4"});
  ASSERT_EQ(f.dark.size(), 2u);
  EXPECT_EQ(f.dark[1].camera, "rear");
}

TEST(FaultSpec, BadSpecsThrowOneLine) {
  for (const char* spec : {"",
                           "dark",
                           "dark:front",
                           "dark:front:8-3",
                           "dark:front:x-3",
                           "freeze:left:3",
                           "drop:1.5",
                           "drop:abc",
                           "corrupt:-0.1",
                           "odo-dropout:4",
                           "yaw-bias:nan",
                           "spoof:B1-105",
                           "spoof:@B1-112",
                           "spoof:A@A",
                           "kidnap:",
                           "kidnap:6:-1",
                           "teleport:3",
                           "missing:",
                           "drop:0.1,,dark:front:1-2",
                           "seed:1.5"}) {
    try {
      parseFaults(std::string(spec));
      ADD_FAILURE() << "accepted '" << spec << "'";
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      EXPECT_NE(message.find("--inject"), std::string::npos) << message;
    }
  }
}

TEST(FaultSpec, UnknownCameraIsRejected) {
  geometry::Rig rig;
  rig.cameras.resize(1);
  rig.cameras[0].name = "front";
  EXPECT_NO_THROW(checkFaultCameras(parseFaults("dark:front:1-2"), rig));
  EXPECT_THROW(checkFaultCameras(parseFaults("missing:roof"), rig), InputError);
}

TEST(FaultInjection, DarkCameraIsBlackAndReadsNothingOnlyInItsWindow) {
  auto inj = injector("dark:front:0.5-0.8");
  for (size_t i : {3u, 6u, 9u}) {
    auto f = frame(0.1 * i);
    std::vector<std::string> warnings;
    inj.apply(i, f, warnings);
    ASSERT_EQ(f.cameras.size(), 2u);
    const bool dark = i == 6;
    EXPECT_EQ(cv::countNonZero(f.cameras[0].image.reshape(1)) == 0, dark) << i;
    EXPECT_EQ(f.cameras[0].instances->empty(), dark) << i;
    EXPECT_GT(cv::countNonZero(f.cameras[1].image.reshape(1)), 0);  // rear untouched
    EXPECT_EQ(hasWarning(warnings, "'front' dark"), dark) << i;
  }
}

TEST(FaultInjection, FrozenCameraRepeatsTheLastImageBeforeTheFreeze) {
  auto inj = injector("freeze:front:0.5-0.75");
  std::vector<std::string> warnings;
  auto before = frame(0.4, "B1-101");
  before.cameras[0].image.setTo(cv::Scalar(7, 7, 7));
  inj.apply(4, before, warnings);
  EXPECT_TRUE(warnings.empty());
  for (size_t i : {5u, 6u, 7u}) {
    auto f = frame(0.1 * i, "B1-120");
    inj.apply(i, f, warnings);
    EXPECT_EQ(f.cameras[0].image.at<cv::Vec3b>(0, 0), cv::Vec3b(7, 7, 7)) << i;
    EXPECT_EQ(f.cameras[0].instances->at(0).text, "B1-101") << i;
    EXPECT_EQ(f.cameras[1].instances->at(0).text, "B1-120") << i;  // rear live
  }
  EXPECT_TRUE(hasWarning(warnings, "'front' frozen"));
  auto after = frame(0.8, "B1-130");
  inj.apply(8, after, warnings);
  EXPECT_EQ(after.cameras[0].instances->at(0).text, "B1-130");
}

TEST(FaultInjection, MissingCameraIsRemoved) {
  auto inj = injector("missing:rear");
  auto f = frame(0.3);
  std::vector<std::string> warnings;
  inj.apply(3, f, warnings);
  ASSERT_EQ(f.cameras.size(), 1u);
  EXPECT_EQ(f.cameras[0].camera, "front");
  EXPECT_TRUE(hasWarning(warnings, "'rear' missing"));
}

TEST(FaultInjection, DroppedFramesKeepOdometryAndFollowTheProbability) {
  auto inj = injector("drop:0.3,seed:11", 2000);
  size_t dropped = 0;
  for (size_t i = 0; i < 2000; ++i) {
    auto f = frame(0.1 * i);
    std::vector<std::string> warnings;
    inj.apply(i, f, warnings);
    if (f.cameras.empty()) {
      ++dropped;
      EXPECT_EQ(f.odometry.size(), 5u);
      EXPECT_TRUE(hasWarning(warnings, "dropped"));
    }
  }
  EXPECT_NEAR(static_cast<double>(dropped) / 2000.0, 0.3, 0.04);
  // The same seed drops the same frame sets.
  auto again = injector("drop:0.3,seed:11", 2000);
  auto other = injector("drop:0.3,seed:12", 2000);
  size_t same = 0, differ = 0;
  for (size_t i = 0; i < 200; ++i) {
    auto a = frame(0.1 * i), b = frame(0.1 * i), c = frame(0.1 * i);
    std::vector<std::string> w;
    inj.apply(i, a, w);
    again.apply(i, b, w);
    other.apply(i, c, w);
    same += a.cameras.size() == b.cameras.size();
    differ += a.cameras.size() != c.cameras.size();
  }
  EXPECT_EQ(same, 200u);
  EXPECT_GT(differ, 0u);
}

TEST(FaultInjection, CorruptImagesLoseTheirTextAndStayDecodableOrEmpty) {
  auto inj = injector("corrupt:1");
  auto f = frame(0.2);
  cv::randu(f.cameras[0].image, 0, 255);
  std::vector<std::string> warnings;
  inj.apply(2, f, warnings);
  ASSERT_EQ(f.cameras.size(), 2u);
  for (const auto& c : f.cameras) {
    EXPECT_TRUE(c.instances->empty());
    EXPECT_TRUE(c.image.empty() || c.image.type() == CV_8UC3);
  }
  EXPECT_TRUE(hasWarning(warnings, "corrupt JPEG"));
}

TEST(FaultInjection, CorruptJpegChangesTheImage) {
  cv::Mat image(64, 96, CV_8UC3);
  cv::randu(image, 0, 255);
  std::mt19937_64 rng(5);
  const cv::Mat broken = corruptJpeg(image, rng);
  if (!broken.empty()) {
    ASSERT_EQ(broken.size(), image.size());
    EXPECT_GT(cv::norm(broken, image, cv::NORM_L1), 0.0);
  }
  EXPECT_TRUE(corruptJpeg(cv::Mat(), rng).empty());
}

TEST(FaultInjection, OdometryDropoutAndYawBias) {
  auto inj = injector("odo-dropout:0.45-0.55,yaw-bias:0.02");
  auto f = frame(0.5);  // samples at 0.42 .. 0.50
  std::vector<std::string> warnings;
  inj.apply(5, f, warnings);
  ASSERT_EQ(f.odometry.size(), 2u);  // 0.42 and 0.44 remain
  for (const auto& s : f.odometry) EXPECT_NEAR(s.yaw_rate, 0.12, 1e-12);
  EXPECT_TRUE(hasWarning(warnings, "odometry dropout: 3 samples"));
  EXPECT_TRUE(hasWarning(warnings, "yaw rate biased"));
}

TEST(FaultInjection, SpoofedSignReadsTheFakeNumber) {
  auto inj = injector("spoof:B1-105@B1-112");
  auto f = frame(0.1, "B1-112");
  f.cameras[1].instances->at(0) = instance("B1-113");
  std::vector<std::string> warnings;
  inj.apply(1, f, warnings);
  EXPECT_EQ(f.cameras[0].instances->at(0).text, "B1-105");
  EXPECT_EQ(f.cameras[1].instances->at(0).text, "B1-113");
  EXPECT_TRUE(hasWarning(warnings, "spoofed"));
}

class FixedSpotter : public ocr::TextSpotter {
 public:
  std::string name() const override { return "fixed"; }
  std::vector<ocr::TextInstance> spot(const cv::Mat&, const ocr::SpotRequest&) override {
    return {instance("B1-112"), instance("B1-101")};
  }
};

TEST(FaultInjection, SpoofingSpotterSubstitutesAndNotes) {
  FixedSpotter inner;
  auto inj = injector("spoof:B1-105@B1-112");
  ocr::TextSpotter* spotter = inj.wrapSpotter(&inner);
  ASSERT_NE(spotter, &inner);
  const auto out = spotter->spot(cv::Mat(4, 4, CV_8UC3), {});
  EXPECT_EQ(out[0].text, "B1-105");
  EXPECT_EQ(out[1].text, "B1-101");
  EXPECT_EQ(inj.takeSpotterNotes().size(), 1u);
  EXPECT_TRUE(inj.takeSpotterNotes().empty());
  auto plain = injector("drop:0.1");
  EXPECT_EQ(plain.wrapSpotter(&inner), &inner);
}

TEST(FaultInjection, AMisreadingRenamesTheTextOnlyWithinItsTimeRange) {
  FixedSpotter inner;
  auto inj = injector("misread:B1-105@B1-112:0.2-0.35");
  ocr::TextSpotter* spotter = inj.wrapSpotter(&inner);
  std::vector<std::string> warnings;
  for (int k = 0; k < 6; ++k) {
    auto f = frame(0.1 * k);
    inj.apply(static_cast<size_t>(k), f, warnings);
    const bool during = k == 2 || k == 3;
    EXPECT_EQ(f.cameras[0].instances->at(0).text, during ? "B1-105" : "B1-112") << k;
    EXPECT_EQ(spotter->spot(cv::Mat(4, 4, CV_8UC3), {})[0].text, during ? "B1-105" : "B1-112")
        << k;
  }
  EXPECT_TRUE(hasWarning(warnings, "misread"));
  EXPECT_EQ(inj.takeSpotterNotes().size(), 2u);
  EXPECT_NE(describeFaults(inj.faults()).find("read as 'B1-105' from 0.20 s to 0.35 s"),
            std::string::npos);
  EXPECT_THROW(parseFaults("misread:B1-105@B1-112"), InputError);
  EXPECT_THROW(parseFaults("misread:B1-112@B1-112:1-2"), InputError);
}

TEST(FaultInjection, KidnapSkipsUntilTheTruthHasMovedAndWithholdsOdometry) {
  // Straight at 2 m/s, a frame set every 0.5 s: 20 m take 10 s = 20 frame sets.
  std::vector<double> timestamps;
  std::vector<io::StampedPose> truth;
  for (int i = 0; i < 60; ++i) {
    timestamps.push_back(0.5 * i);
    io::StampedPose p;
    p.timestamp = 0.5 * i;
    p.pose.translation() = Eigen::Vector3d(1.0 * i, 0.0, 0.0);
    truth.push_back(p);
  }
  const auto skips = kidnapSkips({Kidnap{6.0, 19.9}}, timestamps, truth, {});
  // Last processed before: frame 11 (5.5 s, x = 11); resume at x >= 30.9: frame 31.
  for (size_t i = 0; i < skips.size(); ++i) EXPECT_EQ(skips[i], i >= 12 && i < 31) << i;

  // Without truth, the odometry path length decides.
  std::vector<OdometrySample> odometry;
  for (int i = 1; i <= 600; ++i) odometry.push_back({0.05 * i, 2.0, 0.0});
  const auto by_odometry = kidnapSkips({Kidnap{6.0, 19.9}}, timestamps, {}, odometry);
  EXPECT_EQ(by_odometry, skips);

  FaultInjector inj(parseFaults("kidnap:6"), timestamps, truth, {});
  std::vector<std::string> warnings;
  for (size_t i = 0; i < 31; ++i) EXPECT_EQ(inj.skip(i), i >= 12) << i;
  EXPECT_FALSE(inj.skip(31));
  auto f = frame(15.5);
  inj.apply(31, f, warnings);
  EXPECT_TRUE(f.odometry.empty());
  EXPECT_TRUE(hasWarning(warnings, "kidnapped: 19 frame sets skipped"));
  auto next = frame(16.0);
  inj.apply(32, next, warnings);
  EXPECT_EQ(next.odometry.size(), 5u);
}

TEST(FaultInjection, KidnapBeyondTheDriveStopsAtTheFarthestFrame) {
  std::vector<double> timestamps{0.0, 1.0, 2.0, 3.0};
  std::vector<io::StampedPose> truth(4);
  for (int i = 0; i < 4; ++i) {
    truth[i].timestamp = i;
    truth[i].pose.translation() = Eigen::Vector3d(i, 0.0, 0.0);
  }
  const auto skips = kidnapSkips({Kidnap{1.0, 50.0}}, timestamps, truth, {});
  EXPECT_EQ(skips, (std::vector<bool>{false, true, true, false}));
}

}  // namespace
}  // namespace parkloc::run
