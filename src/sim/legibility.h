#pragma once
// Whether a reader could read a text in a rendered image: the labels' "legible" flag.
// Size alone is not enough: a number seen edge-on along its reading direction has tall glyphs
// squeezed into a few pixels each, and a side camera's motion blur smears glyphs narrower
// than its length into one bar. The rule asks that the image carry the spatial frequencies
// reading needs: about 2 cycles per character (Legge, Pelli, Rubin and Schleske, "Psychophysics
// of reading I", Vision Research 1985: reading speed is unimpaired once text passes 2 cycles
// per character), along the reading direction per character pitch and across it per glyph
// height, below the pixel grid's Nyquist limit and not damped by the camera's blur below
// the usual limiting-resolution modulation of 10 %. Nor is size enough when the ink hardly
// differs from the ground: worn paint in weak light drowns in the sensor's noise, which the
// contrast rule (inkStandsOut) asks of painted floor text.
#include <cmath>
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
  // The contrast rule (inkStandsOut): Rose's criterion, a feature is seen when its signal
  // over the noise integrated on its area reaches about 5 (A. Rose, "The sensitivity
  // performance of the human eye on an absolute scale", JOSA 1948; the usual k = 5).
  double min_feature_snr = 5.0;
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

// The contrast a text's ink makes in the image and the sensor's noise, both before the blur.
struct InkContrast {
  double luma_levels = 0.0;    // ink against the ground under it, 8-bit luma
  double channel_noise = 0.0;  // Gaussian noise per colour channel, 8-bit levels
  // Error in luma levels that is the same over a whole reading feature, as a video codec's
  // 8x8 blocks are: summing over the feature's pixels does not average it down.
  double block_noise = 0.0;
};

// The standard deviation of BT.601 luma (0.299 R + 0.587 G + 0.114 B) per unit of independent
// noise of equal variance in each colour channel.
inline const double kLumaNoisePerChannelNoise =
    std::sqrt(0.299 * 0.299 + 0.587 * 0.587 + 0.114 * 0.114);

// The signal-to-noise ratio of one reading feature of the text: half a cycle of
// `cycles_per_character` along the reading direction by half a cycle across the glyph height
// (the same features the size rule asks the image to carry), its ink contrast summed over its
// pixels against white noise, the noise of BT.601 luma from independent channels, and the
// block noise summed over the same pixels without averaging.
double featureSnr(const geometry::TextPolygon& polygon, int characters, const InkContrast& ink,
                  const LegibilityOptions& options = {});

// Whether the ink stands out of the noise by Rose's criterion: featureSnr >= min_feature_snr.
// Worn paint in a dim corner of a noisy image fails it, however large the text: no reader
// reads what does not show. Blur is the size rule's part (isLegible).
bool inkStandsOut(const geometry::TextPolygon& polygon, int characters, const InkContrast& ink,
                  const LegibilityOptions& options = {});

// Characters of a UTF-8 text (code points), at least 1.
int characterCount(const std::string& text);

}  // namespace parkloc::sim
