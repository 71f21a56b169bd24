#pragma once
// Whether a reader could read a text in a rendered image: the labels' "legible" flag.
// Size alone is not enough: a number seen edge-on along its reading direction has tall glyphs
// squeezed into a few pixels each, and a side camera's motion blur smears glyphs narrower
// than its length into one bar. The rule asks that the image carry the spatial frequencies
// reading needs: about 2 cycles per character (Legge, Pelli, Rubin and Schleske, "Psychophysics
// of reading I", Vision Research 1985: reading speed is unimpaired once text passes 2 cycles
// per character), along the reading direction per character pitch and across it per glyph
// height, below the pixel grid's Nyquist limit and not damped by the camera's blur below
// the usual limiting-resolution modulation of 10 %.
#include <string>

#include "geometry/rig.h"
#include "geometry/text_polygon.h"

namespace parkloc::sim {

struct LightingOptions;

// The renderer's blur of one camera's images: Gaussian defocus, then a horizontal box of
// `motion_length_px` pixels (0: none).
struct ImageBlur {
  double defocus_sigma_px = 0.0;
  double motion_length_px = 0.0;
};

// The blur the renderer applies to `camera`'s images under `light`: side cameras see the
// scene sweep past, front and rear cameras a third of that.
ImageBlur imageBlur(const LightingOptions& light, const geometry::RigCamera& camera);

struct LegibilityOptions {
  // Below this apparent height (area over reading length) no text is read, however sharp.
  double min_height_px = 8.0;
  double cycles_per_character = 2.0;
  double min_modulation = 0.1;
};

// The image's modulation (0..1) of a sine of `cycles_per_px` along the image `direction`
// after the blur: the Gaussian's response times the motion box's discrete one, up to the box's
// first zero (0 beyond it), and 0 above the Nyquist limit of 0.5 cycles per pixel.
double blurModulation(const ImageBlur& blur, const Eigen::Vector2d& direction,
                      double cycles_per_px);

// The rule above for a text of `characters` characters whose image polygon is `polygon`
// (reading order: top-left, top-right, bottom-right, bottom-left).
bool isLegible(const geometry::TextPolygon& polygon, int characters, const ImageBlur& blur,
               const LegibilityOptions& options = {});

// Characters of a UTF-8 text (code points), at least 1.
int characterCount(const std::string& text);

}  // namespace parkloc::sim
