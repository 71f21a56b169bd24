#pragma once
// What `parkloc simulate` generates: garages (layout, numbering, fonts, parked cars) and the
// drives recorded in each of them. Read from a YAML scenario file or built in code; see
// docs/DATASET.md for the file format.
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "sim/appearance.h"

namespace parkloc::sim {

// How parking numbers are written: "098", "117", "B2-117", "A023".
enum class NumberingScheme { kThreeDigit, kPlain, kLevelDash, kZoneLetter };
std::string toString(NumberingScheme scheme);
NumberingScheme numberingSchemeFromString(const std::string& name);  // throws InputError

// One recorded drive. `route` is "tour" (along aisles, through turns) or "park" (a short
// approach and a reverse parking manoeuvre into a free slot). `condition` is "bright",
// "weak" (dim lamps, some off, more sensor noise) or "blur" (motion blur and defocus).
//
// A tour may change level: it starts on `level`, drives, goes down (or up) a ramp for
// `transition_s` seconds and continues on `to_level`. The levels of a garage share their
// layout, so the x-y path runs on unbroken; the ramp is rendered as the garage's shell with no
// text in view (sim/ramp_level.h), see docs/DATASET.md.
struct DriveSpec {
  DriveSpec() = default;
  DriveSpec(std::string route_, std::string condition_, std::string level_, double duration)
      : route(std::move(route_)),
        condition(std::move(condition_)),
        level(std::move(level_)),
        duration_s(duration) {}

  std::string route = "tour";
  std::string condition = "bright";
  std::string level;          // empty: the garage's levels in turn
  double duration_s = 20.0;   // upper bound; a park route ends when parked
  std::string to_level;       // empty: the drive stays on its level
  double transition_s = 3.0;  // seconds on the ramp
  // When the ramp begins, seconds from the start; < 0: the ramp is centred in the drive, so
  // both levels get the same time.
  double transition_at_s = -1.0;
  // How the garage and the camera look on this drive (sim/appearance.h); the garage's
  // `appearance` unless the drive names its own. Default: the clean look.
  AppearanceOptions appearance;
  // Cameras not triggered together: each camera captures this long after the frame set's
  // trigger (seconds, per camera name; absent: 0), plus a delay drawn uniformly in
  // [0, camera_jitter_s] per image. Images are named by their capture times, and the labels
  // and poses.tum hold the truth at those times.
  std::map<std::string, double> camera_delay_s;
  double camera_jitter_s = 0.0;
  // >= 0: the drive repeats drive `repeat_of` (an earlier one of the same garage) with its own
  // look and camera delays: the same route, light, frames and sensor noise, its other fields
  // copied from that drive, so that two looks (or a synchronised and a staggered rig) compare
  // on the same drive. -1: a drive of its own.
  int repeat_of = -1;
};

struct GarageSpec {
  std::string name = "garage";
  std::string split = "train";  // train | val | test
  std::vector<std::string> levels = {"B1"};
  int aisles = 2;  // parallel aisles, each with a slot row on both sides
  int slots_per_row = 15;
  int slots_per_pillar = 3;  // a pillar between groups of this many slots
  double slot_width = 2.5;
  double slot_depth = 5.3;
  double aisle_width = 6.0;
  double ceiling_height = 2.8;
  double pillar_size = 0.6;
  double number_height = 0.45;  // painted parking numbers, metres of ink height
  double occupancy = 0.5;       // share of slots with a parked car
  double worn_share = 0.25;     // share of painted text that is worn or partly erased
  double yellow_share = 0.3;    // share of painted text in yellow instead of white
  NumberingScheme numbering = NumberingScheme::kThreeDigit;
  int first_number = 1;
  // Font files (names under /usr/share/fonts/truetype/{dejavu,liberation,freefont} or paths).
  std::vector<std::string> fonts = {"DejaVuSans-Bold.ttf"};
  // Signs naming the level ("B2") on the end walls of the aisles and cross aisles and hung
  // over each aisle, as real garages have them (garage_signs.cc). Off: no sign is placed and
  // nothing else of the garage changes.
  bool level_signs = false;
  // The look of every drive that does not name its own (sim/appearance.h).
  AppearanceOptions appearance;
  std::vector<DriveSpec> drives = {DriveSpec{}};
};

struct Scenario {
  std::string name = "scenario";
  uint64_t seed = 1;
  double frame_rate = 10.0;     // camera frames per second
  double odometry_rate = 50.0;  // wheel odometry samples per second
  int jpeg_quality = 90;
  // Where floor text's legibility is judged (the labels' "legible" flag): on the image as
  // written, after the camera's processing and every codec (sim/ink_through_camera.h), or
  // (false) on the rendered scene, the ink's contrast against the sensor's noise. The scene
  // misses what the camera's effects and a hard codec do to the strokes.
  bool legibility_on_image = false;
  // The rig's calibration file (io/calibration_yaml.h) the drives are recorded with; a
  // relative path in a scenario file is relative to that file's folder. Empty: the default
  // rig (geometry::defaultRig()).
  std::string rig;
  std::vector<GarageSpec> garages;
};

// The shipped dataset: 10 garages (7 train, 2 val, 1 test with numbering schemes and fonts
// that train never sees), every condition: 13 drives of about 12 s at 10 Hz and one 30 s
// test drive from B1 down to B2, about 2,200 frame sets. Equals data/scenarios/default.yaml.
Scenario defaultScenario();
// One small garage and one ~30 s drive, for `parkloc demo` and quick checks.
Scenario demoScenario();

// Reads a scenario YAML file; throws InputError naming the file and field.
Scenario loadScenario(const std::string& path);
Scenario parseScenario(const std::string& yaml_text, const std::string& source_name);

// Every file name in `fonts` resolved to an existing path; throws InputError.
std::string resolveFontPath(const std::string& font);

}  // namespace parkloc::sim
