#include "sim/annotate.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "geometry/seen_span.h"
#include "geometry/text_polygon.h"

namespace parkloc::sim {

bool segmentBlocked(const GarageLevel& level, const Eigen::Vector3d& from,
                    const Eigen::Vector3d& to, double end_margin) {
  const Eigen::Vector3d d = to - from;
  const double len = d.norm();
  if (len < 1e-9) return false;
  const double t_end = 1.0 - end_margin / len;
  for (const Box& b : level.boxes) {
    double t0 = 0.0, t1 = t_end;
    bool miss = false;
    for (int a = 0; a < 3 && !miss; ++a) {
      if (std::abs(d[a]) < 1e-12) {
        if (from[a] < b.lo[a] || from[a] > b.hi[a]) miss = true;
        continue;
      }
      double ta = (b.lo[a] - from[a]) / d[a], tb = (b.hi[a] - from[a]) / d[a];
      if (ta > tb) std::swap(ta, tb);
      t0 = std::max(t0, ta);
      t1 = std::min(t1, tb);
      if (t0 > t1) miss = true;
    }
    if (!miss) return true;
  }
  return false;
}

namespace {

// The image polygon of the part of a text that the image shows: the corners of its seen span
// (geometry::seenSpan over the text's own plane: inside the image and not hidden), projected
// through the lens. Empty when nothing of it is seen or a corner does not project.
std::optional<geometry::TextPolygon> visiblePolygon(
    const geometry::RigCamera& camera, const geometry::Rigid3& camera_from_map,
    const std::array<Eigen::Vector3d, 4>& corners,
    const std::function<bool(const Eigen::Vector3d&)>& hidden) {
  // Bilinear point of the text's rectangle: u along the reading direction, v across it.
  auto pointAt = [&](double u, double v) -> Eigen::Vector3d {
    return (1.0 - v) * ((1.0 - u) * corners[0] + u * corners[1]) +
           v * ((1.0 - u) * corners[3] + u * corners[2]);
  };
  auto imageOf = [&](double u, double v) {
    return camera.model.project(camera_from_map * pointAt(u, v));
  };
  const auto span = geometry::seenSpan([&](double u, double v) {
    const auto px = imageOf(u, v);
    return px && camera.model.inImage(*px) && !hidden(pointAt(u, v));
  });
  if (!span) return std::nullopt;
  const std::array<std::pair<double, double>, 4> uv = {
      {{span->u0, span->v0}, {span->u1, span->v0}, {span->u1, span->v1}, {span->u0, span->v1}}};
  geometry::TextPolygon out;
  for (size_t k = 0; k < 4; ++k) {
    const auto px = imageOf(uv[k].first, uv[k].second);
    if (!px) return std::nullopt;
    out[k] = *px;
  }
  return out;
}

}  // namespace

std::vector<io::LabelInstance> annotateImage(const Garage& garage, int level,
                                             const geometry::RigCamera& camera,
                                             const geometry::Pose2& map_from_vehicle,
                                             const AnnotateOptions& options) {
  const GarageLevel& L = garage.levels.at(level);
  const geometry::Rigid3 map_from_camera = map_from_vehicle.toRigid3() * camera.vehicle_from_camera;
  const geometry::Rigid3 camera_from_map = map_from_camera.inverse();
  const Eigen::Vector3d eye = map_from_camera.translation();
  const geometry::Rigid3 vehicle_from_map = map_from_vehicle.toRigid3().inverse();
  const Eigen::Vector3d eye_in_vehicle = camera.vehicle_from_camera.translation();
  const auto hidden = [&](const Eigen::Vector3d& p) {
    return segmentBlocked(L, eye, p) ||
           (camera.body &&
            geometry::bodyBlocks(*camera.body, eye_in_vehicle, vehicle_from_map * p));
  };
  std::vector<io::LabelInstance> out;
  for (const TextItem& item : L.texts) {
    const map::Landmark& lm = item.landmark;
    if ((lm.position - eye).norm() > options.max_distance) continue;
    // Text faces the camera? Ground text is seen from above; vertical text from its front.
    const Eigen::Vector3d normal =
        lm.surface == map::Surface::kGround ? Eigen::Vector3d::UnitZ() : lm.normal;
    if (normal.dot(eye - lm.position) <= 0.0) continue;
    const auto corners = lm.corners();
    std::array<Eigen::Vector2d, 4> poly;
    bool projectable = true;
    for (int k = 0; k < 4 && projectable; ++k) {
      const auto px = camera.model.project(camera_from_map * corners[k]);
      if (!px)
        projectable = false;
      else
        poly[k] = *px;
    }
    if (!projectable) continue;
    const double height = geometry::apparentHeightPx(poly);
    if (height <= 0.0 || height < options.min_labelled_height_px) continue;
    const int characters = characterCount(lm.text);
    bool legible = isLegible(poly, characters, options.blur, options.legibility);
    std::optional<double> ink_snr;
    if (item.floor_decal >= 0 && options.floor_ink_contrast && options.channel_noise > 0.0) {
      const Eigen::Vector2d centre = 0.25 * (poly[0] + poly[1] + poly[2] + poly[3]);
      InkContrast ink{options.floor_ink_contrast(item.floor_decal, centre), options.channel_noise};
      if (options.through_camera) ink = options.through_camera(ink, poly);
      ink_snr = featureSnr(poly, characters, ink, options.legibility);
      legible = legible && *ink_snr >= options.legibility.min_feature_snr;
    }
    if (item.floor_decal >= 0 && options.min_ink_kept > 0.0)
      legible = legible && L.floor_decals.at(static_cast<size_t>(item.floor_decal)).ink_kept >=
                               options.min_ink_kept;
    // Sample points on the text: inside the image, and seen or hidden.
    int inside = 0, hidden_count = 0, total = 0;
    const Eigen::Vector3d r = lm.readingDirection() * lm.width;
    const Eigen::Vector3d u = lm.upDirection() * lm.height;
    for (int i = 0; i < options.samples_u; ++i)
      for (int j = 0; j < options.samples_v; ++j) {
        ++total;
        const double a = (i + 0.5) / options.samples_u - 0.5,
                     b = (j + 0.5) / options.samples_v - 0.5;
        const Eigen::Vector3d p = lm.position + a * r + b * u;
        const auto px = camera.model.project(camera_from_map * p);
        if (!px || !camera.model.inImage(*px)) continue;
        ++inside;
        if (hidden(p)) ++hidden_count;
      }
    if (inside < options.min_inside_fraction * total) continue;
    io::LabelInstance inst;
    inst.polygon = poly;
    inst.text = lm.text;
    inst.cls = lm.cls;
    inst.landmark_id = lm.id;
    inst.occluded_fraction = static_cast<double>(hidden_count) / inside;
    inst.legible = legible;
    if (item.floor_decal >= 0)
      inst.paint_wear = L.floor_decals.at(static_cast<size_t>(item.floor_decal)).wear;
    inst.ink_snr = ink_snr;
    inst.truncated = inside < total;
    for (const auto& c : poly) inst.truncated = inst.truncated || !camera.model.inImage(c);
    // What an annotator would box: the part that shows, when an edge, an obstacle or the car
    // itself hides the text's ends.
    if (inst.truncated || hidden_count > 0)
      inst.visible_polygon = visiblePolygon(camera, camera_from_map, corners, hidden);
    const Eigen::Vector2d reading = 0.5 * (poly[1] + poly[2]) - 0.5 * (poly[0] + poly[3]);
    inst.rotation_deg = std::atan2(reading.y(), reading.x()) * 180.0 / M_PI;
    out.push_back(inst);
  }
  return out;
}

}  // namespace parkloc::sim
