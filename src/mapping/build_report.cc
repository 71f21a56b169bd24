#include "mapping/build_report.h"

#include <algorithm>
#include <cmath>

namespace parkloc::mapping {

nlohmann::json sightingHistogram(const MapBuild& build) {
  nlohmann::json bins = {{"3-4", 0}, {"5-9", 0}, {"10-19", 0}, {"20+", 0}};
  for (const LandmarkEstimate& l : build.landmarks) {
    const char* bin = l.frame_sets < 5    ? "3-4"
                      : l.frame_sets < 10 ? "5-9"
                      : l.frame_sets < 20 ? "10-19"
                                          : "20+";
    bins[bin] = bins[bin].get<int>() + 1;
  }
  return bins;
}

nlohmann::json buildReportJson(const MapBuild& build, const std::string& level) {
  nlohmann::json drives = nlohmann::json::array();
  for (const DriveOutcome& d : build.drives) {
    const double per_frame =
        d.reading.frame_sets ? 1000.0 * d.reading.seconds / d.reading.frame_sets : 0.0;
    drives.push_back({{"dir", d.dir},
                      {"frame_sets", d.reading.frame_sets},
                      {"images", d.reading.images},
                      {"missing_images", d.reading.missing_images},
                      {"text_instances", d.reading.instances},
                      {"sightings", d.sightings},
                      {"reading_s", d.reading.seconds},
                      {"survey_frame_sets", d.reading.survey_frame_sets},
                      {"survey_reading_s", d.reading.survey_seconds},
                      {"reading_ms_per_frame_set", per_frame},
                      {"odometry_distance_m", d.odometry_distance_m},
                      {"estimated_distance_m", d.estimated_distance_m},
                      {"odometry_distance_scale", d.distance_scale},
                      {"odometry_yaw_rate_bias_deg_s", d.yaw_rate_bias * 180.0 / M_PI},
                      {"fitted_corner_margin_px", d.fitted_margin_px},
                      {"unfitted_corner_margin_px", d.unfitted_margin_px}});
  }
  std::vector<const LandmarkEstimate*> order;
  for (const LandmarkEstimate& l : build.landmarks) order.push_back(&l);
  std::stable_sort(order.begin(), order.end(),
                   [](const auto* a, const auto* b) { return a->frame_sets > b->frame_sets; });
  nlohmann::json landmarks = nlohmann::json::array();
  for (const LandmarkEstimate* l : order) {
    nlohmann::json j = {{"text", l->text},
                        {"x", l->parameters[kX]},
                        {"y", l->parameters[kY]},
                        {"heading", l->parameters[kHeading]},
                        {"width", l->parameters[kWidth]},
                        {"height", l->parameters[kHeight]},
                        {"sightings", l->sightings},
                        {"frame_sets", l->frame_sets},
                        {"misreads", l->misreads},
                        {"rms_px", l->rms_px},
                        {"median_px", l->median_px},
                        {"outlier_corners", l->outlier_corners}};
    if (l->position_sigma) j["position_sigma"] = *l->position_sigma;
    if (l->heading_sigma) j["heading_sigma"] = *l->heading_sigma;
    if (l->moved_m) j["moved_m"] = *l->moved_m;
    if (l->added) j["added"] = true;
    landmarks.push_back(std::move(j));
  }
  const EstimationSummary& e = build.estimation;
  const double optimisation_per_frame = [&] {
    size_t frames = 0;
    for (const DriveOutcome& d : build.drives) frames += d.estimated.size();
    return frames ? 1000.0 * e.seconds / static_cast<double>(frames) : 0.0;
  }();
  nlohmann::json numbering = nlohmann::json::array();
  for (const map::NumberingFormat& f : build.numbering) {
    const auto [from, to] = map::numberingEnds(f);
    numbering.push_back(
        {{"format", f.pattern}, {"numbers", f.support}, {"from", from}, {"to", to}});
  }
  nlohmann::json undecided = nlohmann::json::array();
  for (const UndecidedPlace& u : build.consensus.undecided) {
    nlohmann::json readings = nlohmann::json::array();
    for (const auto& [text, frame_sets] : u.readings)
      readings.push_back({{"text", text}, {"frame_sets", frame_sets}});
    undecided.push_back(
        {{"x", u.place.x()}, {"y", u.place.y()}, {"why", u.why}, {"readings", readings}});
  }
  return {{"level", level},
          {"drives", drives},
          {"numbering", numbering},
          {"consensus",
           {{"landmarks", build.landmarks.size()},
            {"unplaced_sightings", build.consensus.unplaced},
            {"misread_sightings", build.consensus.misreads},
            {"weak_places", build.consensus.weak_places},
            {"unconfirmed_places", build.consensus.unconfirmed_places},
            {"undecided_places", undecided},
            {"out_of_sequence", build.consensus.out_of_sequence},
            {"decided_by_sequence", build.consensus.decided_by_sequence},
            {"loops_closed", build.consensus.loops},
            {"duplicates", build.consensus.duplicates},
            {"outweighed_duplicates", build.consensus.outweighed_duplicates},
            {"inconsistent", build.inconsistent},
            {"stencil_heights", build.stencil_heights}}},
          {"estimation",
           {{"converged", e.converged},
            {"message", e.message},
            {"iterations", e.iterations},
            {"initial_cost", e.initial_cost},
            {"final_cost", e.final_cost},
            {"seconds", e.seconds},
            {"ms_per_frame_set", optimisation_per_frame},
            {"corner_factors", e.corner_factors},
            {"unprojected_corners", e.unprojected_corners},
            {"odometry_factors", e.odometry_factors},
            {"has_uncertainty", build.has_uncertainty}}},
          {"landmarks_by_frame_sets", sightingHistogram(build)},
          {"landmarks", landmarks},
          {"problems", build.problems}};
}

}  // namespace parkloc::mapping
