#include "eval/svg_plot.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "eval/statistics.h"

namespace parkloc::eval {
namespace {

struct Frame {
  // Plot area in pixels and the data range it shows.
  double left = 64, right = 0, top = 34, bottom = 0;
  double x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  double px(double x) const { return left + (x - x0) / (x1 - x0) * (right - left); }
  double py(double y) const { return bottom - (y - y0) / (y1 - y0) * (bottom - top); }
};

std::string num(double v) { return fmt::format("{:.1f}", v); }

std::string tickLabel(double v, double step) {
  if (std::fabs(v) < step * 1e-6) v = 0.0;
  const int decimals = step >= 1.0 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  return fmt::format("{:.{}f}", v, std::max(0, decimals));
}

void widen(double& lo, double& hi) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) lo = 0, hi = 1;
  if (hi - lo < 1e-12) {
    const double pad = std::max(std::fabs(lo) * 0.1, 1e-3);
    lo -= pad;
    hi += pad;
  }
}

std::string open(const PlotOptions& o) {
  std::string s = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" viewBox=\"0 0 {} {}\" "
      "font-family=\"sans-serif\" font-size=\"11\">\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
      o.width, o.height, o.width, o.height);
  if (!o.title.empty()) {
    s += fmt::format(
        "<text x=\"{}\" y=\"18\" text-anchor=\"middle\" font-size=\"13\" "
        "font-weight=\"bold\">{}</text>\n",
        o.width / 2, escapeXml(o.title));
  }
  return s;
}

// Axes, grid, tick labels and axis titles.
std::string axes(const Frame& f, const PlotOptions& o, bool y_ticks = true) {
  std::string s;
  const std::vector<double> xt = niceTicks(f.x0, f.x1), yt = niceTicks(f.y0, f.y1);
  const double xs = xt.size() > 1 ? xt[1] - xt[0] : 1.0, ys = yt.size() > 1 ? yt[1] - yt[0] : 1.0;
  for (double x : xt) {
    if (x < f.x0 - 1e-9 || x > f.x1 + 1e-9) continue;
    s += fmt::format(
        "<line x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\" stroke=\"#e5e5e5\"/>"
        "<text x=\"{0}\" y=\"{3}\" text-anchor=\"middle\">{4}</text>\n",
        num(f.px(x)), num(f.top), num(f.bottom), num(f.bottom + 14), tickLabel(x, xs));
  }
  for (double y : yt) {
    if (!y_ticks) break;
    if (y < f.y0 - 1e-9 || y > f.y1 + 1e-9) continue;
    s += fmt::format(
        "<line x1=\"{0}\" y1=\"{1}\" x2=\"{2}\" y2=\"{1}\" stroke=\"#e5e5e5\"/>"
        "<text x=\"{3}\" y=\"{4}\" text-anchor=\"end\">{5}</text>\n",
        num(f.left), num(f.py(y)), num(f.right), num(f.left - 4), num(f.py(y) + 4),
        tickLabel(y, ys));
  }
  s += fmt::format(
      "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#444\"/>\n",
      num(f.left), num(f.top), num(f.right - f.left), num(f.bottom - f.top));
  if (!o.x_label.empty()) {
    s += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n",
                     num((f.left + f.right) / 2), o.height - 6, escapeXml(o.x_label));
  }
  if (!o.y_label.empty()) {
    s += fmt::format(
        "<text transform=\"translate(14 {}) rotate(-90)\" text-anchor=\"middle\">{}</text>\n",
        num((f.top + f.bottom) / 2), escapeXml(o.y_label));
  }
  for (double x : o.x_marks) {
    if (x < f.x0 || x > f.x1) continue;
    s += fmt::format(
        "<line x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\" stroke=\"#222\" "
        "stroke-dasharray=\"4 3\"/>\n",
        num(f.px(x)), num(f.top), num(f.bottom));
  }
  return s;
}

Frame plotFrame(const PlotOptions& o) {
  Frame f;
  f.right = o.width - 16;
  f.bottom = o.height - 40;
  return f;
}

}  // namespace

std::string escapeXml(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::vector<double> niceTicks(double lo, double hi, int approximate_count) {
  widen(lo, hi);
  const double raw = (hi - lo) / std::max(1, approximate_count);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * magnitude;
    if (step >= raw) break;
  }
  std::vector<double> ticks;
  for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + step * 1e-9; t += step) {
    ticks.push_back(t);
  }
  return ticks;
}

