#pragma once
// Which sequence folders make up a split of a dataset written by `parkloc simulate`:
// DATASET/splits.json lists sequence names per split, each under DATASET/sequences/<name>.
#include <string>
#include <vector>

namespace parkloc::eval {

// The sequence folders of `split` ("train", "val", "test"), in the order splits.json lists
// them. A DATASET that is itself a sequence folder (it has calib.yaml) is returned alone,
// whatever the split. Throws InputError naming the file, the split and the value for a
// missing or malformed splits.json, an unknown split or a listed folder that does not exist.
std::vector<std::string> splitSequences(const std::string& dataset_dir, const std::string& split);

// The garage level a drive is on, from its meta.json text ("level"); empty when absent.
// Parking numbers repeat from level to level, so the pipeline must be told which one.
std::string sequenceLevel(const std::string& meta_json);

}  // namespace parkloc::eval
