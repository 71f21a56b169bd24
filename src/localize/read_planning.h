#pragma once
// Stage 2 of the pipeline, read planning: what the spotter is asked to read this frame set.
//
//  - Full frame or map-guided regions. While the track holds, the map's texts near the
//    predicted pose are projected into each camera and only those regions are spotted
//    (roi_prediction.h), under a per-frame budget (region_budget.h). Now and then one camera
//    is swept on the full frame, in turn (the round robin), to catch what the prediction
//    missed. Before the first fix a few cameras per frame set are spotted on the full frame,
//    in turn (searching); when the track is lost, every camera, every frame set.
//  - Reads or fits. A landmark read and accepted lately is only fitted to the ink where the
//    map predicts it (ocr::RegionOfInterest::read == false, under 1 ms); of the others at
//    most a few are read per frame set (~15 ms a crop), the largest first.
//  - The ocr::SpotRequest of each camera: its lexicon, its regions, and for a full frame
//    the detector scale, the read limit and the floor texts the tracked pose places nearby.
//
// The paper's pipeline (OCR-RTPS) spots every camera on the full frame every frame set.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "geometry/rig.h"
#include "localize/floor_heights.h"
#include "localize/frame_types.h"
#include "localize/level_estimate.h"
#include "localize/pose_ekf.h"
#include "localize/region_budget.h"
#include "localize/roi_prediction.h"
#include "map/hd_map.h"
#include "map/numbering.h"
#include "map/placed_texts.h"
#include "ocr/text_spotter.h"

namespace parkloc::localize {

struct ReadingOptions {
  // Spot only where the map predicts text while tracking; false: the full frame always.
  bool map_guided = true;
  // While tracking, each camera is spotted on the full frame once per this many frame sets
  // (every frame set when lost or not initialised); 1: always the full frame. 30 frame sets
  // (3 s at 10 Hz) sweep 13 % of the frame sets against 40 % with 10, at the same accuracy
  // on the demo drive.
  int full_frame_interval = 30;
  // While tracking, the full-frame sweeps go one camera at a time in turn, spread evenly over
  // full_frame_interval frame sets, so that no frame set spots two full frames (the p99
  // latency); false: all cameras in the same frame set every full_frame_interval.
  bool full_frame_round_robin = true;

  // Searching (no fix yet): this many cameras are spotted on the full frame per frame set, in
  // turn (0: all of them), and the texts of the last few frame sets are solved together
  // (search_window.h). Spotting one camera costs 50-130 ms on two cores, all four 400-700 ms,
  // against a p99 latency target of 150 ms. A lost track spots every camera every frame set:
  // re-localising matters more than latency then, and one far text seen end-on rarely fixes
  // a pose (one camera per frame set did not recover from a 4 m kidnap within 5 s, all four
  // did in 3.5 s).
  int search_cameras_per_frame = 1;
  // While searching, at most this many detected texts are read per camera, the largest first
  // (0: all): a large text is near and fixes the pose best.
  int search_max_reads = 2;
  // While searching, the detector's input is scaled by this: the round robin comes back to a
  // camera every few frame sets, so a text missed at this scale is only a little late.
  double search_detection_scale = 0.75;

  // Map-guided regions: the map's texts within this radius (metres) of the predicted pose
  // are projected into the cameras.
  double roi_radius_m = 12.0;
  // A predicted text's region is grown by the pose uncertainty and by this margin (pixels),
  // for the map survey error and the OCR polygon jitter.
  double roi_margin_px = 12.0;
  // Predicted text smaller than this (longest side, pixels) cannot be read: skipped.
  double roi_min_size_px = 8.0;
  // Predicted text flatter than this (pixels across the reading direction: a grazing view)
  // is not read reliably: skipped by the region budget.
  double roi_min_height_px = 6.0;
  // At most this many regions per frame set over all cameras, the ones that help most first
  // (region_budget.h); <= 0: every predicted region. Each region costs the OCR engine ~18 ms
  // of CPU; the EKF carries the pose between measurements. Off by default: a budget of 3
  // made fixes too sparse through a turn on the demo drive (24 cm mean error).
  int max_regions_per_frame = 0;
  // On a frame set that sweeps a camera on the full frame (~100 ms), the region budget of
  // the other cameras, to keep the frame set within the p99 latency target.
  int max_regions_with_full_frame = 1;

