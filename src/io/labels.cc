#include "io/labels.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "common/error.h"

namespace parkloc::io {
namespace {

using nlohmann::json;

// ICDAR-2015 marks text that a detector may miss without penalty as "###".
constexpr double kIgnoreOccludedFraction = 0.5;

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError(fmt::format("labels {}: {}", path, what));
}

const json& field(const json& obj, const char* key, const std::string& path,
                  const std::string& where) {
  const auto it = obj.find(key);
  if (it == obj.end()) fail(path, fmt::format("{}missing field '{}'", where, key));
  return *it;
}

double number(const json& obj, const char* key, const std::string& path, const std::string& where) {
  const json& v = field(obj, key, path, where);
  if (!v.is_number())
    fail(path, fmt::format("{}field '{}': expected a number, got {}", where, key, v.type_name()));
  return v.get<double>();
}

std::string string(const json& obj, const char* key, const std::string& path,
                   const std::string& where) {
  const json& v = field(obj, key, path, where);
  if (!v.is_string())
    fail(path, fmt::format("{}field '{}': expected a string, got {}", where, key, v.type_name()));
  return v.get<std::string>();
}

// An image width or height: a number that fits an int (casting 1e300 to int is undefined
// behaviour; found by fuzz/fuzz_labels).
int imageSize(const json& doc, const char* key, const std::string& path) {
  const double value = number(doc, key, path, "");
  if (!(value >= 0.0 && value <= std::numeric_limits<int>::max()))
    fail(path, fmt::format("field '{}': {} is not an image size", key, value));
  return static_cast<int>(value);
}

geometry::TextPolygon readPolygon(const json& polygon, const char* key, const std::string& path,
                                  const std::string& where) {
  if (!polygon.is_array() || polygon.size() != 4)
    fail(path, fmt::format("{}field '{}': expected 4 [x, y] points", where, key));
  geometry::TextPolygon out;
  for (size_t k = 0; k < 4; ++k) {
    const json& p = polygon[k];
    if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
      fail(path, fmt::format("{}field '{}': point {} is not [x, y]", where, key, k));
    out[k] = {p[0].get<double>(), p[1].get<double>()};
    if (!out[k].allFinite())
      fail(path, fmt::format("{}field '{}': point {} is not finite", where, key, k));
  }
  return out;
}

LabelInstance readInstance(const json& j, const std::string& path, size_t index) {
  const std::string where = fmt::format("instance #{}: ", index);
  if (!j.is_object()) fail(path, where + "expected an object");
  LabelInstance inst;
  inst.polygon = readPolygon(field(j, "polygon", path, where), "polygon", path, where);
  inst.text = string(j, "text", path, where);
  const std::string cls = string(j, "class", path, where);
  const auto parsed = map::textClassFromString(cls);
  if (!parsed) fail(path, fmt::format("{}field 'class': unknown class '{}'", where, cls));
  inst.cls = *parsed;
  if (j.contains("occluded_fraction"))
    inst.occluded_fraction = number(j, "occluded_fraction", path, where);
  if (j.contains("truncated")) {
    if (!j["truncated"].is_boolean()) fail(path, where + "field 'truncated': expected a boolean");
    inst.truncated = j["truncated"].get<bool>();
  }
  if (j.contains("legible")) {
    if (!j["legible"].is_boolean()) fail(path, where + "field 'legible': expected a boolean");
    inst.legible = j["legible"].get<bool>();
  }
  if (j.contains("landmark_id")) inst.landmark_id = string(j, "landmark_id", path, where);
  if (j.contains("rotation_deg")) inst.rotation_deg = number(j, "rotation_deg", path, where);
  if (j.contains("visible_polygon"))
    inst.visible_polygon = readPolygon(j["visible_polygon"], "visible_polygon", path, where);
  if (j.contains("paint_wear")) {
    inst.paint_wear = number(j, "paint_wear", path, where);
    if (!(inst.paint_wear >= 0.0 && inst.paint_wear <= 1.0))
      fail(path, fmt::format("{}field 'paint_wear': expected a number in [0, 1], got {}", where,
                             inst.paint_wear));
  }
  if (j.contains("ink_snr")) {
    inst.ink_snr = number(j, "ink_snr", path, where);
    if (!(*inst.ink_snr >= 0.0))
      fail(path,
           fmt::format("{}field 'ink_snr': expected a number >= 0, got {}", where, *inst.ink_snr));
  }
  return inst;
}

json polygonJson(const geometry::TextPolygon& polygon) {
  json out = json::array();
  for (const auto& p : polygon) out.push_back({p.x(), p.y()});
  return out;
}

}  // namespace

