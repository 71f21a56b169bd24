#pragma once
// A small simulated sequence for the training-data tests: two frame sets of the demo garage
// (simulating takes seconds).
#include <filesystem>
#include <string>

#include "sim/dataset_writer.h"

namespace parkloc::ocr::testing {

// Writes the dataset under `root`/dataset (replacing `root`); returns the sequence's folder.
inline std::string writeSmallSequence(const std::filesystem::path& root) {
  std::filesystem::remove_all(root);
  sim::Scenario scenario = sim::demoScenario();
  scenario.garages[0].slots_per_row = 9;
  sim::DatasetOptions dataset;
  dataset.out_dir = (root / "dataset").string();
  dataset.max_frames = 2;
  sim::writeDataset(scenario, dataset);
  return (root / "dataset" / "sequences" / sim::planSequences(scenario)[0].name).string();
}

}  // namespace parkloc::ocr::testing
