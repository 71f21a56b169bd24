#include "config/ocr_options.h"

namespace parkloc::config {
namespace {

void describe(OptionVisitor& v, ocr::DbOptions& o) {
  v.value("binary_threshold", o.binary_threshold, "a map pixel is text above this probability");
  v.value("box_threshold", o.box_threshold, "a box is kept when its mean probability reaches this");
  v.value("unclip_ratio", o.unclip_ratio, "DB's growth of a shrunk text kernel back to its box");
  v.value("max_candidates", o.max_candidates, "boxes looked at per image at most");
  v.value("min_size", o.min_size, "shorter side of a box in map pixels, below: noise");
  v.value("dilate", o.dilate, "2x2 dilation of the binary map (PaddleOCR's use_dilation)");
}

void describe(OptionVisitor& v, ocr::GroundViewOptions& o) {
  v.value("resolution", o.resolution, "metres per view pixel");
  v.value("near", o.near,
          "where the view starts ahead of the camera (negative: behind; a fisheye sees beside)");
  v.value("far", o.far, "metres ahead of the camera");
  v.value("half_width", o.half_width, "metres to each side of the camera");
  v.value("reference_focal_px", o.reference_focal_px,
          "far and half_width are for this focal length; a camera's reach scales by fx over it "
          "(0: as given)");
  v.value("max_extent_scale", o.max_extent_scale,
          "... by at most this: the view's area and detection time grow with its square");
}

void describe(OptionVisitor& v, ocr::LexiconOptions& o) {
  v.value("min_posterior", o.min_posterior,
          "the best entry is taken when its posterior against a free reading reaches this");
  v.value("min_log_prob_per_char", o.min_log_prob_per_char,
          "... and its mean log probability a character is above this (not noise)");
  v.value("open_world_weight", o.open_world_weight,
          "prior weight of \"a text not in the lexicon\": below 1, the map lists what is there");
  v.value("look_alikes_are_the_entry", o.look_alikes_are_the_entry,
          "a reading off only by look-alike glyphs (O/0, U/0) is the entry misread");
}

void describe(OptionVisitor& v, ocr::PlacedWindowOptions& o) {
  v.value("side_m", o.side_m, "square window around a placed text: the number and the pose error");
  v.value("inside_margin_m", o.inside_margin_m,
          "a text this far inside the floor view is left to it");
  v.value("min_height_px", o.min_height_px,
          "texts that would show shorter than this in the raw image are too small to find");
  v.value("text_height_m", o.text_height_m, "the painted numbers' height, for that estimate");
  v.value("max_texts", o.max_texts, "windows per image, the tallest texts first (0: all)");
}

void describe(OptionVisitor& v, ocr::DetectionOptions& o) {
  v.choice("view", o.view,
           {{"raw", ocr::FisheyeView::kRaw},
            {"ground", ocr::FisheyeView::kGround},
            {"ground_and_raw", ocr::FisheyeView::kGroundAndRaw}},
           "what the detector looks at: the raw image, the floor's bird's-eye view, or both");
  v.value("scene_max_side", o.scene_max_side,
          "a raw image is detected at this longer side: PaddleOCR's own input size");
  v.section("scene_db", "PaddleOCR's post-processing for its own detector",
            [&] { describe(v, o.scene_db); });
  v.value("scene_read_expand_x", o.scene_read_expand_x,
          "a raw image's boxes are read from a crop grown by this along the text (1: as found)");
  v.value("scene_read_expand_y", o.scene_read_expand_y, "... and by this across it");
  v.section("floor_view", "the floor's bird's-eye view the floor detector looks at",
            [&] { describe(v, o.floor_view); });
  v.section("floor_db", "the floor detector's post-processing (trained on DB kernels r = 0.4)",
            [&] { describe(v, o.floor_db); });
  v.value("floor_read_expand_x", o.floor_read_expand_x,
          "floor boxes are the text's own box: read from a crop grown by this along the text");
  v.value("floor_read_expand_y", o.floor_read_expand_y, "... and by this across it");
  v.value("floor_unfitted_unclip_ratio", o.floor_unfitted_unclip_ratio,
          "a floor box with no ink fit is the kernel grown by this, not floor_db's (0: that)");
  v.value("birdseye_unfitted_unclip_ratio", o.birdseye_unfitted_unclip_ratio,
          "... and on a bird's-eye image (parkloc ocr --birdseye)");
  v.value("confident_box_score", o.confident_box_score,
          "floor boxes this sure are text found even when nothing reads them");
  v.section("band", "the raw image's horizon band, as rays from the optical axis", [&] {
    v.value("top", o.band.top, "radians from the axis of its top edge (negative: above)");
    v.value("bottom", o.band.bottom, "radians from the axis of its bottom edge");
    v.value("pixels_per_radian", o.band.pixels_per_radian,
            "the band detector's training scale: a longer focal length is shrunk to it (0: never)");
  });
  v.section("band_db", "the band detector's post-processing", [&] { describe(v, o.band_db); });
  v.section("placed_reach", "under a pose, placed floor texts out to this view get windows",
            [&] { describe(v, o.placed_reach); });
  v.section("placed_windows", "the windows around placed texts beyond the floor view",
            [&] { describe(v, o.placed_windows); });
}

void describe(OptionVisitor& v, ocr::PlacedSizeOptions& o) {
  v.value("min_length_share", o.min_length_share,
          "a box shorter than this share of its text's length is refused as that text");
  v.value("max_height_ratio", o.max_height_ratio,
          "a box taller than this multiple of its text is cut to its height (unclip margin)");
  v.value("max_length_ratio", o.max_length_ratio, "... longer than this, to its length");
  v.value("unmatched_margin_m", o.unmatched_margin_m,
          "an unmatched box lying on a placed text within this margin is held to it too");
  v.value("unmatched_max_angle", o.unmatched_max_angle,
          "... when it runs along that text within this angle (radians)");
}

void describe(OptionVisitor& v, ocr::MapPriorOptions& o) {
  v.section("placed_lexicon", "decoding a floor box against the texts the map places near it",
            [&] { describe(v, o.placed_lexicon); });
  v.section("on_placed_text_lexicon", "... a box lying on a placed text: the map paints it there",
            [&] { describe(v, o.on_placed_text_lexicon); });
  v.value("on_placed_text_margin_m", o.on_placed_text_margin_m,
          "metres around a placed text's footprint within which a box lies on it");
  v.value("placed_reading_max_angle", o.placed_reading_max_angle,
          "a box along the placed texts' direction (radians) is read that way round only");
  v.value("unplaced_class_weight", o.unplaced_class_weight,
          "class prior of other floor text beside a placed parking number (1: classifier alone)");
  v.value("min_cut_part_chars", o.min_cut_part_chars,
          "a box cut by the image border decodes against placed texts' parts this long (0: none)");
  v.optionalSection("placed_size", o.placed_size,
                    "a box read as a placed text is held to its painted size (DB's margin)",
                    [&](ocr::PlacedSizeOptions& p) { describe(v, p); });
}

void describe(OptionVisitor& v, ocr::ReadingOptions& o) {
  v.value("max_crop_width", o.max_crop_width, "recognizer crops at most this wide (squeezed)");
  v.value("batch_size", o.batch_size, "crops per recognizer run");
  v.choice("direction", o.direction,
           {{"decode_both", ocr::DirectionMode::kDecodeBoth},
            {"classifier", ocr::DirectionMode::kClassifier}},
           "which way round a crop reads");
  v.value("direction_confident", o.direction_confident,
          "direction classifier probability above which one crop suffices");
  v.section("lexicon", "decoding against the map's texts, for a box without a placed prior",
            [&] { describe(v, o.lexicon); });
  v.value("alphabet", o.alphabet,
          "a free reading keeps only these characters and the lexicon's (\"\": all classes)");
  v.value("min_text_confidence", o.min_text_confidence,
          "free readings less confident than this are not text");
  v.value("reread_margins", o.reread_margins,
          "an unmatched placed box is read again from crops grown by these (along, across)");
  v.value("reread_by_fallback_only", o.reread_by_fallback_only,
          "... by the second recognizer alone: the first already failed on that box");
}

void describe(OptionVisitor& v, ocr::CornerRefinementOptions& o) {
  v.value("crop_height", o.crop_height, "rectified crop height used to find the ink, pixels");
  v.value("search_expand_x", o.search_expand_x,
          "ink is looked for in the box grown by this along the text (DB boxes cut glyphs)");
  v.value("search_expand_y", o.search_expand_y, "... and by this across it");
  v.value("max_ground_height", o.max_ground_height, "metres; taller text is not floor text");
  v.value("max_ground_width", o.max_ground_width, "metres; longer text is not floor text");
  v.value("denoise_sigma_raw_px", o.denoise_sigma_raw_px,
          "smoothing in raw pixels before thresholding: sensor noise is per raw pixel");
  v.value("min_contrast", o.min_contrast, "ink and floor differ by at least this, grey levels");
  v.value("colour_fallback", o.colour_fallback,
          "where grey levels find no text, ink is what lies far from the floor's colour");
  v.value("min_length_share", o.min_length_share,
          "a fit shorter than this share of its box lost part of the text: box kept");
  v.value("frames", o.frames, "text inside a painted frame: fit the glyphs, not the frame");
  v.value("patches", o.patches, "text on a patch of colour: fit the glyphs, not the patch");
}

void describe(OptionVisitor& v, ocr::TrackedFitOptions& o) {
  v.value("search_expand_x", o.search_expand_x,
          "the predicted box is searched for ink within this multiple of its length");
  v.value("search_expand_y", o.search_expand_y, "... and its height");
  v.value("min_width_ratio", o.min_width_ratio, "fitted over predicted width, at least");
  v.value("max_width_ratio", o.max_width_ratio, "... at most");
  v.value("min_height_ratio", o.min_height_ratio, "fitted over predicted height, at least");
  v.value("max_height_ratio", o.max_height_ratio, "... at most");
  v.value("max_centre_shift", o.max_centre_shift,
          "the fit's centre may be off the prediction by this share of its width");
  v.value("crop_height", o.crop_height, "rectified crop height, pixels");
}

void describe(OptionVisitor& v, ocr::RegionOptions& o) {
  v.value("expand_x", o.expand_x,
          "a searched region spans at least this multiple of its text's length (pose error)");
  v.value("expand_y", o.expand_y, "... and of its height");
  v.value("patch_width", o.patch.width, "the region is warped to a patch this wide, pixels");
  v.value("patch_height", o.patch.height, "... and this tall");
  v.value("read_at_prediction", o.read_at_prediction,
          "a region with a predicted polygon is read there without detection");
  v.value("prediction_expand_x", o.prediction_expand_x,
          "... from the prediction grown by this along the text");
  v.value("prediction_expand_y", o.prediction_expand_y, "... and by this across it");
  v.section("tracked_fit", "regions only fitted to their ink, not read",
            [&] { describe(v, o.tracked_fit); });
}

}  // namespace

void describe(OptionVisitor& v, ocr::PpOcrOptions& o) {
  v.section("onnx", "ONNX Runtime's thread pools", [&] {
    v.value("intra_op_threads", o.onnx.intra_op_threads, "threads inside one operator");
    v.value("inter_op_threads", o.onnx.inter_op_threads, "operators run at once");
  });
  v.section("detection", "which detector looks where, and its post-processing",
            [&] { describe(v, o.detection); });
  v.section("map_prior", "what the map says about a floor box under a predicted pose",
            [&] { describe(v, o.map_prior); });
  v.section("reading", "the recognizers' cascade and lexicon decoding",
            [&] { describe(v, o.reading); });
  v.section("corners", "the corner fit to the ink", [&] {
    v.value("refine", o.corners.refine, "fit the corners to the ink; false: the box as detected");
    describe(v, o.corners.fit);
  });
  v.section("regions", "map-guided regions", [&] { describe(v, o.regions); });
}

}  // namespace parkloc::config
