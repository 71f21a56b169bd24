// `parkloc map build SEQUENCE... --out MAP.geojson`: the map of a garage level from drives
// through it (mapping/map_builder.h), with its report next to it: MAP.report.json and
// MAP.svg (the landmarks and the drives).
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "apps/parkloc/config_args.h"
#include "apps/parkloc/map_commands.h"
#include "apps/parkloc/progress_line.h"
#include "common/error.h"
#include "eval/map_plot.h"
#include "io/anchors_csv.h"
#include "io/map_geojson.h"
#include "io/sequence.h"
#include "mapping/anchor_fit.h"
#include "mapping/build_report.h"
#include "mapping/map_builder.h"
#include "mapping/map_merge.h"
#include "mapping/sightings_json.h"

namespace parkloc::app {
namespace {

namespace fs = std::filesystem;

struct MapBuildArgs {
  std::vector<std::string> drives;
  std::string out;
  std::string level;
  std::string anchors;
  bool similarity = false;
  std::string merge;
  std::string sightings;
  std::string numbering;
  bool quiet = false;
  ConfigArgs config;
};

std::string replaceExtension(const std::string& path, const std::string& extension) {
  return fs::path(path).replace_extension(extension).string();
}

void writeText(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  if (!out || !(out << text)) throw IoError("cannot write " + path);
}

void run(const MapBuildArgs& a) {
  config::Config config = a.config.load();
  if (!a.numbering.empty()) config.map_build.reading.formats = a.numbering;
  // Read everything that can fail on bad input before the long reading starts.
  std::vector<io::Anchor> anchors;
  if (!a.anchors.empty()) anchors = io::loadAnchors(a.anchors);
  std::optional<map::HdMap> existing;
  if (!a.merge.empty()) existing = io::loadMap(a.merge);
  std::vector<std::unique_ptr<io::Sequence>> sequences;
  std::vector<const io::Sequence*> drives;
  for (const std::string& dir : a.drives) {
    // Only what the vehicle records: the drive's map and poses, if any, stay unread.
    sequences.push_back(
        std::make_unique<io::Sequence>(dir, "", "", "", io::SequenceContents::kSensors));
    if (sequences.back()->odometry().empty())
      throw InputError(fmt::format(
          "drive {}: no odometry.csv: the map builder needs wheel odometry between the texts",
          dir));
    drives.push_back(sequences.back().get());
  }
  std::optional<std::vector<mapping::Sighting>> read_before;
  std::unique_ptr<ocr::TextSpotter> spotter;
  if (!a.sightings.empty())
    read_before = mapping::loadSightings(a.sightings);
  else
    spotter = makeSpotter(config);
  ProgressLine progress(a.quiet);
  mapping::MapBuild build = mapping::buildMap(
      drives, spotter.get(), config.map_build,
      [&](size_t d, size_t done, size_t total) {
        progress(
            {fmt::format("reading {}", fs::path(a.drives[d]).filename().string()), done, total});
      },
      read_before ? &*read_before : nullptr);
  progress.finish();

  std::vector<eval::MapPath> paths;
  nlohmann::json report = mapping::buildReportJson(build, a.level);
  if (!anchors.empty()) {
    const mapping::AnchorFit fit = mapping::fitAnchors(build.landmarks, anchors, a.similarity);
    for (auto& l : build.landmarks) mapping::applyFit(fit.fit, l);
    for (auto& d : build.drives) {
      for (auto& p : d.estimated) p = mapping::applyFit(fit.fit, p);
      for (auto& p : d.dead_reckoned) p = mapping::applyFit(fit.fit, p);
    }
    nlohmann::json residuals = nlohmann::json::object();
    for (size_t i = 0; i < fit.used.size(); ++i) residuals[fit.used[i]] = fit.fit.residuals[i];
    report["anchors"] = {{"fit", a.similarity ? "similarity" : "rigid"},
                         {"scale", fit.fit.scale},
                         {"rms_m", fit.fit.rms},
                         {"residuals_m", residuals},
                         {"unmatched", fit.unmatched}};
    fmt::print("anchors: {} fit over {} anchors, rms {:.3f} m, scale {:.4f}{}\n",
               a.similarity ? "similarity" : "rigid", fit.used.size(), fit.fit.rms, fit.fit.scale,
               fit.unmatched.empty()
                   ? ""
                   : fmt::format(" ({} not in the built map)", fit.unmatched.size()));
  }
  std::vector<map::Landmark> landmarks;
  if (existing) {
    const mapping::MapMerge merge =
        mapping::mergeMaps(*existing, build.landmarks, a.level, mapping::MergeOptions{});
    landmarks = merge.landmarks;
    for (auto& d : build.drives)
      for (auto& p : d.estimated) p = mapping::applyFit(merge.fit, p);
    report["merge"] = {{"existing", a.merge},
                       {"confirmed", merge.confirmed},
                       {"moved", merge.moved},
                       {"added", merge.added},
                       {"kept_unseen", merge.kept_unseen}};
    fmt::print("merge into {}: {} confirmed, {} moved, {} added, {} kept unseen\n", a.merge,
               merge.confirmed, merge.moved.size(), merge.added.size(), merge.kept_unseen);
    for (const std::string& text : merge.moved) fmt::print("  moved: {}\n", text);
  } else {
    for (const auto& l : build.landmarks) landmarks.push_back(l.toLandmark(a.level));
  }
  report["landmarks"] = mapping::buildReportJson(build, a.level)["landmarks"];

  // A built map holds what the drives read, not every number of the level; merged into an
  // existing map, it is as complete as that map.
  const map::HdMap built(std::move(landmarks), fs::path(a.out).stem().string(), {},
                         existing ? existing->complete() : false);
  io::saveMap(built, a.out);
  for (size_t d = 0; d < build.drives.size(); ++d) {
    const std::string name = fs::path(a.drives[d]).filename().string();
    paths.push_back({name + " (estimated)", "#1f77b4", build.drives[d].estimated});
  }
  writeText(replaceExtension(a.out, ".svg"),
            eval::mapPlotSvg(fmt::format("{}: {} landmarks", a.out, built.size()), built, paths));
  writeText(replaceExtension(a.out, ".report.json"), report.dump(2) + "\n");
  if (a.sightings.empty())
    mapping::saveSightings(build.sightings, replaceExtension(a.out, ".sightings.jsonl"));

  const mapping::EstimationSummary& e = build.estimation;
  size_t frame_sets = 0;
  double reading_s = 0.0;
  for (const auto& d : build.drives) {
    frame_sets += d.reading.frame_sets;
    reading_s += d.reading.seconds;
  }
  fmt::print(
      "map {}: {} landmarks from {} drive(s), {} frame sets; {} misread sightings outvoted, "
      "{} loops closed\n",
      a.out, built.size(), build.drives.size(), frame_sets, build.consensus.misreads,
      build.consensus.loops);
  fmt::print(
      "  reading {}, estimation {:.2f} s ({} iterations, {} corner and {} odometry "
      "factors)\n",
      a.sightings.empty() ? fmt::format("{:.1f} s ({:.0f} ms per frame set)", reading_s,
                                        frame_sets ? 1000.0 * reading_s / frame_sets : 0.0)
                          : "from " + a.sightings,
      e.seconds, e.iterations, e.corner_factors, e.odometry_factors);
  if (!build.numbering.empty()) {
    std::vector<std::string> formats;
    for (const auto& f : build.numbering) {
      const auto [from, to] = map::numberingEnds(f);
      formats.push_back(
          f.support ? fmt::format("{} ({} to {}, from {} numbers)", f.pattern, from, to, f.support)
                    : f.pattern + " (given)");
    }
    fmt::print("  read against the numbering {}\n", fmt::join(formats, ", "));
  }
  if (!build.inconsistent.empty())
    fmt::print("  left out, corners fit no floor text: {}\n", fmt::join(build.inconsistent, ", "));
  if (!build.stencil_heights.empty())
    fmt::print("  height set to the stencil's, the corners' too far off it: {}\n",
               fmt::join(build.stencil_heights, ", "));
  if (!build.consensus.out_of_sequence.empty())
    fmt::print("  left out, out of the numbering's sequence beside a better-seen number: {}\n",
               fmt::join(build.consensus.out_of_sequence, ", "));
  if (!build.consensus.decided_by_sequence.empty())
    fmt::print("  contested places decided by the numbering's sequence: {}\n",
               fmt::join(build.consensus.decided_by_sequence, ", "));
  if (!build.consensus.undecided.empty()) {
    std::vector<std::string> places;
    for (const mapping::UndecidedPlace& u : build.consensus.undecided) {
      std::vector<std::string> readings;
      for (size_t k = 0; k < std::min<size_t>(u.readings.size(), 3); ++k)
        readings.push_back(fmt::format("{} {}", u.readings[k].first, u.readings[k].second));
      places.push_back(fmt::format("{} ({})", fmt::join(readings, " / "), u.why));
    }
    fmt::print("  left out, reading undecided (frame sets): {}\n", fmt::join(places, "; "));
  }
  for (const std::string& p : build.problems) fmt::print("  problem: {}\n", p);
  fmt::print("wrote {}, {}, {}\n", a.out, replaceExtension(a.out, ".svg"),
             replaceExtension(a.out, ".report.json"));
}

}  // namespace

CLI::App* addMapBuild(CLI::App& map) {
  auto args = std::make_shared<MapBuildArgs>();
  auto* cmd = map.add_subcommand(
      "build", "Build the map of a garage level from drives through it (no map needed)");
  cmd->add_option("drives", args->drives,
                  "Sequence folders (images, calib.yaml, odometry.csv); their map and poses, "
                  "if any, are not read")
      ->required();
  cmd->add_option("--out", args->out, "The map to write (GeoJSON); the report goes next to it")
      ->required();
  cmd->add_option("--level", args->level, "The garage level the drives are on");
  cmd->add_option("--anchors", args->anchors,
                  "CSV 'text,x,y' of landmarks with known map positions: the map is fitted "
                  "to them");
  cmd->add_flag("--similarity", args->similarity,
                "With --anchors: fit a similarity (scale too) instead of a rigid transform");
  cmd->add_option("--merge", args->merge,
                  "An existing map (GeoJSON) to add the drives to: matched texts confirm or "
                  "move, the rest are added");
  cmd->add_option("--sightings", args->sightings,
                  "Sightings an earlier build of the same drives wrote (MAP.sightings.jsonl): "
                  "estimate again without reading the images");
  cmd->add_option("--numbering", args->numbering,
                  "The garage's numbering formats, comma-separated, '#' for a digit (e.g. "
                  "C###,K2-###): read against them besides those the build learns");
  cmd->add_flag("--quiet", args->quiet, "No progress on stderr");
  args->config.addTo(cmd);
  cmd->callback([args] { run(*args); });
  return cmd;
}

}  // namespace parkloc::app
