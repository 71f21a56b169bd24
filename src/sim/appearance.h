#pragma once
// How a drive's garage and camera look beyond the plain render: the wear and finish of the
// floor, the styles of the painted numbers and the camera's own effects. Each factor is one
// switch with a strength in [0, 1] (0: off, the plain render untouched), so an evaluation can
// say what each one costs. The plain render is the "clean" look; every factor on is
// "realistic". See docs/DATASET.md for the scenario keys.
#include <string>
#include <vector>

namespace parkloc::sim {

struct AppearanceOptions {
  // The floor (sim/floor_wear.h, sim/floor_finish.h).
  float floor_wear = 0.0f;  // tyre streaks, oil stains, repair patches, cracks: their density
  float gloss = 0.0f;       // wet or sealed sheen mirroring the ceiling lamps: its strength
  float epoxy = 0.0f;       // a coloured epoxy coating: how little concrete shows through it
  // The painted numbers (sim/number_styles.h): the share of numbers drawn in each style.
  float stencil = 0.0f;   // stencil glyphs, their strokes cut by bridges
  float outlined = 0.0f;  // hollow glyphs, only their outline painted
  float boxed = 0.0f;     // inside a painted frame or on a coloured patch
  float faded = 0.0f;     // paint worn down, some numbers past reading
  // The camera (sim/camera_effects.h): the size of each effect.
  float auto_exposure = 0.0f;  // exposure hunting from frame to frame
  float white_balance = 0.0f;  // a colour cast of the lamps the camera does not remove
  float hdr_clipping = 0.0f;   // highlights clipped, shadows crushed by a steep tone curve
  float lens_dirt = 0.0f;      // smudges and drops on the lens
  float flare = 0.0f;          // veiling glare and ghosts around lamps in view
  float compression = 0.0f;    // the video codec's 8x8 blocks at a low bit rate

  // The subset a drive with these options belongs to: "clean" with none on, "realistic"
  // with all on, else the factors on joined by '+' ("floor_wear+gloss").
  std::string subset() const;
  bool any() const;
  // Whether a factor changes the garage (floor, numbers) rather than only the camera.
  bool changesGarage() const;
  bool changesCamera() const;
};

// The factors' names as the scenario writes them, in the order above.
const std::vector<std::string>& appearanceFactorNames();
// The value of factor `name` (one of appearanceFactorNames()), mutable.
float& appearanceFactor(AppearanceOptions& options, const std::string& name);
float appearanceFactor(const AppearanceOptions& options, const std::string& name);

// A named look: "clean" (every factor 0) or "realistic" (every factor on: the floor and the
// camera at full size, half the numbers stencilled, a fifth outlined, half boxed, a quarter
// faded, the codec at half size); throws InputError
// naming `where` for any other name.
AppearanceOptions appearancePreset(const std::string& name, const std::string& where);

}  // namespace parkloc::sim
