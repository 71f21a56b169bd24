#include "sim/appearance.h"

#include <stdexcept>

#include "common/error.h"

namespace parkloc::sim {
namespace {

struct Field {
  const char* name;
  float AppearanceOptions::*member;
  bool garage;  // changes the garage, not only the camera
};

const Field kFields[] = {
    {"floor_wear", &AppearanceOptions::floor_wear, true},
    {"gloss", &AppearanceOptions::gloss, true},
    {"epoxy", &AppearanceOptions::epoxy, true},
    {"stencil", &AppearanceOptions::stencil, true},
    {"outlined", &AppearanceOptions::outlined, true},
    {"boxed", &AppearanceOptions::boxed, true},
    {"faded", &AppearanceOptions::faded, true},
    {"auto_exposure", &AppearanceOptions::auto_exposure, false},
    {"white_balance", &AppearanceOptions::white_balance, false},
    {"hdr_clipping", &AppearanceOptions::hdr_clipping, false},
    {"lens_dirt", &AppearanceOptions::lens_dirt, false},
    {"flare", &AppearanceOptions::flare, false},
    {"compression", &AppearanceOptions::compression, false},
};

const Field& field(const std::string& name) {
  for (const Field& f : kFields)
    if (name == f.name) return f;
  throw std::invalid_argument("unknown appearance factor '" + name + "'");
}

}  // namespace

const std::vector<std::string>& appearanceFactorNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const Field& f : kFields) out.emplace_back(f.name);
    return out;
  }();
  return names;
}

float& appearanceFactor(AppearanceOptions& options, const std::string& name) {
  return options.*(field(name).member);
}

float appearanceFactor(const AppearanceOptions& options, const std::string& name) {
  return options.*(field(name).member);
}

std::string AppearanceOptions::subset() const {
  std::string joined;
  int on = 0;
  for (const Field& f : kFields) {
    if (this->*(f.member) <= 0.0f) continue;
    ++on;
    joined += (joined.empty() ? "" : "+") + std::string(f.name);
  }
  if (on == 0) return "clean";
  if (on == static_cast<int>(std::size(kFields))) return "realistic";
  return joined;
}

bool AppearanceOptions::any() const {
  for (const Field& f : kFields)
    if (this->*(f.member) > 0.0f) return true;
  return false;
}

bool AppearanceOptions::changesGarage() const {
  for (const Field& f : kFields)
    if (f.garage && this->*(f.member) > 0.0f) return true;
  return false;
}

bool AppearanceOptions::changesCamera() const {
  for (const Field& f : kFields)
    if (!f.garage && this->*(f.member) > 0.0f) return true;
  return false;
}

AppearanceOptions appearancePreset(const std::string& name, const std::string& where) {
  AppearanceOptions options;
  if (name == "clean") return options;
  if (name == "realistic") {
    // Every factor on, each as a garage that has it shows it. The floor's finish and the
    // camera's effects at full size; the number styles, which are shares of the numbers, as a
    // garage mixes them (at a share of 1 every number would be stencilled, boxed and faded at
    // once, and 17 % of the val drive's numbers would be legible: no garage looks like that);
    // the codec at half size, JPEG at about quality 37, a car camera's stream at a moderate
    // bit rate (at quality 15 a quarter of the numbers stay legible).
    for (const Field& f : kFields) options.*(f.member) = 1.0f;
    options.stencil = 0.5f;
    options.outlined = 0.2f;
    options.boxed = 0.5f;
    options.faded = 0.25f;
    options.compression = 0.5f;
    return options;
  }
  throw InputError(where +
                   ": field 'appearance' must be clean, realistic or a mapping of "
                   "factors, not '" +
                   name + "'");
}

}  // namespace parkloc::sim
