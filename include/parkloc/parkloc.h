#pragma once
// parkloc embedded in another program: a localizer built from a rig calibration, a garage map
// and an optional configuration, fed camera images and wheel odometry as they arrive, giving
// the vehicle's pose in the map once per frame set.
//
//   parkloc::LocalizerSettings settings;
//   settings.calibration_file = "calib.yaml";
//   settings.map_file = "map.geojson";
//   auto made = parkloc::Localizer::create(settings);
//   if (!made.localizer) { std::cerr << made.error << "\n"; return 1; }
//   parkloc::Localizer& localizer = *made.localizer;
//   localizer.addOdometry(t, speed, yaw_rate);                  // as samples arrive
//   for (const auto& pose : localizer.addImage("front", t, bgr))  // as images arrive
//     if (pose.has_pose) use(pose.x, pose.y, pose.yaw);
//
// Frame sets. A surround-view rig's cameras are rarely triggered together, so images are
// grouped by capture time: a frame set holds at most one image per camera, each captured
// within `frame_set_tolerance_s` of the set's first image. A set is processed as soon as it
// holds an image of every camera in the calibration, or when an image arrives that cannot
// join it (a second image of a camera already in the set, or one captured later than the
// tolerance allows); a camera whose image has not arrived by then is missing from that set,
// and the pipeline localizes with the others. An image captured before the open set's
// tolerance window arrived too late for its set: it is dropped and reported in the next
// estimate's warnings, as is an image of a camera the calibration does not name. Each image
// is used at its own capture time (the pipeline propagates the pose between them with the
// odometry). flush() processes the open set at the end of a stream.
//
// Odometry. A sample goes with the first frame set captured at or after it; samples must
// come in increasing time, and a sample for a set already processed is dropped and reported.
// Give the samples up to an image's time before the image, as a vehicle bus delivers them.
//
// Errors. create() returns the reason instead of a localizer for a calibration, map,
// configuration or model that cannot be read; nothing else in this interface throws for bad
// input (an unusable image or sample is skipped and reported in warnings). Not thread-safe:
// one thread feeds one localizer.
//
// Units and frames: seconds, metres, radians; the pose is map_from_vehicle, the vehicle frame
// x forward, y left, origin on the ground under the rear-axle centre (ROS REP-103); the map
// frame x east, y north, as the map file's coordinates.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace parkloc {

struct LocalizerSettings {
  std::string calibration_file;  // rig calibration YAML (README "File formats")
  std::string map_file;          // the garage's map, GeoJSON
  // A configuration YAML overlaid on the defaults (`parkloc config dump` prints them; the
  // installed <prefix>/share/parkloc/config/default.yaml holds them). "": the defaults.
  std::string config_file;
  // The model folder. "": the configuration's models.dir, else $PARKLOC_MODEL_DIR, else the
  // installed <prefix>/share/parkloc/models, else the build tree's third_party/models.
  std::string models_dir;
  // A hint: the map level the drive starts on; "": the configuration's, else estimated from
  // the texts seen.
  std::string level;
  // How far from a frame set's first image (before or after) another camera's image may be
  // captured and still join the set: under half the frame period. 0.045 s suits 10 Hz cameras (0.45 frame
  // periods, the tolerance `parkloc run` derives from a recorded drive's frame rate).
  double frame_set_tolerance_s = 0.045;
};

enum class TrackingStatus {
  kNoFix,          // no fix yet: no pose
  kTracking,       // a measurement updated the pose with this frame set
  kDeadReckoning,  // no measurement this frame set; the pose is predicted by odometry
  kLost,           // the uncertainty grew too large, or the track is re-localising
};
std::string toString(TrackingStatus status);  // "no_fix", "tracking", "dead_reckoning", "lost"

// The localizer's answer for one frame set.
struct PoseEstimate {
  double timestamp = 0.0;  // the set's time: the capture time of its earliest image, seconds
  TrackingStatus status = TrackingStatus::kNoFix;
  bool has_pose = false;  // false only before the first fix
  // map_from_vehicle: position in metres, heading in radians counter-clockwise from map x.
  double x = 0.0, y = 0.0, yaw = 0.0;
  // Covariance of (x, y, yaw), row-major, m^2 and rad^2.
  std::array<double, 9> covariance{};
  // The level driven on: the most probable one, its probability, and whether it is decided
  // (undecided with a pose: the levels share the places seen so far).
  std::string level;
  double level_probability = 0.0;
  bool level_decided = false;
  // The pose rests on one landmark's reading, not yet confirmed by a second landmark read
  // consistently with it: it may come from a misreading and may jump when one is found.
  bool tentative = false;
  std::vector<std::string> cameras;   // the cameras whose images the set held
  std::vector<std::string> warnings;  // dropped inputs, unreadable images, the pipeline's notes
};

struct LocalizerOrError;

class Localizer {
 public:
  // Reads the calibration, the map and the configuration and loads the models.
  static LocalizerOrError create(const LocalizerSettings& settings);

  ~Localizer();
  Localizer(Localizer&&) noexcept;
  Localizer& operator=(Localizer&&) noexcept;
  Localizer(const Localizer&) = delete;
  Localizer& operator=(const Localizer&) = delete;

  // The calibration's camera names, the names addImage() takes.
  std::vector<std::string> cameras() const;
  // The model folder in use.
  const std::string& modelsDir() const;

  // A wheel-odometry sample: forward speed (m/s) and yaw rate (rad/s, counter-clockwise).
  void addOdometry(double timestamp, double speed, double yaw_rate);
  // An 8-bit BGR image (as cv::imread or cv::VideoCapture give it) and its capture time. An
  // image of another type is dropped with a warning; an empty one stands for a frame that
  // could not be decoded (the camera counts as present, the pipeline reports it).
  // Returns the estimates of the frame sets this image completes, oldest first: none while
  // the set waits for other cameras, one usually, two when the image closes the open set and
  // completes a set of its own.
  std::vector<PoseEstimate> addImage(const std::string& camera, double timestamp,
                                     const cv::Mat& image);
  // Processes the open frame set, complete or not; empty when none is open.
  std::optional<PoseEstimate> flush();
  // Forgets the track and any open frame set (a new drive).
  void reset();

 private:
  struct Impl;
  explicit Localizer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// A localizer, or the reason there is none (one line naming the file and the problem).
struct LocalizerOrError {
  std::optional<Localizer> localizer;
  std::string error;
};

}  // namespace parkloc
