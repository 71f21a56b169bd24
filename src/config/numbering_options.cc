#include "config/numbering_options.h"

namespace parkloc::config {

void describe(OptionVisitor& v, map::NumberingOptions& o) {
  v.value("min_support", o.min_support, "a format is followed by at least this many numbers");
  v.value("max_strings", o.max_strings,
          "a format spans at most this many numbers (else it is dropped)");
  v.value("range_margin", o.range_margin,
          "a learnt format spans its known numbers' values and this much either side");
  v.value("open_letters", o.open_letters,
          "a capital letter that differs among a format's numbers opens to every capital");
}

}  // namespace parkloc::config
