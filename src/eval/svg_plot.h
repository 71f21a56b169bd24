#pragma once
// Small self-contained SVG charts for the HTML report (no scripts, no network): line and
// point series on linear axes, histograms, and per-stage latency ranges.
#include <string>
#include <vector>

namespace parkloc::eval {

struct PlotSeries {
  std::string label;
  std::string color = "#1f77b4";
  std::vector<double> x, y;
  bool line = true;          // polyline through the points
  double marker_radius = 0;  // > 0: a dot at each point
  double line_width = 1.5;
  std::vector<std::string> point_labels;  // optional text next to each point
};

struct PlotOptions {
  std::string title;
  std::string x_label, y_label;
  int width = 600;
  int height = 360;
  bool equal_aspect = false;  // same metres per pixel on both axes (maps)
  // Vertical reference lines (e.g. 0 on an error histogram).
  std::vector<double> x_marks;
};

std::string linePlot(const std::vector<PlotSeries>& series, const PlotOptions& options);

// Histogram of `values` with `bins` equal bins over [min, max] of the data (or the given
// range when lo < hi).
std::string histogramPlot(const std::vector<double>& values, int bins, const std::string& color,
                          const PlotOptions& options, double lo = 0.0, double hi = 0.0);

// One horizontal row per named sample: a bar from the 5th to the 95th percentile, a tick at
// the median and a dot at the 99th percentile.
struct RangeRow {
  std::string label;
  std::vector<double> values;
};
std::string rangePlot(const std::vector<RangeRow>& rows, const PlotOptions& options);

// "Nice" tick positions covering [lo, hi] (1, 2, 5 times a power of ten).
std::vector<double> niceTicks(double lo, double hi, int approximate_count = 6);

// Escapes &, <, >, " for HTML / SVG text.
std::string escapeXml(const std::string& text);

}  // namespace parkloc::eval
