#pragma once
// The map builder's options as a configuration section (option_visitor.h).
#include "config/option_visitor.h"
#include "mapping/map_builder.h"

namespace parkloc::config {

void describe(OptionVisitor& v, mapping::MapBuildOptions& o);

}  // namespace parkloc::config
