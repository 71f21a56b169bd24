#include "mapping/map_builder.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "common/error.h"
#include "geometry/planar_fit.h"
#include "mapping/landmark_seed.h"
#include "mapping/odometry_factor.h"
#include "mapping/sighting_cast.h"

namespace parkloc::mapping {
namespace {

std::vector<std::optional<CastSighting>> castAll(const std::vector<Sighting>& sightings,
                                                 const std::vector<const geometry::Rig*>& rigs,
                                                 const std::vector<SurveyPoses>& poses) {
  std::vector<std::optional<CastSighting>> cast;
  cast.reserve(sightings.size());
  for (const Sighting& s : sightings)
    cast.push_back(castOnFloor(s, *rigs[s.drive], poses[s.drive].map_from_vehicle[s.frame]));
  return cast;
}

double pathLength(const std::vector<geometry::Pose2>& poses) {
  double d = 0.0;
  for (size_t i = 1; i < poses.size(); ++i)
    d += (poses[i].translation() - poses[i - 1].translation()).norm();
  return d;
}

// Moves a later drive's dead-reckoned poses into the frame of the drives before it, by a
// rigid fit of the places of the texts it shares with them.
void joinFrame(std::vector<SurveyPoses>& poses, size_t drive,
               const std::vector<const geometry::Rig*>& rigs,
               const std::vector<Sighting>& sightings, const ConsensusOptions& options,
               const std::string& name) {
  std::vector<Sighting> earlier, own;
  for (const Sighting& s : sightings) (s.drive < drive ? earlier : own).push_back(s);
  const Consensus before = formConsensus(earlier, castAll(earlier, rigs, poses), options);
  const Consensus after = formConsensus(own, castAll(own, rigs, poses), options);
  std::map<std::string, Eigen::Vector2d> known;
  for (const TextTrack& t : before.tracks) known[t.text] = t.place;
  std::vector<Eigen::Vector2d> from, to;
  for (const TextTrack& t : after.tracks)
    if (const auto it = known.find(t.text); it != known.end()) {
      from.push_back(t.place);
      to.push_back(it->second);
    }
  const auto fit = geometry::fitPlanar(from, to, /*with_scale=*/false);
  if (!fit)
    throw InputError(fmt::format(
        "drive {}: shares {} text(s) with the drives before it, 2 are needed to join their map",
        name, from.size()));
  for (geometry::Pose2& p : poses[drive].map_from_vehicle) p = fit->to_from_from * p;
}

// The formats the user gives (ReadingOptions::formats); InputError for one that is none.
std::vector<map::NumberingFormat> givenNumbering(const ReadingOptions& options) {
  std::vector<map::NumberingFormat> formats;
  std::string rest = options.formats;
  while (!rest.empty()) {
    const size_t comma = rest.find(',');
    const std::string pattern = rest.substr(0, comma);
    rest = comma == std::string::npos ? "" : rest.substr(comma + 1);
    if (!map::validNumbering(pattern, options.numbering.max_strings))
      throw InputError(fmt::format(
          "numbering format '{}': expected characters and '#' for each open digit, spanning at "
          "most {} numbers (e.g. C### or K2-###)",
          pattern, options.numbering.max_strings));
    formats.push_back({pattern, 0});
  }
  return formats;
}

// The formats of the numbers that a first reading of one drive agreed on.
std::vector<map::NumberingFormat> learntNumbering(const std::vector<Sighting>& first,
                                                  const geometry::Rig* rig,
                                                  const SurveyPoses& poses,
                                                  const MapBuildOptions& options) {
  // The drive is alone here: its sightings refer to drive 0 of a one-drive frame.
  std::vector<Sighting> own = first;
  for (Sighting& s : own) s.drive = 0;
  const Consensus agreed = formConsensus(own, castAll(own, {rig}, {poses}), options.consensus);
  std::vector<std::string> numbers;
  for (const TextTrack& t : agreed.tracks) numbers.push_back(t.text);
  return map::learnNumbering(numbers, options.reading.numbering);
}

void addFormats(std::vector<map::NumberingFormat>& formats,
                const std::vector<map::NumberingFormat>& more) {
  for (const map::NumberingFormat& f : more)
    if (std::none_of(formats.begin(), formats.end(),
                     [&](const map::NumberingFormat& g) { return g.pattern == f.pattern; }))
      formats.push_back(f);
}

}  // namespace

MapBuild estimateMap(const std::vector<const geometry::Rig*>& rigs,
                     const std::vector<SurveyPoses>& poses, const std::vector<Sighting>& sightings,
                     const MapBuildOptions& options) {
  MapBuild build;
  build.sightings = sightings;
  const auto cast = castAll(sightings, rigs, poses);
  build.consensus = formConsensus(sightings, cast, options.consensus);
  if (build.consensus.tracks.empty())
    throw InputError(
        fmt::format("no text was read in {} frame sets of the same place (of {} readings): no map",
                    options.consensus.min_frame_sets, sightings.size()));
  for (const std::string& text : build.consensus.duplicates)
    build.problems.push_back(fmt::format(
        "'{}' was read at two places far apart (painted twice, or a misread): left out", text));
  for (const std::string& text : build.consensus.outweighed_duplicates)
    build.problems.push_back(fmt::format(
        "'{}' was read at two places far apart: kept where it was read in at least {} times "
        "the frame sets, the other place taken for a misread",
        text, options.consensus.min_margin));
  for (const TextTrack& track : build.consensus.tracks)
    build.landmarks.push_back(seedLandmark(track, cast));

  std::vector<DriveState> states;
  // Estimate; leave out the landmarks whose corners do not fit a floor text; again.
  for (;;) {  // each round leaves out one landmark or more, or ends
    states.assign(poses.size(), DriveState{});
    for (size_t d = 0; d < poses.size(); ++d) {
      states[d].rig = rigs[d];
      for (const geometry::Pose2& p : poses[d].map_from_vehicle)
        states[d].poses.push_back({p.x, p.y, p.yaw});
      states[d].motion = poses[d].motion;
      for (size_t i = 0; i + 1 < poses[d].timestamps.size(); ++i)
        states[d].seconds.push_back(poses[d].timestamps[i + 1] - poses[d].timestamps[i]);
    }
    std::vector<LandmarkEstimate> seeds = build.landmarks;
    MapProblem problem(states, build.landmarks, sightings, build.consensus.tracks,
                       options.estimation);
    build.estimation = problem.solve();
    problem.measureResiduals();
    std::vector<size_t> keep;
    for (size_t t = 0; t < build.landmarks.size(); ++t) {
      if (build.landmarks[t].median_px <= options.max_median_px &&
          build.landmarks[t].rms_px <= options.max_rms_px)
        keep.push_back(t);
      else
        build.inconsistent.push_back(build.landmarks[t].text);
    }
    if (keep.size() == build.landmarks.size()) {
      std::string why;
      build.has_uncertainty = problem.computeUncertainty(&why);
      if (!build.has_uncertainty) build.problems.push_back("no landmark sigmas: " + why);
      break;
    }
    if (keep.empty()) throw InputError("no text read fits a flat text on the floor: no map");
    std::vector<TextTrack> tracks;
    build.landmarks.clear();
    for (size_t t : keep) {
      tracks.push_back(build.consensus.tracks[t]);
      build.landmarks.push_back(seeds[t]);
    }
    build.consensus.tracks = std::move(tracks);
  }
  if (!build.estimation.converged)
    build.problems.push_back("the estimation did not converge: " + build.estimation.message);
  build.stencil_heights = applyStencilHeight(build.landmarks, options.stencil);

  for (size_t d = 0; d < poses.size(); ++d) {
    DriveOutcome drive;
    drive.dead_reckoned = poses[d].map_from_vehicle;
    for (const auto& p : states[d].poses) drive.estimated.emplace_back(p[0], p[1], p[2]);
    drive.odometry_distance_m = pathLength(drive.dead_reckoned);
    drive.estimated_distance_m = pathLength(drive.estimated);
    drive.distance_scale = states[d].odometry_calibration[kDistanceScale];
    drive.yaw_rate_bias = states[d].odometry_calibration[kYawRateBias];
    drive.fitted_margin_px = states[d].corner_margin_px[0];
    drive.unfitted_margin_px = states[d].corner_margin_px[1];
    for (const Sighting& s : sightings) drive.sightings += s.drive == d ? 1 : 0;
    // The cameras measure distance through the landmarks; the odometry through the wheels.
    if (drive.odometry_distance_m > 1.0) {
      const double scale = drive.estimated_distance_m / drive.odometry_distance_m - 1.0;
      if (std::fabs(scale) > options.odometry_scale_tolerance)
        build.problems.push_back(fmt::format(
            "drive {}: the odometry's distance differs from the cameras' by {:+.1f} % (wheel "
            "scale?): the poses between the texts are doubtful",
            d, 100.0 * scale));
    }
    build.drives.push_back(std::move(drive));
  }
  return build;
}

MapBuild buildMap(const std::vector<const io::Sequence*>& drives, ocr::TextSpotter* spotter,
                  const MapBuildOptions& options,
                  const std::function<void(size_t, size_t, size_t)>& progress,
                  const std::vector<Sighting>* read_before) {
  std::vector<const geometry::Rig*> rigs;
  std::vector<SurveyPoses> poses;
  std::vector<Sighting> sightings;
  std::vector<ReadingStats> stats(drives.size());
  std::vector<map::NumberingFormat> numbering = givenNumbering(options.reading);
  for (size_t d = 0; d < drives.size(); ++d) {
    const io::Sequence& drive = *drives[d];
    rigs.push_back(&drive.rig());
    poses.push_back(deadReckon(drive.odometry(), drive.timestamps(), drive.dir()));
    std::vector<Sighting> read;
    if (read_before) {
      stats[d].frame_sets = drive.timestamps().size();
      for (const Sighting& s : *read_before) {
        if (s.drive != d) continue;
        if (s.frame >= drive.timestamps().size() || s.camera < 0 ||
            static_cast<size_t>(s.camera) >= drive.rig().cameras.size())
          throw InputError(
              fmt::format("sightings of drive {}: frame set {} camera {} is not in the drive",
                          drive.dir(), s.frame, s.camera));
        read.push_back(s);
      }
    } else if (spotter) {
      const auto tell = [&](size_t done, size_t total) {
        if (progress) progress(d, done, total);
      };
      if (options.reading.learn_numbering) {
        ReadingStats survey;
        const std::vector<Sighting> first = readDrive(
            drive, d, *spotter, options.reading.survey_step, {}, options.reading, survey, tell);
        stats[d].survey_frame_sets = survey.frame_sets;
        stats[d].survey_seconds = stats[d].seconds = survey.seconds;
        addFormats(numbering, learntNumbering(first, rigs[d], poses[d], options));
      }
      read = readDrive(drive, d, *spotter, options.reading.frame_step,
                       map::numberingLexicon(numbering), options.reading, stats[d], tell);
    }
    if (read.empty())
      throw InputError(fmt::format("drive {}: no parking number was read in {} frame sets",
                                   drive.dir(), stats[d].frame_sets));
    sightings.insert(sightings.end(), read.begin(), read.end());
    if (d > 0) joinFrame(poses, d, rigs, sightings, options.consensus, drive.dir());
  }
  MapBuild build = estimateMap(rigs, poses, sightings, options);
  build.numbering = std::move(numbering);
  for (size_t d = 0; d < drives.size(); ++d) {
    build.drives[d].dir = drives[d]->dir();
    build.drives[d].reading = stats[d];
  }
  return build;
}

}  // namespace parkloc::mapping
