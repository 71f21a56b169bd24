#include "localize/read_planning.h"

#include <algorithm>
#include <set>

#include "localize/shared_places.h"
#include "map/numbering.h"

namespace parkloc::localize {
namespace {

// The numbers of the map's numbering formats (ReadingOptions::numbering_competitors); none for
// a map that holds every text of its area.
std::vector<std::string> numberingOf(const map::HdMap& map, const ReadingOptions& options) {
  if (!options.numbering_competitors || map.complete()) return {};
  std::vector<std::string> numbers;
  for (const map::Landmark& l : map.landmarks())
    if (l.cls == map::TextClass::kParkingNumber) numbers.push_back(l.text);
  return map::numberingLexicon(map::learnNumbering(numbers, options.numbering));
}

// Appends to `texts` the `numbers` it lacks: they compete with the map's texts and match none.
void addCompetitors(std::vector<std::string>& texts, const std::vector<std::string>& numbers) {
  const std::set<std::string> known(texts.begin(), texts.end());
  for (const std::string& n : numbers)
    if (!known.count(n)) texts.push_back(n);
}

}  // namespace

ReadPlanner::ReadPlanner(const geometry::Rig& rig, const geometry::Rig& calibrated_rig,
                         const map::HdMap& map, const FloorHeights& floors,
                         const ReadingOptions& options, bool guided)
    : rig_(rig),
      calibrated_rig_(calibrated_rig),
      map_(map),
      floors_(floors),
      options_(options),
      schedule_(options, guided),
      // Every level's texts: the full frame is where the texts of another level (after a
      // ramp) and the level signs are read.
      lexicon_(map::distinctTexts(map)),
      floor_lexicon_(map::distinctTexts(map, /*floor_only=*/true)) {
  const std::vector<std::string> numbers = numberingOf(map, options);
  addCompetitors(lexicon_, numbers);
  addCompetitors(floor_lexicon_, numbers);
  roi_options_.margin_px = options.roi_margin_px;
  roi_options_.min_size_px = options.roi_min_size_px;
}

void ReadPlanner::reset() {
  schedule_.reset();
  frame_index_ = -1;
  last_asked_.clear();
  last_read_.clear();
  last_read_attempt_.clear();
}

ReadPlan ReadPlanner::plan(bool tracking, const PoseEkf& ekf, const LevelEstimate& level,
                           std::optional<int> worker_slots, bool tentative, bool no_reads) {
  const bool full_frames_elsewhere = worker_slots.has_value();
  ++frame_index_;
  const size_t n_cameras = rig_.cameras.size();
  ReadPlan plan;
  plan.tracking = tracking;
  plan.tentative = tentative && options_.tentative_reads_whole_lexicon;
  plan.level = level.restriction();
  plan.choice = schedule_.next(n_cameras, tracking, ekf.initialised(), tentative, worker_slots);
  plan.regions.resize(n_cameras);
  if (plan.choice.all) return plan;

  // Regions of every guided camera, then the budget over all of them. While the level is
  // undecided, a place the levels share is one region, asked for the text of any level.
  std::vector<const map::Landmark*> nearby =
      map_.withinRadius(ekf.pose().translation(), options_.roi_radius_m, plan.level);
  std::vector<SharedPlace> places;  // while undecided
  if (!level.belief().decided) {
    places = sharedPlaces(nearby, level.belief().level, level.options().shared_place_m);
    nearby.clear();
    for (const SharedPlace& p : places) nearby.push_back(p.landmark);
  }
  auto& candidates = plan.regions;
  const bool sweeping = plan.choice.sweeping && !full_frames_elsewhere;
  for (size_t c = 0; c < n_cameras; ++c) {
    if (plan.choice.full_frame[c] && !full_frames_elsewhere) continue;
    candidates[c] = predictRegionCandidates(rig_.cameras[c], nearby, floors_, ekf.pose(),
                                            ekf.covariance(), roi_options_);
    for (RegionCandidate& r : candidates[c])
      for (const SharedPlace& p : places) {
        if (p.landmark->id != r.landmark_id) continue;
        r.roi.expected_texts = p.texts;
        // A place whose text differs between levels is read, not fitted, while the level
        // is undecided: its reading is what tells the level.
        if (p.texts.size() > 1) {
          last_read_.erase(r.landmark_id);
          r.tells_level = true;
        }
      }
  }
  RegionBudgetOptions budget;
  budget.max_regions =
      sweeping ? std::min(options_.max_regions_per_frame, options_.max_regions_with_full_frame)
               : options_.max_regions_per_frame;
  if (options_.max_regions_per_frame <= 0)
    budget.max_regions = 0;  // no budget
  else if (budget.max_regions <= 0)
    budget.max_regions = -1;  // nothing on this frame set
  budget.first_camera = frame_index_ % static_cast<int>(std::max<size_t>(n_cameras, 1));
  budget.min_height_px = options_.roi_min_height_px;
  std::vector<std::vector<RegionCandidate>> kept(n_cameras);
  if (budget.max_regions >= 0) {
    const auto chosen = selectRegionsWithinBudget(candidates, last_asked_, frame_index_, budget);
    for (size_t c = 0; c < n_cameras; ++c)
      for (size_t i : chosen[c]) {
        last_asked_[candidates[c][i].landmark_id] = frame_index_;
        kept[c].push_back(std::move(candidates[c][i]));
      }
  }
  candidates = std::move(kept);
  // A frame set that sweeps a camera on the full frame spends its reads there.
  if (options_.reread_interval_frames > 0) chooseReadsAndFits(candidates, sweeping || no_reads);
  return plan;
}

// Texts read lately are only fitted; of the others, up to level_place_reads places that tell
// an undecided level and then the largest are read, at most max_reads_per_frame over all
// cameras; the rest wait for a later frame set.
void ReadPlanner::chooseReadsAndFits(std::vector<std::vector<RegionCandidate>>& candidates,
                                     bool no_reads) {
  struct Unread {
    size_t camera, index;
    double size;
    bool tells_level;
  };
  // Whether `when` holds a frame index for `id` within the last reread_interval_frames.
  const auto lately = [&](const std::map<std::string, int>& when, const std::string& id) {
    const auto it = when.find(id);
    return it != when.end() && frame_index_ - it->second < options_.reread_interval_frames;
  };
  std::vector<Unread> unread;
  std::vector<std::vector<bool>> keep(candidates.size());
  for (size_t c = 0; c < candidates.size(); ++c) {
    keep[c].assign(candidates[c].size(), false);
    for (size_t i = 0; i < candidates[c].size(); ++i) {
      RegionCandidate& r = candidates[c][i];
      if (lately(last_read_, r.landmark_id)) {
        r.roi.read = false;
        keep[c][i] = r.height_px >= options_.tracked_min_height_px;
      } else if (!lately(last_read_attempt_, r.landmark_id)) {
        // (A region tried lately and not read, occluded or blurred, waits a while.)
        unread.push_back({c, i, r.size_px, r.tells_level});
      }
    }
  }
  // The largest first; then up to level_place_reads places that tell the level move ahead.
  std::stable_sort(unread.begin(), unread.end(),
                   [](const Unread& a, const Unread& b) { return a.size > b.size; });
  std::vector<Unread> first, rest;
  for (const Unread& u : unread)
    (u.tells_level && static_cast<int>(first.size()) < options_.level_place_reads ? first : rest)
        .push_back(u);
  unread = std::move(first);
  unread.insert(unread.end(), rest.begin(), rest.end());
  const size_t reads = no_reads ? 0
                       : options_.max_reads_per_frame > 0
                           ? std::min(unread.size(), size_t(options_.max_reads_per_frame))
                           : unread.size();
  for (size_t k = 0; k < reads; ++k) {
    keep[unread[k].camera][unread[k].index] = true;
    last_read_attempt_[candidates[unread[k].camera][unread[k].index].landmark_id] = frame_index_;
  }
  for (size_t c = 0; c < candidates.size(); ++c) {
    std::vector<RegionCandidate> kept;
    for (size_t i = 0; i < candidates[c].size(); ++i)
      if (keep[c][i]) kept.push_back(std::move(candidates[c][i]));
    candidates[c] = std::move(kept);
  }
}

ocr::SpotRequest ReadPlanner::request(size_t c, ReadPlan& plan, const geometry::Pose2& pose) const {
  ocr::SpotRequest request;
  request.camera = &calibrated_rig_.cameras[c];
  if (!plan.choice.full_frame[c]) {
    for (auto& r : plan.regions[c]) {
      request.lexicon.insert(request.lexicon.end(), r.roi.expected_texts.begin(),
                             r.roi.expected_texts.end());
      request.regions.push_back(std::move(r.roi));
    }
    if (plan.tentative && !request.regions.empty()) request.lexicon = lexicon_;
    return request;
  }
  request.lexicon = lexicon_;
  request.floor_lexicon = floor_lexicon_;
  request.second_opinions = options_.second_opinions;
  // While tracking, the full frame is a sweep for what the prediction missed.
  if (plan.tracking && options_.reread_interval_frames > 0) {
    request.max_reads = std::max(0, options_.max_reads_per_frame);
    request.detection_scale = static_cast<float>(options_.sweep_detection_scale);
    if (options_.sweep_places_floor_texts) {
      request.placed_floor_texts =
          map::placeFloorTexts(map_, pose, options_.sweep_placement_range_m, plan.level);
      request.placement_radius_m = options_.sweep_placement_radius_m;
      request.narrow_to_placed_texts = false;
      // Numbers beyond the floor view are seen at a grazing angle, and their corners fix
      // the pose less well than those of the numbers the floor view shows (docs/OCR.md).
      request.look_beyond_the_view = false;
    }
  } else if (plan.choice.searching) {
    request.max_reads = std::max(0, options_.search_max_reads);
    request.detection_scale = static_cast<float>(options_.search_detection_scale);
  }
  return request;
}

void ReadPlanner::noteOutcomes(const FrameResult& result) {
  // One association per instance, camera by camera in rig order.
  size_t k = 0;
  for (const auto& camera : result.cameras)
    for (const auto& instance : camera.instances) {
      const Association& a = result.associations[k++];
      if (a.landmark_id.empty()) continue;
      if (a.verdict == AssociationVerdict::kAccepted && instance.read)
        last_read_[a.landmark_id] = frame_index_;
      else if (a.verdict != AssociationVerdict::kAccepted && !instance.read)
        last_read_.erase(a.landmark_id);
    }
}

}  // namespace parkloc::localize
