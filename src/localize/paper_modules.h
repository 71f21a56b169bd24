#pragma once
// The three modules of the paper (OCR-RTPS), each switchable for its ablation (paper table
// "AFM / MCRP / MCAP"). Both pipelines use them: the AFM drops anomalous parking numbers
// before association (box_plot_filter.h); MCRP and MCAP choose which observations the
// measurement fuses.
#include <vector>

#include "localize/box_plot_filter.h"
#include "localize/landmark_observation.h"

namespace parkloc::localize {

struct PaperModuleOptions {
  // AFM: the box-plot anomaly filter on parking numbers (section 3.3).
  bool afm = true;
  // MCRP: one landmark's relative position is averaged over the cameras that see it
  // (section 3.5); off: the first camera's (rig order) alone.
  bool mcrp = true;
  // MCAP: every landmark seen is used (section 3.5); off: only the one that looks largest,
  // the nearest and most precise.
  bool mcap = true;
  // The AFM's queue of recent numbers: the paper's 30 frames.
  int afm_queue_length = 30;
  // The AFM's box: [median - k IQR, median + k IQR], the paper's k = 1.5.
  double afm_iqr_factor = 1.5;
  // After this many rejections in a row the AFM's queue is refilled (0: never, the paper's
  // literal rule): a queue stuck on the numbers of one aisle would otherwise reject the next
  // aisle's forever (BoxPlotFilterOptions::reset_after_rejections).
  int afm_reset_after_rejections = 30;
};

BoxPlotFilterOptions afmOptions(const PaperModuleOptions& options);

// The observations MCRP and MCAP let through (MCRP first: one camera per landmark; then
// MCAP: one landmark), in the order given.
std::vector<LandmarkObservation> selectForModules(std::vector<LandmarkObservation> obs,
                                                  const PaperModuleOptions& options);

}  // namespace parkloc::localize