std::string linePlot(const std::vector<PlotSeries>& series, const PlotOptions& o) {
  Frame f = plotFrame(o);
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const PlotSeries& s : series) {
    for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      x0 = std::min(x0, s.x[i]), x1 = std::max(x1, s.x[i]);
      y0 = std::min(y0, s.y[i]), y1 = std::max(y1, s.y[i]);
    }
  }
  widen(x0, x1);
  widen(y0, y1);
  const double px = (x1 - x0) * 0.03, py = (y1 - y0) * 0.05;
  f.x0 = x0 - px, f.x1 = x1 + px, f.y0 = y0 - py, f.y1 = y1 + py;
  if (o.equal_aspect) {
    // Grow the shorter range so one metre spans as many pixels across as up.
    const double sx = (f.x1 - f.x0) / (f.right - f.left), sy = (f.y1 - f.y0) / (f.bottom - f.top);
    if (sx > sy) {
      const double c = (f.y0 + f.y1) / 2, h = sx * (f.bottom - f.top) / 2;
      f.y0 = c - h, f.y1 = c + h;
    } else {
      const double c = (f.x0 + f.x1) / 2, h = sy * (f.right - f.left) / 2;
      f.x0 = c - h, f.x1 = c + h;
    }
  }
  std::string s = open(o) + axes(f, o);
  for (const PlotSeries& ser : series) {
    const size_t n = std::min(ser.x.size(), ser.y.size());
    if (ser.line && n > 1) {
      std::string points;
      for (size_t i = 0; i < n; ++i) {
        if (!std::isfinite(ser.x[i]) || !std::isfinite(ser.y[i])) continue;
        points += num(f.px(ser.x[i])) + "," + num(f.py(ser.y[i])) + " ";
      }
      s += fmt::format(
          "<polyline fill=\"none\" stroke=\"{}\" stroke-width=\"{}\" "
          "stroke-linejoin=\"round\" points=\"{}\"/>\n",
          ser.color, ser.line_width, points);
    }
    if (ser.marker_radius > 0) {
      for (size_t i = 0; i < n; ++i) {
        if (!std::isfinite(ser.x[i]) || !std::isfinite(ser.y[i])) continue;
        s += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"{}\" fill=\"{}\"/>", num(f.px(ser.x[i])),
                         num(f.py(ser.y[i])), ser.marker_radius, ser.color);
        if (i < ser.point_labels.size() && !ser.point_labels[i].empty()) {
          s += fmt::format("<text x=\"{}\" y=\"{}\" font-size=\"8\" fill=\"#555\">{}</text>",
                           num(f.px(ser.x[i]) + 3), num(f.py(ser.y[i]) - 3),
                           escapeXml(ser.point_labels[i]));
        }
      }
      s += "\n";
    }
  }
  // Legend, top right inside the plot.
  double ly = f.top + 14;
  for (const PlotSeries& ser : series) {
    if (ser.label.empty()) continue;
    s += fmt::format(
        "<rect x=\"{}\" y=\"{}\" width=\"14\" height=\"4\" fill=\"{}\"/>"
        "<text x=\"{}\" y=\"{}\" text-anchor=\"end\">{}</text>\n",
        num(f.right - 20), num(ly - 5), ser.color, num(f.right - 24), num(ly),
        escapeXml(ser.label));
    ly += 14;
  }
  return s + "</svg>\n";
}

std::string histogramPlot(const std::vector<double>& values, int bins, const std::string& color,
                          const PlotOptions& o, double lo, double hi) {
  Frame f = plotFrame(o);
  if (!(lo < hi)) {
    lo = values.empty() ? 0.0 : *std::min_element(values.begin(), values.end());
    hi = values.empty() ? 1.0 : *std::max_element(values.begin(), values.end());
  }
  widen(lo, hi);
  bins = std::max(1, bins);
  std::vector<int> counts(static_cast<size_t>(bins), 0);
  const double width = (hi - lo) / bins;
  for (double v : values) {
    if (!std::isfinite(v)) continue;
    const int b = std::clamp(static_cast<int>(std::floor((v - lo) / width)), 0, bins - 1);
    ++counts[static_cast<size_t>(b)];
  }
  f.x0 = lo, f.x1 = hi, f.y0 = 0;
  f.y1 = std::max(1, *std::max_element(counts.begin(), counts.end())) * 1.08;
  std::string s = open(o);
  for (int b = 0; b < bins; ++b) {
    const double x = f.px(lo + b * width), w = f.px(lo + (b + 1) * width) - x;
    const double y = f.py(counts[static_cast<size_t>(b)]);
    s += fmt::format(
        "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{}\" fill-opacity=\"0.75\" "
        "stroke=\"white\" stroke-width=\"0.5\"/>",
        num(x), num(y), num(std::max(0.0, w)), num(f.bottom - y), color);
  }
  return s + "\n" + axes(f, o) + "</svg>\n";
}

std::string rangePlot(const std::vector<RangeRow>& rows, const PlotOptions& o) {
  Frame f = plotFrame(o);
  f.left = 120;
  double hi = 0.0;
  for (const RangeRow& r : rows) {
    for (double v : r.values) hi = std::max(hi, v);
  }
  f.x0 = 0.0, f.x1 = hi > 0 ? hi * 1.05 : 1.0;
  f.y0 = 0.0, f.y1 = std::max<double>(1, rows.size());
  std::string s = open(o);
  s += axes(f, o, false);  // no y ticks: the rows are named instead
  for (size_t i = 0; i < rows.size(); ++i) {
    const Summary st = summarize(rows[i].values);
    const double lo = percentile(rows[i].values, 5.0);
    const double row_centre = f.py(f.y1 - static_cast<double>(i) - 0.5);
    const double h = std::min(18.0, (f.bottom - f.top) / f.y1 * 0.5);
    const double top = row_centre - h / 2, bottom = row_centre + h / 2;
    s += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"end\">{}</text>", num(f.left - 6),
                     num(row_centre + 4), escapeXml(rows[i].label));
    s += fmt::format(
        "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"#9ecae1\" "
        "stroke=\"#3182bd\"/>",
        num(f.px(lo)), num(top), num(std::max(1.0, f.px(st.p95) - f.px(lo))), num(h));
    s += fmt::format(
        "<line x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\" stroke=\"#08306b\" "
        "stroke-width=\"2\"/>",
        num(f.px(st.median)), num(top), num(bottom));
    s += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"3\" fill=\"#d62728\"/>", num(f.px(st.p99)),
                     num(row_centre));
    s += fmt::format(
        "<text x=\"{}\" y=\"{}\" font-size=\"9\" fill=\"#333\">median {:.1f}, p95 {:.1f}, "
        "p99 {:.1f} ms</text>\n",
        num(f.px(lo)), num(top - 3), st.median, st.p95, st.p99);
  }
  return s + "</svg>\n";
}

}  // namespace parkloc::eval
