#include "eval/map_plot.h"

#include "eval/svg_plot.h"

namespace parkloc::eval {
namespace {

PlotSeries landmarkDots(const map::HdMap& map, const std::string& label, const std::string& color,
                        bool with_text) {
  PlotSeries s;
  s.label = label;
  s.color = color;
  s.line = false;
  s.marker_radius = 3.0;
  for (const map::Landmark& l : map.landmarks()) {
    s.x.push_back(l.position.x());
    s.y.push_back(l.position.y());
    if (with_text) s.point_labels.push_back(l.text);
  }
  return s;
}

}  // namespace

std::string mapPlotSvg(const std::string& title, const map::HdMap& map,
                       const std::vector<MapPath>& paths, const map::HdMap* under) {
  std::vector<PlotSeries> series;
  if (under) series.push_back(landmarkDots(*under, "true map", "#bbbbbb", false));
  for (const MapPath& path : paths) {
    PlotSeries s;
    s.label = path.label;
    s.color = path.color;
    for (const geometry::Pose2& p : path.poses) {
      s.x.push_back(p.x);
      s.y.push_back(p.y);
    }
    series.push_back(std::move(s));
  }
  series.push_back(landmarkDots(map, "landmarks", "#d62728", true));
  PlotOptions options;
  options.title = title;
  options.x_label = "x (m)";
  options.y_label = "y (m)";
  options.width = 1000;
  options.height = 700;
  options.equal_aspect = true;
  return linePlot(series, options);
}

}  // namespace parkloc::eval
