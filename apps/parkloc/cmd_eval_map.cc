// `parkloc eval map BUILT.geojson TRUE.geojson`: a built map against the true one
// (eval/map_comparison.h): a printed table, and with --out the figures as JSON and the built
// map drawn over the true one (SVG).
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>

#include "apps/parkloc/map_commands.h"
#include "common/error.h"
#include "eval/map_comparison.h"
#include "eval/map_plot.h"
#include "io/map_geojson.h"
#include "io/sequence.h"

namespace parkloc::app {
namespace {

namespace fs = std::filesystem;

struct EvalMapArgs {
  std::string built;
  std::string truth;
  std::vector<std::string> drives;
  std::string level;
  std::string out;
};

nlohmann::json summaryJson(const eval::Summary& s) {
  return {
      {"count", s.count}, {"mean", s.mean}, {"rms", s.rmse}, {"max", s.max}, {"median", s.median}};
}

void run(const EvalMapArgs& a) {
  const map::HdMap built = io::loadMap(a.built);
  const map::HdMap truth = io::loadMap(a.truth);
  std::map<std::string, int> legible;
  for (const std::string& dir : a.drives)
    for (const auto& [id, frames] : eval::legibleFrameSets(io::Sequence(dir)))
      legible[id] += frames;
  const eval::MapComparisonOptions options;
  const eval::MapComparison c = eval::compareMaps(built, truth, a.level, legible, options);
  if (!c.fit)
    throw InputError(
        fmt::format("{}: fewer than two texts match {} on level '{}'", a.built, a.truth, c.level));

  fmt::print("{} against {} (level '{}'), SE(2) fit over {} texts\n", a.built, a.truth, c.level,
             c.position_m.count);
  fmt::print("  {:<28} {:>9} {:>9} {:>9}\n", "", "mean", "RMS", "max");
  fmt::print("  {:<28} {:>9.2f} {:>9.2f} {:>9.2f}\n", "position error (cm)",
             100 * c.position_m.mean, 100 * c.position_m.rmse, 100 * c.position_m.max);
  fmt::print("  {:<28} {:>9.3f} {:>9.3f} {:>9.3f}\n", "heading error (deg)", c.abs_heading_deg.mean,
             c.abs_heading_deg.rmse, c.abs_heading_deg.max);
  fmt::print("  {:<28} {:>9.2f} {:>9.2f} {:>9.2f}\n", "width error (%)", 100 * c.abs_width_rel.mean,
             100 * c.abs_width_rel.rmse, 100 * c.abs_width_rel.max);
  fmt::print("  {:<28} {:>9.2f} {:>9.2f} {:>9.2f}\n", "height error (%)",
             100 * c.abs_height_rel.mean, 100 * c.abs_height_rel.rmse, 100 * c.abs_height_rel.max);
  fmt::print("  completeness: {} of {} parking numbers{} in the map ({:.1f} %)\n", c.legible_found,
             c.legible,
             a.drives.empty()
                 ? ""
                 : fmt::format(" legible in >= {} frame sets", options.legible_frame_sets),
             100.0 * c.completeness);
  fmt::print("  phantoms and wrong texts: {} of {} built landmarks{}\n", c.phantoms.size(), c.built,
             c.phantoms.empty() ? "" : fmt::format(" ({})", fmt::join(c.phantoms, ", ")));
  if (!c.missing.empty()) fmt::print("  missing: {}\n", fmt::join(c.missing, ", "));

  if (a.out.empty()) return;
  fs::create_directories(a.out);
  nlohmann::json errors = nlohmann::json::array();
  for (const auto& e : c.errors)
    errors.push_back({{"text", e.text},
                      {"position_m", e.position_m},
                      {"heading_deg", e.heading_deg},
                      {"width_rel", e.width_rel},
                      {"height_rel", e.height_rel},
                      {"wrong_place", e.wrong_place}});
  const nlohmann::json j = {{"built", a.built},
                            {"truth", a.truth},
                            {"level", c.level},
                            {"fit",
                             {{"x", c.fit->to_from_from.x},
                              {"y", c.fit->to_from_from.y},
                              {"yaw", c.fit->to_from_from.yaw}}},
                            {"position_m", summaryJson(c.position_m)},
                            {"abs_heading_deg", summaryJson(c.abs_heading_deg)},
                            {"abs_width_rel", summaryJson(c.abs_width_rel)},
                            {"abs_height_rel", summaryJson(c.abs_height_rel)},
                            {"built_landmarks", c.built},
                            {"true_parking_numbers", c.true_parking_numbers},
                            {"legible", c.legible},
                            {"legible_found", c.legible_found},
                            {"completeness", c.completeness},
                            {"missing", c.missing},
                            {"phantoms", c.phantoms},
                            {"landmarks", errors}};
  const std::string json_path = (fs::path(a.out) / "map_eval.json").string();
  std::ofstream(json_path) << j.dump(2) << "\n";
  // The built map in the true frame over the true map's level.
  std::vector<map::Landmark> aligned;
  for (map::Landmark l : built.landmarks()) {
    l.position.head<2>() = c.fit->apply(l.position.head<2>());
    l.heading += c.fit->to_from_from.yaw;
    aligned.push_back(l);
  }
  std::vector<map::Landmark> level_truth;
  for (const map::Landmark& l : truth.landmarks())
    if (c.level.empty() || l.level == c.level) level_truth.push_back(l);
  const map::HdMap aligned_map(aligned), truth_level(level_truth);
  const std::string svg_path = (fs::path(a.out) / "map_eval.svg").string();
  std::ofstream(svg_path) << eval::mapPlotSvg(
      fmt::format("{} (red) over {} (grey)", a.built, a.truth), aligned_map, {}, &truth_level);
  fmt::print("wrote {}, {}\n", json_path, svg_path);
}

}  // namespace

CLI::App* addEvalMap(CLI::App& eval) {
  auto args = std::make_shared<EvalMapArgs>();
  auto* cmd = eval.add_subcommand("map", "Compare a built map with the true one");
  cmd->add_option("built", args->built, "The built map (GeoJSON)")->required();
  cmd->add_option("truth", args->truth, "The true map (GeoJSON)")->required();
  cmd->add_option("--drive", args->drives,
                  "Drives the map was built from: completeness counts the parking numbers "
                  "their labels show legibly in >= 3 frame sets (default: all of the level)");
  cmd->add_option("--level", args->level, "The true map's level (default: the built map's)");
  cmd->add_option("--out", args->out, "Folder for map_eval.json and map_eval.svg");
  cmd->callback([args] { run(*args); });
  return cmd;
}

}  // namespace parkloc::app
