#pragma once
// The numbering formats' options (map/numbering.h), one section shared by the map builder's
// reading and the localizer's.
#include "config/option_visitor.h"
#include "map/numbering.h"

namespace parkloc::config {

void describe(OptionVisitor& v, map::NumberingOptions& o);

}  // namespace parkloc::config
