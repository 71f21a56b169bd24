#include "mapping/sightings_json.h"

#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "common/error.h"

namespace parkloc::mapping {

void saveSightings(const std::vector<Sighting>& sightings, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw IoError("cannot write " + path);
  for (const Sighting& s : sightings) {
    nlohmann::json pixels = nlohmann::json::array();
    for (const auto& p : s.pixels) pixels.push_back({p.x(), p.y()});
    out << nlohmann::json{{"drive", s.drive},
                          {"frame", s.frame},
                          {"camera", s.camera},
                          {"text", s.text},
                          {"class", map::toString(s.cls)},
                          {"pixels", pixels},
                          {"score", s.recognition_score},
                          {"second_opinion", s.second_opinion},
                          {"off_numbering", s.off_numbering},
                          {"box_only", s.box_only}}
               .dump()
        << "\n";
  }
}

std::vector<Sighting> loadSightings(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("sightings {}: cannot read the file", path));
  std::vector<Sighting> sightings;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    try {
      const nlohmann::json j = nlohmann::json::parse(line);
      Sighting s;
      s.drive = j.at("drive").get<size_t>();
      s.frame = j.at("frame").get<size_t>();
      s.camera = j.at("camera").get<int>();
      s.text = j.at("text").get<std::string>();
      const auto cls = map::textClassFromString(j.at("class").get<std::string>());
      if (!cls) throw InputError("unknown class");
      s.cls = *cls;
      for (int i = 0; i < 4; ++i)
        s.pixels[i] = {j.at("pixels").at(i).at(0).get<double>(),
                       j.at("pixels").at(i).at(1).get<double>()};
      s.recognition_score = j.at("score").get<double>();
      s.second_opinion = j.value("second_opinion", false);
      s.off_numbering = j.value("off_numbering", false);
      s.box_only = j.value("box_only", false);
      sightings.push_back(std::move(s));
    } catch (const std::exception& e) {
      throw InputError(fmt::format("sightings {} line {}: {}", path, number, e.what()));
    }
  }
  return sightings;
}

}  // namespace parkloc::mapping
