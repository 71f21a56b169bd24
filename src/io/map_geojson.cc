#include "io/map_geojson.h"

#include <fmt/format.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "common/error.h"

namespace parkloc::io {
namespace {

using nlohmann::json;

// The "type" member when it is a string, else "" (json::value would throw type_error 302 for
// a number; found by fuzz/fuzz_map).
std::string typeOf(const json& object) {
  const auto it = object.find("type");
  return it != object.end() && it->is_string() ? it->get<std::string>() : "";
}

class FeatureReader {
 public:
  FeatureReader(const std::string& source, size_t index, const json& feature)
      : source_(source), index_(index), feature_(feature) {}

  [[noreturn]] void fail(const std::string& what) const {
    const std::string who = id_.empty() ? fmt::format("feature #{}", index_)
                                        : fmt::format("feature #{} (id '{}')", index_, id_);
    throw InputError(fmt::format("map {}: {}: {}", source_, who, what));
  }

  const json& property(const json& props, const char* key) const {
    const auto it = props.find(key);
    if (it == props.end()) fail(fmt::format("missing property '{}'", key));
    return *it;
  }
  std::string stringProperty(const json& props, const char* key) const {
    const json& v = property(props, key);
    if (!v.is_string())
      fail(fmt::format("property '{}': expected a string, got {}", key, v.type_name()));
    return v.get<std::string>();
  }
  double numberProperty(const json& props, const char* key) const {
    const json& v = property(props, key);
    if (!v.is_number())
      fail(fmt::format("property '{}': expected a number, got {}", key, v.type_name()));
    return v.get<double>();
  }
  Eigen::Vector3d vectorOf(const json& v, const std::string& what, bool allow_2d) const {
    if (!v.is_array() || v.size() < (allow_2d ? 2u : 3u) || v.size() > 3)
      fail(fmt::format("{}: expected an array of {} numbers", what, allow_2d ? "2 or 3" : "3"));
    Eigen::Vector3d out = Eigen::Vector3d::Zero();
    for (size_t i = 0; i < v.size(); ++i) {
      if (!v[i].is_number())
        fail(fmt::format("{}: element {} is a {}, expected a number", what, i, v[i].type_name()));
      out[static_cast<int>(i)] = v[i].get<double>();
    }
    return out;
  }

  // The optional sigma properties; `fallback` (the map-wide default) where absent.
  map::MapAccuracy accuracyOf(const json& props, const map::MapAccuracy& fallback) const {
    map::MapAccuracy a = fallback;
    if (props.contains("position_sigma")) a.position_sigma = numberProperty(props, "position_sigma");
    if (props.contains("heading_sigma")) a.heading_sigma = numberProperty(props, "heading_sigma");
    if (const std::string problem = map::accuracyProblem(a); !problem.empty()) fail(problem);
    return a;
  }

  map::Landmark read(const map::MapAccuracy& map_accuracy) {
    if (!feature_.is_object()) fail("expected a JSON object");
    if (typeOf(feature_) != "Feature") fail("'type' must be \"Feature\"");
    const auto props_it = feature_.find("properties");
    if (props_it == feature_.end() || !props_it->is_object()) fail("missing 'properties' object");
    const json& props = *props_it;
    map::Landmark l;
    // The id first, so that later messages can name it.
    if (const auto id = props.find("id"); id != props.end() && id->is_string())
      id_ = id->get<std::string>();
    l.id = stringProperty(props, "id");

    const auto geometry = feature_.find("geometry");
    if (geometry == feature_.end() || !geometry->is_object()) fail("missing 'geometry' object");
    if (typeOf(*geometry) != "Point") fail("geometry: 'type' must be \"Point\"");
    const auto coordinates = geometry->find("coordinates");
    if (coordinates == geometry->end()) fail("geometry: missing 'coordinates'");
    l.position = vectorOf(*coordinates, "geometry 'coordinates'", true);

    l.text = stringProperty(props, "text");
    const std::string cls = stringProperty(props, "class");
    const auto text_class = map::textClassFromString(cls);
    if (!text_class)
      fail(
          fmt::format("property 'class': unknown class '{}' (parking_number, pillar, other)", cls));
    l.cls = *text_class;
    l.level = stringProperty(props, "level");
    l.heading = numberProperty(props, "heading");
    l.width = numberProperty(props, "width");
    l.height = numberProperty(props, "height");
    const std::string surface = stringProperty(props, "surface");
    const auto parsed_surface = map::surfaceFromString(surface);
    if (!parsed_surface)
      fail(fmt::format("property 'surface': unknown surface '{}' (ground, vertical)", surface));
    l.surface = *parsed_surface;
    if (l.surface == map::Surface::kVertical || props.contains("normal"))
      l.normal = vectorOf(property(props, "normal"), "property 'normal'", false);
    l.accuracy = accuracyOf(props, map_accuracy);
    return l;
  }

