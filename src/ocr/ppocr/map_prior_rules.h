#pragma once
// The map's rules applied to a floor box after it is read, under a predicted pose
// (SpotRequest::placed_floor_texts):
//   - the one-end rule: a free reading of a box lying on a placed text that is one end of that
//     text, glyph for glyph, is that text partly seen (ocr/cut_parts.h);
//   - the placed size: a box read as a placed text is held to that text's painted size
//     (ocr/placed_size.h), because DB's unclip margin grows boxes of small text;
//   - the placed classes: a box takes the classes of the texts placed near it
//     (ocr/placed_classes.h).
#include "ocr/ground_view.h"
#include "ocr/ppocr/map_prior_options.h"
#include "ocr/ppocr/read_jobs.h"
#include "ocr/text_classifier.h"
#include "ocr/text_spotter.h"

namespace parkloc::ocr {

// The one-end rule, for an instance read freely (no lexicon match) from `job`.
void applyOneEndRule(TextInstance& inst, const ReadJob& job, const MapPriorOptions& options);

// Holds a floor box read as a text placed near it, or lying on one, to that text's size, in
// `view`'s pixels, which keep the floor's proportions. A box refused as that text loses its
// reading; false when it is then not confident enough (`confident_box_score`) to be reported
// unread, or read nothing and is a fragment of the text it lies on.
bool holdToPlacedSize(TextInstance& inst, const GroundView& view, const SpotRequest& request,
                      const PlacedSizeOptions& size, float confident_box_score);

// The class weights of a floor box whose centre lies at `view_pixel` of `view`: those of the
// texts placed near it when the request narrows floor boxes to them, else any floor class.
ClassWeights floorClassWeights(const GroundView& view, const cv::Point2f& view_pixel,
                               const SpotRequest& request, const MapPriorOptions& options);

// Whether a request reads floor boxes against the texts the map places near them.
bool narrowsToPlacedTexts(const SpotRequest& request);

}  // namespace parkloc::ocr
