#pragma once
// Fault injection on drives (`parkloc run --inject SPEC`): a layer between the sequence
// folder and the pipeline that breaks the inputs the way a car's sensors break (a dark or
// frozen camera, a missing camera, dropped and corrupt frames, odometry dropouts, a yaw-rate
// bias, a spoofed parking number, a kidnapped vehicle), so that the pipeline's answer to
// each can be measured (docs/RELIABILITY.md).
//
// SPEC: items separated by commas (a CLI may also repeat the option):
//   dark:CAM:T0-T1      camera CAM sees black from T0 to T1 seconds (sequence time)
//   freeze:CAM:T0-T1    camera CAM repeats its last image before T0 until T1
//   missing:CAM         camera CAM delivers nothing for the whole drive
//   drop:P              each frame set is lost with probability P (odometry still arrives)
//   corrupt:P           each camera image is a corrupt JPEG with probability P
//   odo-dropout:T0-T1   no odometry samples from T0 to T1
//   yaw-bias:B          B rad/s added to every odometry yaw rate
//   spoof:FAKE@REAL     the sign REAL reads FAKE (a fake parking number at REAL's place)
//   misread:FAKE@REAL:T0-T1
//                       the spotter reads REAL as FAKE from T0 to T1 (a misreading, e.g. of
//                       a worn or blurred number, that may give a wrong first fix)
//   kidnap:T[:D]        at T the vehicle jumps D metres (default 20): frame sets are skipped
//                       and their odometry withheld until the truth has moved D metres
//   seed:N              seed of the random choices (drop, corrupt); default 7
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "geometry/rig.h"
#include "io/odometry_csv.h"
#include "io/tum.h"
#include "localize/pipeline.h"
#include "ocr/text_spotter.h"

namespace parkloc::run {

struct TimeRange {
  double begin = 0.0;
  double end = 0.0;
  bool contains(double t) const { return t >= begin && t <= end; }
};

struct CameraFault {
  std::string camera;
  TimeRange range;
};

struct SpoofedSign {
  std::string fake;  // what the sign shows
  std::string real;  // the sign it replaces
  // A misreading: only while the sequence time lies in this range (a spoof: always).
  std::optional<TimeRange> during;
};

struct Kidnap {
  double time = 0.0;
  double distance_m = 20.0;
};

struct InputFaults {
  std::vector<CameraFault> dark;
  std::vector<CameraFault> frozen;
  std::vector<std::string> missing_cameras;
  double drop_probability = 0.0;
  double corrupt_probability = 0.0;
  std::vector<TimeRange> odometry_dropouts;
  double yaw_rate_bias = 0.0;  // rad/s
  std::vector<SpoofedSign> spoofs;
  std::vector<Kidnap> kidnaps;
  uint64_t seed = 7;

  bool empty() const;
};

// Parses SPEC (see the top of this file); several specs are merged. Throws InputError
// naming the item and the field for anything malformed.
InputFaults parseFaults(const std::string& spec);
InputFaults parseFaults(const std::vector<std::string>& specs);
// One line per fault, for the run's log.
std::string describeFaults(const InputFaults& faults);
// Throws InputError when a fault names a camera the rig does not have.
void checkFaultCameras(const InputFaults& faults, const geometry::Rig& rig);

// Frame indices to skip for the kidnaps: from the first frame at or after each kidnap time
// until the first frame whose ground-truth position is distance_m from the last frame
// before it (without truth: path length from the odometry speeds). When the drive never
// gets that far, up to the frame farthest away.
std::vector<bool> kidnapSkips(const std::vector<Kidnap>& kidnaps,
                              const std::vector<double>& timestamps,
                              const std::vector<io::StampedPose>& truth,
                              const std::vector<OdometrySample>& odometry);

// A spotter that reads REAL as FAKE (the spoofed sign, for runs with real OCR); it notes
// each substitution. `inner` must outlive it.
class SpoofingSpotter : public ocr::TextSpotter {
 public:
  SpoofingSpotter(ocr::TextSpotter* inner, std::vector<SpoofedSign> spoofs);
  // The sequence time of the frame set being spotted (SpoofedSign::during).
  void setTime(double time) { time_ = time; }
  std::string name() const override;
  std::vector<ocr::TextInstance> spot(const cv::Mat& image,
                                      const ocr::SpotRequest& request) override;
  // The substitutions since the last call, as warnings.
  std::vector<std::string> takeNotes();

 private:
  ocr::TextSpotter* inner_;
  std::vector<SpoofedSign> spoofs_;
  std::vector<std::string> notes_;
  double time_ = 0.0;
};

// Replaces spoofed (and, at `time`, misread) texts in place; returns one note per
// substitution.
std::vector<std::string> spoofInstances(const std::vector<SpoofedSign>& spoofs,
                                        std::vector<ocr::TextInstance>& instances, double time);

// A corrupt JPEG of `image`: encoded, truncated and with flipped bytes, then decoded the way
// a frame from disk would be. The result may be empty (undecodable) or garbled.
cv::Mat corruptJpeg(const cv::Mat& image, std::mt19937_64& rng);

// Applies the faults frame set by frame set. Frames must come in order; state: the images
// and instances a frozen camera repeats, whether odometry is withheld after a kidnap.
class FaultInjector {
 public:
  // `timestamps`, `truth` and `odometry` of the whole drive decide the kidnap skips.
  FaultInjector(InputFaults faults, const std::vector<double>& timestamps,
                const std::vector<io::StampedPose>& truth,
                const std::vector<OdometrySample>& odometry);

  bool active() const { return !faults_.empty(); }
  const InputFaults& faults() const { return faults_; }

  // True when frame set `index` is skipped (a kidnap): it is not processed at all, and the
  // odometry up to the next processed frame set is withheld.
  bool skip(size_t index);
  // Breaks one frame set's inputs; says what it did in `warnings` ("fault: ...").
  void apply(size_t index, localize::FrameInput& frame, std::vector<std::string>& warnings);
  // The spotter to hand the pipeline: `inner` itself, or a SpoofingSpotter around it.
  ocr::TextSpotter* wrapSpotter(ocr::TextSpotter* inner);
  // Notes of the wrapped spotter since the last call.
  std::vector<std::string> takeSpotterNotes();

 private:
  InputFaults faults_;
  std::vector<bool> skips_;
  bool withhold_next_odometry_ = false;
  size_t skipped_in_a_row_ = 0;
  std::map<std::string, localize::CameraInput> last_seen_;  // per camera, the latest unbroken input
  std::map<std::string, localize::CameraInput> frozen_;     // per camera, the input it repeats
  std::unique_ptr<SpoofingSpotter> spoofing_;
};

}  // namespace parkloc::run
