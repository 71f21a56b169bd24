#pragma once
// Writes a scenario as a dataset: DIR/sequences/<name>/ (calib.yaml, map.geojson, poses.tum,
// levels.csv, odometry.csv, meta.json, images/<camera>/<stem>.jpg, labels/<camera>/<stem>.json
// and .txt) and DIR/splits.json. See docs/DATASET.md.
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "geometry/rig.h"
#include "sim/scenario.h"

namespace parkloc::sim {

struct DatasetOptions {
  std::string out_dir;
  std::optional<uint64_t> seed;  // replaces the scenario's seed
  int max_sequences = -1;        // < 0: all
  // Only the sequences of these splits (empty: all). Garages keep the seeds they have in the
  // whole scenario, so `--split test` writes exactly the test split of the full dataset.
  std::vector<std::string> splits;
  int max_frames = -1;  // per sequence; < 0: all
  int jobs = 1;         // sequences rendered at the same time
  // Also write each frame set's stitched top-down image (sim/birds_eye.h) with its labels,
  // under <sequence>/birdseye/images and birdseye/labels, at this many metres per pixel.
  bool birdseye = false;
  double birdseye_metres_per_pixel = 0.02;
  // The rig the drives are recorded with, in place of the scenario's (Scenario::rig).
  std::optional<geometry::Rig> rig;
};


// What was written. Rotation subsets follow the paper's Table 8: |rotation_deg| about 45
// (30..60), 90 (60..120) and 180 (>= 150) degrees.
struct DatasetStats {
  int sequences = 0;
  int frame_sets = 0;
  int images = 0;
  // Legible instances only; the thinner ones (labelled "legible": false) are counted apart.
  std::array<int, 3> instances_per_class{0, 0, 0};  // pillar, parking number, other
  std::map<std::string, int> images_per_condition;  // bright, weak, blur
  std::map<std::string, int> instances_per_condition;
  std::map<std::string, int> instances_per_rotation;  // rot45, rot90, rot180
  std::map<std::string, int> images_per_split;
  int occluded_instances = 0;  // occluded_fraction >= 0.5
  int truncated_instances = 0;
  int illegible_instances = 0;
  double render_seconds = 0.0;  // summed over sequences (CPU-parallel time counts once per job)
  double wall_seconds = 0.0;
};

// Progress: sequences' frame sets done so far and in total.
using ProgressCallback = std::function<void(size_t done, size_t total)>;

// A sequence's folder name: "<garage>_<level>_d<drive index>", e.g. "g01_B1_d0"; a drive
// that changes level names both, "<garage>_<level>-<to_level>_d<drive index>" ("g10_B1-B2_d3").
struct SequencePlan {
  std::string name;
  size_t garage = 0;
  size_t drive = 0;
  std::string level;     // the level the drive starts on
  std::string to_level;  // the level it ends on after a ramp; empty when it stays
  std::string split;
  std::string condition;
};
std::vector<SequencePlan> planSequences(const Scenario& scenario);

// Throws InputError / IoError for bad options or unwritable folders.
DatasetStats writeDataset(const Scenario& scenario, const DatasetOptions& options,
                          const ProgressCallback& progress = {});

// The seeds derived from the scenario seed, so every random choice changes with --seed.
uint64_t garageSeed(uint64_t scenario_seed, size_t garage);
uint64_t driveSeed(uint64_t scenario_seed, size_t garage, size_t drive);

}  // namespace parkloc::sim
