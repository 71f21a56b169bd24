#pragma once
// The ways real garages paint their parking numbers beyond a plain solid font: stencil glyphs
// whose strokes are cut by the bridges that hold a stencil together, outlined (hollow) glyphs,
// numbers inside a painted frame or on a coloured patch (blue, green, yellow, dark grey), and
// paint faded and worn down further than the plain render wears it. A styled number keeps its
// landmark: its ink box, text and map entry are unchanged; only its texture, colour and the
// decals beside it change.
#include <opencv2/core.hpp>
#include <random>

#include "sim/appearance.h"
#include "sim/garage.h"

namespace parkloc::sim {

// Cuts bridges into the glyphs of `coverage` (8-bit ink, glyphs side by side): at each glyph's
// centre column, every horizontal stroke (a run of ink well wider than the glyph's strokes)
// gets a gap about a tenth of the glyph's height wide, as a stencil's "0", "8" and "4" have.
void cutStencilBridges(cv::Mat& coverage);

// Keeps only the outline of the glyphs of `coverage`: the ink minus the ink eroded by about
// a quarter of the stroke width. The outer edge, and so the ink box, stays where it was.
void hollowOutGlyphs(cv::Mat& coverage);

// Restyles the parking numbers of every level with the shares of AppearanceOptions::stencil,
// outlined, boxed and faded, each number drawn independently.
void styleNumbers(Garage& garage, const AppearanceOptions& appearance, std::mt19937_64& rng);

}  // namespace parkloc::sim
