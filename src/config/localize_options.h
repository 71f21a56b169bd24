#pragma once
// The localization pipeline's options as configuration sections (option_visitor.h).
#include "config/option_visitor.h"
#include "localize/pipeline.h"

namespace parkloc::config {

void describe(OptionVisitor& v, localize::PipelineOptions& o);

}  // namespace parkloc::config