  // A landmark read and accepted within this many frame sets is only fitted, not read again
  // (0: every region is read every frame set). Reading every region every frame set cost
  // 560 ms median per frame set on the demo drive for 9.5 cm mean error, against 54 ms and
  // 2.8 cm with 10 (and 2 reads per frame set).
  int reread_interval_frames = 10;
  // At most this many regions are read per frame set over all cameras, the largest unread
  // first; one tried without success waits reread_interval_frames (<= 0: no limit).
  int max_reads_per_frame = 2;
  // While the level is undecided, up to this many of a frame set's reads go first to places
  // whose text differs between levels (a level sign on a pillar or a wall), however small:
  // one reading of one can decide the level, where a parking number the levels share says
  // nothing of it; the other reads go to the largest texts, whose corners fix the pose.
  // 0: by size alone.
  int level_place_reads = 1;
  // Predicted text flatter than this (pixels) is not fitted: its corners would not fix the
  // pose.
  double tracked_min_height_px = 8.0;
  // While the track is tentative (track_lifecycle.h), a region is read against every text
  // of the map, not only the text the pose predicts there: under a pose from one misreading
  // the number painted at a predicted place is another one, and decoding it against the
  // predicted text alone can force that text onto it.
  bool tentative_reads_whole_lexicon = true;
  // While the track is tentative, each camera is swept on the full frame once per this many
  // frame sets (4 on a four-camera rig: one camera every frame set): under a wrong pose the
  // map-guided regions may hold no text at all, and the sweep reads what tells it is wrong.
  // <= 1: as while tracking (full_frame_interval).
  int tentative_full_frame_interval = 4;

  // While tracking, the full-frame sweep's detector input is scaled by this (it only has to
  // catch what the prediction missed). Chosen on the validation drives: the same mean error
  // as 0.75 (1.27 / 0.78 / 0.99 cm) with the slowest sweep frame set at 61-102 ms.
  double sweep_detection_scale = 0.5;
  // While tracking, the sweep reads each floor box only the way round that the floor texts
  // the tracked pose places near it read (ocr::SpotRequest::placed_floor_texts,
  // map/placed_texts.h): one recognizer pass a box instead of two. It still decodes against
  // the whole floor lexicon: narrowing that to the placed texts matched more worn and cut
  // numbers, whose corners raised the val split's mean error from 1.41 to 1.75 cm.
  bool sweep_places_floor_texts = true;
  // The floor texts are placed out to this range (metres): the floor views' reach.
  double sweep_placement_range_m = map::kFloorViewReachM;
  // ... and looked for within this radius (metres) of a box.
  double sweep_placement_radius_m = 1.0;

  // Ask the spotter for second opinions (ocr::SpotRequest::second_opinions) on full frames.
  // Off: on the test drives they moved no error figure but cost the full-frame frame sets
  // 30-50 ms at p95 and p99, and a second opinion can only confirm a tracked pose, never
  // start one (AssociationVerdict::kUnconfirmed).
  bool second_opinions = false;

  // With a map that is not complete (map::HdMap::complete: one built from drives), the full
  // frame is also read against the numbers of the map's numbering formats (map/numbering.h)
  // that the map lacks; they match no landmark. A map built from a drive holds the numbers that
  // drive read: a number outside it, read against the map's texts alone, is taken for the map's
  // nearest number and can fix the pose at that number's place. A complete map lacks no
  // number, and there the competitors only split the posterior of worn numbers (levels val:
  // a first fix 1.9 s later on lv01_P3_d1).
  bool numbering_competitors = true;
  // Zone letters open (A### to Z###): the zones of a partial map need not be all the
  // garage has.
  map::NumberingOptions numbering = [] {
    map::NumberingOptions o;
    o.open_letters = true;
    return o;
  }();
};

// Which cameras are spotted on the full frame this frame set: the round robin while
// tracking, the search turn before the first fix.
struct FullFrameChoice {
  std::vector<bool> full_frame;  // per rig camera
  bool all = false;              // every camera on the full frame (no map guidance)
  bool sweeping = false;         // tracking, and one camera's turn for a full-frame sweep
  bool searching = false;        // no fix yet: a few cameras in turn
};

class FullFrameSchedule {
 public:
  // `guided`: map-guided reading applies (false in the paper's pipeline).
  FullFrameSchedule(const ReadingOptions& options, bool guided)
      : options_(options), guided_(guided) {}
  void reset() { *this = FullFrameSchedule(options_, guided_); }
  // `tracking`: the filter's pose is good enough to predict regions; `initialised`: the
  // filter has a pose at all (lost or not); `tentative`: the track is tentative
  // (tentative_full_frame_interval). `worker_slots`: the full frames go to workers
  // (search_worker.h), this many of them free this frame set; nullopt: spotted inside the
  // frame set. With no worker free the turn waits: the camera due is the next one taken,
  // so that a busy worker skips no camera of the search or the sweep.
  FullFrameChoice next(size_t n_cameras, bool tracking, bool initialised, bool tentative = false,
                       std::optional<int> worker_slots = std::nullopt);