ImageLabels loadLabels(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(fmt::format("labels {}: cannot open file", path));
  std::ostringstream text;
  text << in.rdbuf();
  json doc;
  try {
    doc = json::parse(text.str());
  } catch (const json::parse_error& e) {
    fail(path, fmt::format("malformed JSON at byte {}", e.byte));
  } catch (const json::exception& e) {
    // A number too large for a double ("1e400") is out_of_range, not parse_error (found by
    // fuzz/fuzz_labels).
    fail(path, fmt::format("malformed JSON ({})", e.what()));
  }
  if (!doc.is_object()) fail(path, "expected a JSON object");
  ImageLabels labels;
  labels.camera = string(doc, "camera", path, "");
  labels.timestamp = number(doc, "timestamp", path, "");
  labels.width = imageSize(doc, "width", path);
  labels.height = imageSize(doc, "height", path);
  const json& instances = field(doc, "instances", path, "");
  if (!instances.is_array()) fail(path, "field 'instances': expected an array");
  for (size_t i = 0; i < instances.size(); ++i)
    labels.instances.push_back(readInstance(instances[i], path, i));
  return labels;
}

void saveLabels(const ImageLabels& labels, const std::string& path) {
  json instances = json::array();
  for (const LabelInstance& inst : labels.instances) {
    json instance = {{"polygon", polygonJson(inst.polygon)},
                     {"text", inst.text},
                     {"class_id", static_cast<int>(inst.cls)},
                     {"class", map::toString(inst.cls)},
                     {"occluded_fraction", inst.occluded_fraction},
                     {"truncated", inst.truncated},
                     {"legible", inst.legible},
                     {"landmark_id", inst.landmark_id},
                     {"rotation_deg", inst.rotation_deg},
                     {"paint_wear", inst.paint_wear}};
    if (inst.visible_polygon) instance["visible_polygon"] = polygonJson(*inst.visible_polygon);
    if (inst.ink_snr) instance["ink_snr"] = *inst.ink_snr;
    instances.push_back(std::move(instance));
  }
  const json doc = {{"camera", labels.camera},
                    {"timestamp", labels.timestamp},
                    {"width", labels.width},
                    {"height", labels.height},
                    {"instances", std::move(instances)}};
  std::ofstream out(path, std::ios::binary);
  if (!out) throw IoError(fmt::format("labels {}: cannot open for writing", path));
  out << doc.dump(1) << "\n";
  if (!out) throw IoError(fmt::format("labels {}: write failed", path));
}

void saveIcdarLabels(const ImageLabels& labels, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw IoError(fmt::format("labels {}: cannot open for writing", path));
  for (const LabelInstance& inst : labels.instances) {
    for (const auto& p : inst.visible_polygon ? *inst.visible_polygon : inst.polygon)
      out << std::lround(p.x()) << ',' << std::lround(p.y()) << ',';
    const bool ignore = inst.occluded_fraction >= kIgnoreOccludedFraction || !inst.legible;
    out << (ignore ? std::string("###") : inst.text) << "\n";
  }
  if (!out) throw IoError(fmt::format("labels {}: write failed", path));
}

}  // namespace parkloc::io
