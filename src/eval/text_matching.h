#pragma once
// ICDAR-2015 style detection matching: one-to-one pairs of ground-truth and detected text
// polygons at IoU >= 0.5, with "don't care" ground truth that neither counts as missed nor
// turns a detection on it into a false positive.
#include <optional>
#include <vector>

#include "geometry/image_polygon.h"

namespace parkloc::eval {

using geometry::Quad;

struct MatchingOptions {
  double min_iou = 0.5;
  // A detection that covers a don't-care instance with more than this share of its own area
  // is ignored (the ICDAR-2015 rule for '###' regions).
  double dont_care_min_coverage = 0.5;
  // When set, polygons are compared by their parts inside an image of this size: a text
  // cut by the image border is annotated by what the image shows, as ICDAR annotates
  // (the simulator's label polygons run on outside the image).
  std::optional<cv::Size> image_size;
};

struct MatchedPair {
  size_t truth = 0;
  size_t detection = 0;
  double iou = 0.0;
};

struct ImageMatching {
  std::vector<MatchedPair> matches;
  std::vector<size_t> missed_truths;  // cared-for ground truth without a match (FN)
  // For each missed truth that some detection overlaps (under min_iou), the detection that
  // overlaps it most: what was found there, for looking at the misses.
  std::vector<MatchedPair> nearest_to_missed;
  std::vector<size_t> false_detections;    // detections without a match (FP)
  std::vector<size_t> ignored_detections;  // unmatched detections on don't-care regions
};

// `dont_care[i]` marks truth i as ignored (e.g. at least half occluded). Pairs are taken
// greedily by decreasing IoU, so each truth and each detection is used at most once; matching
// against cared-for truth comes first, so a good detection next to an ignored region counts.
ImageMatching matchDetections(const std::vector<Quad>& truths, const std::vector<bool>& dont_care,
                              const std::vector<Quad>& detections,
                              const MatchingOptions& options = {});

// The same, where truth i may also be boxed by `alternatives[i]` when that is set (empty: none
// has one): its IoU with a detection is the larger of the two. A text partly hidden or cut is
// annotated by the part that shows, and a detector may box that part or the whole text; a box
// on either of a don't-care truth is ignored.
ImageMatching matchDetections(const std::vector<Quad>& truths,
                              const std::vector<std::optional<Quad>>& alternatives,
                              const std::vector<bool>& dont_care,
                              const std::vector<Quad>& detections,
                              const MatchingOptions& options = {});

}  // namespace parkloc::eval
