#pragma once
// The text spotter's options as configuration sections (option_visitor.h). The model files
// are not among them: they are chosen in the `models` section (config.h, ModelOptions).
#include "config/option_visitor.h"
#include "ocr/ppocr/pp_ocr_spotter.h"

namespace parkloc::config {

void describe(OptionVisitor& v, ocr::PpOcrOptions& o);

}  // namespace parkloc::config