 private:
  const std::string& source_;
  size_t index_;
  const json& feature_;
  std::string id_;
};

// The FeatureCollection's own "properties": the map-wide accuracy its features default to.
map::MapAccuracy mapAccuracy(const json& doc, const std::string& source) {
  map::MapAccuracy a;
  const auto props = doc.find("properties");
  if (props == doc.end() || props->is_null()) return a;
  const auto fail = [&](const std::string& what) {
    throw InputError(fmt::format("map {}: map-wide properties: {}", source, what));
  };
  if (!props->is_object()) fail(fmt::format("expected an object, got {}", props->type_name()));
  for (const char* key : {"position_sigma", "heading_sigma"}) {
    const auto it = props->find(key);
    if (it == props->end()) continue;
    if (!it->is_number())
      fail(fmt::format("'{}': expected a number, got {}", key, it->type_name()));
    (std::string(key) == "position_sigma" ? a.position_sigma : a.heading_sigma) =
        it->get<double>();
  }
  if (const std::string problem = map::accuracyProblem(a); !problem.empty()) fail(problem);
  return a;
}

// The FeatureCollection's own "complete" (default true): whether the map holds every text of
// the area it covers.
bool mapComplete(const json& doc, const std::string& source) {
  const auto props = doc.find("properties");
  if (props == doc.end() || !props->is_object()) return true;
  const auto it = props->find("complete");
  if (it == props->end()) return true;
  if (!it->is_boolean())
    throw InputError(
        fmt::format("map {}: map-wide properties: 'complete': expected true or false, got {}",
                    source, it->type_name()));
  return it->get<bool>();
}

std::string stripJsonExceptionPrefix(const std::string& what) {
  // "[json.exception.parse_error.101] parse error at line 1, ..." -> "parse error at ..."
  const size_t close = what.find("] ");
  return close == std::string::npos ? what : what.substr(close + 2);
}

}  // namespace

map::HdMap parseMap(const std::string& geojson_text, const std::string& source_name) {
  json doc;
  try {
    doc = json::parse(geojson_text);
  } catch (const json::parse_error& e) {
    throw InputError(fmt::format("map {}: malformed JSON at byte {}: {}", source_name, e.byte,
                                 stripJsonExceptionPrefix(e.what())));
  } catch (const json::exception& e) {
    // A number too large for a double ("1e400") is out_of_range, not parse_error.
    throw InputError(
        fmt::format("map {}: malformed JSON: {}", source_name, stripJsonExceptionPrefix(e.what())));
  }
  if (!doc.is_object() || typeOf(doc) != "FeatureCollection")
    throw InputError(fmt::format("map {}: expected a GeoJSON FeatureCollection", source_name));
  const auto features = doc.find("features");
  if (features == doc.end() || !features->is_array())
    throw InputError(fmt::format("map {}: missing 'features' array", source_name));
  std::string name;
  if (const auto n = doc.find("name"); n != doc.end() && n->is_string())
    name = n->get<std::string>();
  const map::MapAccuracy accuracy = mapAccuracy(doc, source_name);

  std::vector<map::Landmark> landmarks;
  landmarks.reserve(features->size());
  std::map<std::string, size_t> first_index_of_id;
  for (size_t i = 0; i < features->size(); ++i) {
    landmarks.push_back(FeatureReader(source_name, i, (*features)[i]).read(accuracy));
    const auto [it, inserted] = first_index_of_id.emplace(landmarks.back().id, i);
    if (!inserted)
      throw InputError(fmt::format("map {}: feature #{}: duplicate id '{}' (first at feature #{})",
                                   source_name, i, landmarks.back().id, it->second));
  }
  // Remaining checks (parking number twice on a level, sizes, normals) are the map's own.
  if (const std::string problem = map::HdMap::validate(landmarks); !problem.empty())
    throw InputError(fmt::format("map {}: {}", source_name, problem));
  return map::HdMap(std::move(landmarks), name, accuracy, mapComplete(doc, source_name));
}

map::HdMap loadMap(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(fmt::format("map {}: cannot open file", path));
  std::ostringstream text;
  text << in.rdbuf();
  return parseMap(text.str(), path);
}

std::string mapToGeoJson(const map::HdMap& map) {
  // Insertion-ordered keys and one feature per line: readable, and diffs show one landmark.
  using ordered = nlohmann::ordered_json;
  std::string out = "{\"type\": \"FeatureCollection\",\n";
  if (!map.name().empty()) out += " \"name\": " + ordered(map.name()).dump() + ",\n";
  out += " \"crs\": \"local metric frame: metres, x east, y north, z up\",\n";
  const map::MapAccuracy& accuracy = map.accuracy();
  if (accuracy.position_sigma || accuracy.heading_sigma || !map.complete()) {
    ordered props = ordered::object();
    if (accuracy.position_sigma) props["position_sigma"] = *accuracy.position_sigma;
    if (accuracy.heading_sigma) props["heading_sigma"] = *accuracy.heading_sigma;
    if (!map.complete()) props["complete"] = false;
    out += " \"properties\": " + props.dump() + ",\n";
  }
  out += " \"features\": [";
  const auto& landmarks = map.landmarks();
  for (size_t i = 0; i < landmarks.size(); ++i) {
    const map::Landmark& l = landmarks[i];
    ordered props = {{"id", l.id},
                     {"text", l.text},
                     {"class", map::toString(l.cls)},
                     {"level", l.level},
                     {"heading", l.heading},
                     {"width", l.width},
                     {"height", l.height},
                     {"surface", map::toString(l.surface)}};
    if (l.surface == map::Surface::kVertical || l.normal != Eigen::Vector3d::UnitZ())
      props["normal"] = {l.normal.x(), l.normal.y(), l.normal.z()};
    // A feature states its own sigma where it differs from the map-wide default.
    if (l.accuracy.position_sigma && l.accuracy.position_sigma != accuracy.position_sigma)
      props["position_sigma"] = *l.accuracy.position_sigma;
    if (l.accuracy.heading_sigma && l.accuracy.heading_sigma != accuracy.heading_sigma)
      props["heading_sigma"] = *l.accuracy.heading_sigma;
    const ordered feature = {
        {"type", "Feature"},
        {"geometry",
         {{"type", "Point"}, {"coordinates", {l.position.x(), l.position.y(), l.position.z()}}}},
        {"properties", std::move(props)}};
    // nlohmann prints doubles in their shortest round-trip form, so a reload is exact.
    out += (i ? ",\n  " : "\n  ") + feature.dump();
  }
  out += landmarks.empty() ? "]\n}\n" : "\n ]\n}\n";
  return out;
}

void saveMap(const map::HdMap& map, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw IoError(fmt::format("map {}: cannot open for writing", path));
  out << mapToGeoJson(map);
  if (!out) throw IoError(fmt::format("map {}: write failed", path));
}

}  // namespace parkloc::io
