#pragma once
// One line of frames.jsonl: everything the pipeline did with a frame set (instances,
// associations, pose, covariance, status, per-stage timings, warnings).
#include <string>

#include "localize/pipeline.h"

namespace parkloc::run {

// Compact JSON object on one line (no trailing newline).
std::string frameResultToJson(const localize::FrameResult& result);

}  // namespace parkloc::run