 private:
  ReadingOptions options_;
  bool guided_ = true;
  int frames_since_full_frame_ = 0;  // without the round robin
  int tracking_frames_ = 0;          // frame sets since the track began
  size_t next_sweep_camera_ = 0;
  size_t next_search_camera_ = 0;
  bool sweep_waiting_ = false;  // a sweep came due while no worker was free
};

// The plan of one frame set.
struct ReadPlan {
  FullFrameChoice choice;
  bool tracking = false;
  std::vector<std::vector<RegionCandidate>> regions;  // per rig camera, the regions to spot
  std::string level;                                  // map level of the plan ("": all)
  bool tentative = false;  // the track is tentative: regions are read against the whole map
};

class ReadPlanner {
 public:
  // The rigs, map and floors must outlive the planner. `rig` places the regions (each camera
  // where it stood when it captured its image, localize/capture_time.h); the spotter gets the
  // cameras of `calibrated_rig` (its floor views are made once per calibration).
  ReadPlanner(const geometry::Rig& rig, const geometry::Rig& calibrated_rig, const map::HdMap& map,
              const FloorHeights& floors, const ReadingOptions& options, bool guided);
  void reset();

  // The plan of the next frame set at the filter's predicted pose. `tracking`: the filter's
  // pose is good enough to predict regions; `level`: the levels to look for (the decided
  // one, else every level, a shared place read once for any of its texts).
  // `worker_slots`: the full frames are spotted off the frame set's critical path
  // (search_worker.h) by this many workers free now, so a sweep's camera gets its regions as
  // well and a sweep costs the frame set none of its reads; nullopt: inside the frame set.
  // `tentative`: the track is tentative (track_lifecycle.h). `no_reads`: only fits this
  // frame set (the reads' worker is busy); the texts due a read are not marked as tried and
  // come up again in the next plan.
  ReadPlan plan(bool tracking, const PoseEkf& ekf, const LevelEstimate& level,
                std::optional<int> worker_slots = std::nullopt, bool tentative = false,
                bool no_reads = false);

  // Camera c's request (its regions are moved out of the plan).
  ocr::SpotRequest request(size_t c, ReadPlan& plan, const geometry::Pose2& pose) const;

  // After association: a landmark read and accepted needs no reading for a while; one only
  // fitted that does not fit the prediction is read again.
  void noteOutcomes(const FrameResult& result);

  const ReadingOptions& options() const { return options_; }

 private:
  void chooseReadsAndFits(std::vector<std::vector<RegionCandidate>>& candidates, bool no_reads);

  const geometry::Rig& rig_;
  const geometry::Rig& calibrated_rig_;
  const map::HdMap& map_;
  const FloorHeights& floors_;
  ReadingOptions options_;
  RoiOptions roi_options_;
  FullFrameSchedule schedule_;
  std::vector<std::string> lexicon_;              // every text of the map (full-frame spotting)
  std::vector<std::string> floor_lexicon_;        // the texts of it painted on the floor
  int frame_index_ = -1;                          // the frame set being planned
  std::map<std::string, int> last_asked_;         // landmark -> frame set it was last asked for
  std::map<std::string, int> last_read_;          // ... last read and accepted
  std::map<std::string, int> last_read_attempt_;  // ... last given a read
};

}  // namespace parkloc::localize
