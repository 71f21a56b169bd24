#include "sim/scenario.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/error.h"

namespace parkloc::sim {
namespace {

const char* const kFontDirs[] = {"/usr/share/fonts/truetype/dejavu",
                                 "/usr/share/fonts/truetype/liberation",
                                 "/usr/share/fonts/truetype/freefont"};

template <typename T>
void read(const YAML::Node& node, const char* key, T& value, const std::string& where) {
  const YAML::Node child = node[key];
  if (!child) return;
  try {
    value = child.as<T>();
  } catch (const YAML::Exception&) {
    throw InputError(where + ": field '" + key + "' has an invalid value '" + YAML::Dump(child) +
                     "'");
  }
}

// An `appearance` entry: a preset name ("clean", "realistic") or a mapping of factors, each
// true / false or a strength in [0, 1], over `base` (what the garage says).
AppearanceOptions parseAppearance(const YAML::Node& node, const AppearanceOptions& base,
                                  const std::string& where) {
  if (node.IsScalar()) return appearancePreset(node.as<std::string>(), where);
  if (!node.IsMap())
    throw InputError(where + ": field 'appearance' must be a preset name or a mapping");
  AppearanceOptions out = base;
  const auto& names = appearanceFactorNames();
  for (const auto& entry : node) {
    const std::string key = entry.first.as<std::string>();
    if (std::find(names.begin(), names.end(), key) == names.end())
      throw InputError(where + ": unknown appearance key '" + key + "'");
    const YAML::Node& value = entry.second;
    double strength = 0.0;
    bool flag = false;
    if (YAML::convert<bool>::decode(value, flag)) {
      strength = flag ? 1.0 : 0.0;
    } else if (!YAML::convert<double>::decode(value, strength)) {
      throw InputError(where + ": appearance key '" + key + "' has an invalid value '" +
                       YAML::Dump(value) + "'");
    }
    if (!(strength >= 0.0 && strength <= 1.0))
      throw InputError(where + ": appearance key '" + key + "' out of range (0 to 1)");
    appearanceFactor(out, key) = static_cast<float>(strength);
  }
  return out;
}

DriveSpec parseDrive(const YAML::Node& node, const AppearanceOptions& appearance,
                     const std::string& where) {
  // yaml-cpp throws its own exceptions when a scalar is indexed like a mapping.
  if (!node.IsMap()) throw InputError(where + ": expected a mapping");
  DriveSpec d;
  d.appearance = appearance;
  if (const YAML::Node a = node["appearance"]) d.appearance = parseAppearance(a, appearance, where);
  read(node, "route", d.route, where);
  read(node, "condition", d.condition, where);
  read(node, "level", d.level, where);
  read(node, "duration_s", d.duration_s, where);
  read(node, "to_level", d.to_level, where);
  read(node, "transition_s", d.transition_s, where);
  read(node, "transition_at_s", d.transition_at_s, where);
  read(node, "repeat_of", d.repeat_of, where);
  read(node, "camera_jitter_s", d.camera_jitter_s, where);
  if (const YAML::Node delays = node["camera_delay_s"]) {
    if (!delays.IsMap())
      throw InputError(where + ": field 'camera_delay_s' must map cameras to seconds");
    for (const auto& item : delays) {
      const std::string camera = item.first.as<std::string>();
      double delay = 0.0;
      try {
        delay = item.second.as<double>();
      } catch (const YAML::Exception&) {
        throw InputError(where + ": camera_delay_s '" + camera + "' is not a number");
      }
      if (!(delay >= 0.0 && delay <= 0.1))
        throw InputError(where + ": camera_delay_s '" + camera + "' out of range (0 to 0.1 s)");
      d.camera_delay_s[camera] = delay;
    }
  }
  if (!(d.camera_jitter_s >= 0.0 && d.camera_jitter_s <= 0.02))
    throw InputError(where + ": field 'camera_jitter_s' out of range (0 to 0.02 s)");
  if (d.route != "tour" && d.route != "park")
    throw InputError(where + ": field 'route' must be tour or park, not '" + d.route + "'");
  if (d.condition != "bright" && d.condition != "weak" && d.condition != "blur")
    throw InputError(where + ": field 'condition' must be bright, weak or blur, not '" +
                     d.condition + "'");
  if (!(d.duration_s > 0.0 && d.duration_s < 3600.0))
    throw InputError(where + ": field 'duration_s' out of range");
  if (!(d.transition_s >= 0.5 && d.transition_s <= 60.0))
    throw InputError(where + ": field 'transition_s' out of range (0.5 to 60 s)");
  if (!std::isfinite(d.transition_at_s))
    throw InputError(where + ": field 'transition_at_s' out of range");
  if (!d.to_level.empty()) {
    // A park route's slot and manoeuvre belong to one level's parked cars.
    if (d.route != "tour")
      throw InputError(where + ": field 'to_level' needs route tour, not '" + d.route + "'");
    if (d.to_level == d.level)
      throw InputError(where + ": field 'to_level' is the drive's own level '" + d.level + "'");
    const double ramp_start =
        d.transition_at_s < 0.0 ? 0.5 * (d.duration_s - d.transition_s) : d.transition_at_s;
    if (!(ramp_start > 0.0 && ramp_start + d.transition_s < d.duration_s))
      throw InputError(where + ": the ramp (transition_at_s, transition_s) does not fit in " +
                       "duration_s");
  }
  return d;
}

GarageSpec parseGarage(const YAML::Node& node, const GarageSpec& defaults,
                       const std::string& where) {
  if (!node.IsMap()) throw InputError(where + ": expected a mapping");
  GarageSpec g = defaults;
  read(node, "name", g.name, where);
  read(node, "split", g.split, where);
  read(node, "levels", g.levels, where);
  read(node, "aisles", g.aisles, where);
  read(node, "slots_per_row", g.slots_per_row, where);
  read(node, "slots_per_pillar", g.slots_per_pillar, where);
  read(node, "slot_width", g.slot_width, where);
  read(node, "slot_depth", g.slot_depth, where);
  read(node, "aisle_width", g.aisle_width, where);
  read(node, "ceiling_height", g.ceiling_height, where);
  read(node, "pillar_size", g.pillar_size, where);
  read(node, "number_height", g.number_height, where);
  read(node, "occupancy", g.occupancy, where);
  read(node, "worn_share", g.worn_share, where);
  read(node, "yellow_share", g.yellow_share, where);
  read(node, "first_number", g.first_number, where);
  read(node, "fonts", g.fonts, where);
  read(node, "level_signs", g.level_signs, where);
  if (const YAML::Node a = node["appearance"])
    g.appearance = parseAppearance(a, g.appearance, where);
  if (node["numbering"]) {
    std::string scheme;
    read(node, "numbering", scheme, where);
    g.numbering = numberingSchemeFromString(scheme);
  }
  if (const YAML::Node drives = node["drives"]) {
    if (!drives.IsSequence()) throw InputError(where + ": field 'drives' must be a list");
    g.drives.clear();
    for (size_t i = 0; i < drives.size(); ++i)
      g.drives.push_back(
          parseDrive(drives[i], g.appearance, where + " drive " + std::to_string(i)));
  }
  for (size_t i = 0; i < g.drives.size(); ++i) {
    DriveSpec& d = g.drives[i];
    if (d.repeat_of < 0) continue;
    if (static_cast<size_t>(d.repeat_of) >= i || g.drives[d.repeat_of].repeat_of >= 0)
      throw InputError(where + " drive " + std::to_string(i) +
                       ": field 'repeat_of' must name an earlier drive of its own");
    DriveSpec copy = g.drives[d.repeat_of];
    copy.appearance = d.appearance;
    copy.camera_delay_s = d.camera_delay_s;
    copy.camera_jitter_s = d.camera_jitter_s;
    copy.repeat_of = d.repeat_of;
    d = copy;
  }
  if (node["appearance"] && !node["drives"])
    for (DriveSpec& d : g.drives) d.appearance = g.appearance;
  if (g.split != "train" && g.split != "val" && g.split != "test")
    throw InputError(where + ": field 'split' must be train, val or test, not '" + g.split + "'");
  if (g.levels.empty()) throw InputError(where + ": field 'levels' is empty");
  if (g.aisles < 1 || g.aisles > 20) throw InputError(where + ": field 'aisles' out of range");
  if (g.slots_per_row < 3 || g.slots_per_row > 200)
    throw InputError(where + ": field 'slots_per_row' out of range");
  if (g.slots_per_pillar < 1) throw InputError(where + ": field 'slots_per_pillar' out of range");
  if (!(g.number_height >= 0.1 && g.number_height <= 1.0))
    throw InputError(where + ": field 'number_height' out of range");
  if (!(g.occupancy >= 0.0 && g.occupancy <= 1.0))
    throw InputError(where + ": field 'occupancy' out of range");
  if (!(g.ceiling_height >= 2.2 && g.ceiling_height <= 6.0))
    throw InputError(where + ": field 'ceiling_height' out of range");
  if (!(g.aisle_width >= 4.0 && g.slot_width >= 2.0 && g.slot_depth >= 4.5))
    throw InputError(where + ": aisle or slot too small");
  if (g.fonts.empty()) throw InputError(where + ": field 'fonts' is empty");
  for (const auto& f : g.fonts) resolveFontPath(f);
  if (g.drives.empty()) throw InputError(where + ": no drives");
  for (size_t i = 0; i < g.drives.size(); ++i) {
    const std::string& to = g.drives[i].to_level;
    if (!to.empty() && std::find(g.levels.begin(), g.levels.end(), to) == g.levels.end())
      throw InputError(where + " drive " + std::to_string(i) + ": field 'to_level' '" + to +
                       "' is not one of the garage's levels");
  }
  return g;
}

GarageSpec makeGarage(const std::string& name, const std::string& split,
                      std::vector<std::string> levels, int aisles, int slots,
                      NumberingScheme numbering, int first_number, double number_height,
                      std::vector<std::string> fonts, std::vector<DriveSpec> drives) {
  GarageSpec g;
  g.name = name;
  g.split = split;
  g.levels = std::move(levels);
  g.aisles = aisles;
  g.slots_per_row = slots;
  g.numbering = numbering;
  g.first_number = first_number;
  g.number_height = number_height;
  g.fonts = std::move(fonts);
  g.drives = std::move(drives);
  return g;
}

}  // namespace

std::string toString(NumberingScheme scheme) {
  switch (scheme) {
    case NumberingScheme::kThreeDigit:
      return "three_digit";
    case NumberingScheme::kPlain:
      return "plain";
    case NumberingScheme::kLevelDash:
      return "level_dash";
    case NumberingScheme::kZoneLetter:
      return "zone_letter";
  }
  return "three_digit";
}

NumberingScheme numberingSchemeFromString(const std::string& name) {
  if (name == "three_digit") return NumberingScheme::kThreeDigit;
  if (name == "plain") return NumberingScheme::kPlain;
  if (name == "level_dash") return NumberingScheme::kLevelDash;
  if (name == "zone_letter") return NumberingScheme::kZoneLetter;
  throw InputError(
      "scenario: field 'numbering' must be three_digit, plain, level_dash or "
      "zone_letter, not '" +
      name + "'");
}

std::string resolveFontPath(const std::string& font) {
  namespace fs = std::filesystem;
  // The error_code overload: a name the file system cannot take (too long, say) is just a
  // font that is not there (fuzz finding 13).
  std::error_code ec;
  if (font.find('/') != std::string::npos) {
    if (fs::exists(font, ec)) return font;
  } else {
    for (const char* dir : kFontDirs) {
      const fs::path p = fs::path(dir) / font;
      if (fs::exists(p, ec)) return p.string();
    }
  }
  throw InputError("scenario: font '" + font + "' not found (looked in /usr/share/fonts/truetype)");
}

Scenario defaultScenario() {
  using N = NumberingScheme;
  auto drive = [](const char* route, const char* condition) {
    return DriveSpec{route, condition, "", 12.0};
  };
  // A tour that goes down a ramp from `from` to `to` in the middle of the drive.
  auto levelChange = [](const char* from, const char* to, double duration, double ramp) {
    DriveSpec d{"tour", "bright", from, duration};
    d.to_level = to;
    d.transition_s = ramp;
    return d;
  };
  Scenario s;
  s.name = "default";
  s.seed = 2026;
  // Train and val share schemes three_digit / level_dash / plain and sans fonts; test uses
  // zone_letter numbers and serif / mono fonts that train never sees. Every split has every
  // condition; the test garage has one drive per condition and a drive that changes level.
  s.garages = {
      makeGarage("g01", "train", {"B1", "B2"}, 2, 15, N::kThreeDigit, 1, 0.45,
                 {"DejaVuSans-Bold.ttf", "LiberationSans-Bold.ttf"}, {drive("tour", "bright")}),
      makeGarage("g02", "train", {"B1"}, 3, 12, N::kLevelDash, 101, 0.40,
                 {"DejaVuSansCondensed-Bold.ttf"}, {drive("park", "weak")}),
      makeGarage("g03", "train", {"B2", "B3"}, 2, 18, N::kThreeDigit, 50, 0.55,
                 {"FreeSansBold.ttf", "LiberationSansNarrow-Bold.ttf"}, {drive("tour", "blur")}),
      makeGarage("g04", "train", {"P1"}, 2, 12, N::kLevelDash, 1, 0.35, {"LiberationSans-Bold.ttf"},
                 {drive("park", "bright")}),
      makeGarage("g05", "train", {"B1"}, 3, 15, N::kThreeDigit, 200, 0.50,
                 {"DejaVuSansMono-Bold.ttf", "DejaVuSans-Bold.ttf"}, {drive("tour", "weak")}),
      makeGarage("g06", "train", {"B1", "B2"}, 2, 15, N::kLevelDash, 1, 0.45,
                 {"LiberationMono-Bold.ttf", "FreeSansBold.ttf"}, {drive("park", "blur")}),
      makeGarage("g07", "train", {"L2"}, 2, 21, N::kThreeDigit, 300, 0.60,
                 {"DejaVuSansCondensed-Bold.ttf", "LiberationSansNarrow-Bold.ttf"},
                 {drive("tour", "bright")}),
      makeGarage("g08", "val", {"B1"}, 2, 15, N::kPlain, 100, 0.45,
                 {"DejaVuSans-Bold.ttf", "LiberationSans-Regular.ttf"},
                 {drive("tour", "bright"), drive("park", "blur")}),
      makeGarage("g09", "val", {"B2"}, 2, 12, N::kLevelDash, 1, 0.40, {"FreeSans.ttf"},
                 {drive("tour", "weak")}),
      makeGarage("g10", "test", {"B1", "B2"}, 2, 15, N::kZoneLetter, 1, 0.45,
                 {"LiberationSerif-Bold.ttf", "FreeMonoBold.ttf", "DejaVuSerif-Bold.ttf"},
                 {drive("tour", "bright"), drive("park", "weak"), drive("tour", "blur"),
                  levelChange("B1", "B2", 30.0, 3.0)}),
  };
  return s;
}

Scenario demoScenario() {
  Scenario s;
  s.name = "demo";
  s.seed = 7;
  s.garages = {makeGarage("demo", "test", {"B2"}, 2, 12, NumberingScheme::kLevelDash, 101, 0.45,
                          {"DejaVuSans-Bold.ttf"}, {DriveSpec{"tour", "bright", "", 30.0}})};
  return s;
}

Scenario parseScenario(const std::string& yaml_text, const std::string& source_name) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    throw InputError(source_name + ": malformed YAML: " + e.what());
  }
  if (!root.IsMap()) throw InputError(source_name + ": expected a mapping at the top level");
  Scenario s;
  read(root, "name", s.name, source_name);
  read(root, "seed", s.seed, source_name);
  read(root, "frame_rate", s.frame_rate, source_name);
  read(root, "odometry_rate", s.odometry_rate, source_name);
  read(root, "jpeg_quality", s.jpeg_quality, source_name);
  read(root, "legibility_on_image", s.legibility_on_image, source_name);
  read(root, "rig", s.rig, source_name);
  if (!(s.frame_rate >= 1.0 && s.frame_rate <= 60.0))
    throw InputError(source_name + ": field 'frame_rate' out of range");
  if (!(s.odometry_rate >= s.frame_rate && s.odometry_rate <= 1000.0))
    throw InputError(source_name + ": field 'odometry_rate' out of range");
  if (s.jpeg_quality < 10 || s.jpeg_quality > 100)
    throw InputError(source_name + ": field 'jpeg_quality' out of range");
  GarageSpec defaults;
  if (const YAML::Node d = root["garage_defaults"])
    defaults = parseGarage(d, defaults, source_name + " garage_defaults");
  const YAML::Node garages = root["garages"];
  if (!garages || !garages.IsSequence() || garages.size() == 0)
    throw InputError(source_name + ": field 'garages' missing or empty");
  for (size_t i = 0; i < garages.size(); ++i)
    s.garages.push_back(
        parseGarage(garages[i], defaults, source_name + " garage " + std::to_string(i)));
  // A reader forms frame sets from images within 0.45 frame periods of the pacing camera's
  // (io/frame_sets.h): the cameras' delays and jitter must stay inside that.
  for (size_t g = 0; g < s.garages.size(); ++g)
    for (size_t d = 0; d < s.garages[g].drives.size(); ++d) {
      const DriveSpec& drive = s.garages[g].drives[d];
      double spread = drive.camera_jitter_s;
      for (const auto& [camera, delay] : drive.camera_delay_s)
        spread = std::max(spread, delay + drive.camera_jitter_s);
      if (spread >= 0.4 / s.frame_rate)
        throw InputError(fmt::format(
            "{} garage {} drive {}: camera delays and jitter span {:.3f} s, more than 0.4 frame "
            "periods ({:.3f} s)",
            source_name, g, d, spread, 0.4 / s.frame_rate));
    }
  return s;
}

Scenario loadScenario(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw IoError("cannot open scenario file '" + path + "'");
  std::stringstream buffer;
  buffer << in.rdbuf();
  Scenario s = parseScenario(buffer.str(), path);
  if (!s.rig.empty() && std::filesystem::path(s.rig).is_relative())
    s.rig = (std::filesystem::path(path).parent_path() / s.rig).lexically_normal().string();
  return s;
}

}  // namespace parkloc::sim
