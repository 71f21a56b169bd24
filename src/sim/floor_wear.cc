#include "sim/floor_wear.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace parkloc::sim {
namespace {

double uniform(std::mt19937_64& rng, double a, double b) {
  return std::uniform_real_distribution<double>(a, b)(rng);
}

// Points of a canvas in 1/16 texels (cv drawing's shift of 4).
cv::Point fixedPoint(double x, double y, double tpm) {
  return {static_cast<int>(std::lround(x * tpm * 16)), static_cast<int>(std::lround(y * tpm * 16))};
}

void polyline(cv::Mat& canvas, const std::vector<Eigen::Vector2d>& pts, double tpm, double width_m,
              double darkness) {
  std::vector<cv::Point> p;
  for (const auto& q : pts) p.push_back(fixedPoint(q.x(), q.y(), tpm));
  const int thickness = std::max(1, static_cast<int>(std::lround(width_m * tpm)));
  cv::polylines(canvas, std::vector<std::vector<cv::Point>>{p}, false,
                cv::Scalar(std::clamp(darkness, 0.0, 1.0) * 255.0), thickness, cv::LINE_AA, 4);
}

// A tyre's track: a line drifting a little sideways, as no driver holds a lane exactly.
std::vector<Eigen::Vector2d> drift(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                   double amplitude, std::mt19937_64& rng) {
  const Eigen::Vector2d along = b - a;
  const Eigen::Vector2d n = Eigen::Vector2d(-along.y(), along.x()).normalized();
  const double phase = uniform(rng, 0.0, 6.3), wavelength = uniform(rng, 6.0, 15.0);
  const int steps = std::max(2, static_cast<int>(along.norm() / 0.25));
  std::vector<Eigen::Vector2d> out;
  for (int i = 0; i <= steps; ++i) {
    const double t = static_cast<double>(i) / steps;
    out.push_back(a + t * along +
                  amplitude * std::sin(phase + t * along.norm() / wavelength * 6.283) * n);
  }
  return out;
}

// A quadratic Bezier curve from a to c bending toward b: the path of a wheel turning into a slot.
std::vector<Eigen::Vector2d> arc(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                 const Eigen::Vector2d& c) {
  std::vector<Eigen::Vector2d> out;
  for (int i = 0; i <= 24; ++i) {
    const double t = i / 24.0;
    out.push_back((1 - t) * (1 - t) * a + 2 * (1 - t) * t * b + t * t * c);
  }
  return out;
}

}  // namespace

cv::Mat floorGrime(const Garage& g, const GarageLevel& level, float strength,
                   std::mt19937_64& rng) {
  const double tpm = g.grime_texels_per_metre;
  const cv::Size size(static_cast<int>(std::ceil(g.size.x() * tpm)),
                      static_cast<int>(std::ceil(g.size.y() * tpm)));
  const double s = std::clamp(static_cast<double>(strength), 0.0, 1.0);
  const double area = g.size.x() * g.size.y();
  // Darkness layers (0: none, 255: black), drawn antialiased in 8 bits.
  cv::Mat tyres(size, CV_8UC1, cv::Scalar(0)), oil(size, CV_8UC1, cv::Scalar(0)),
      cracks(size, CV_8UC1, cv::Scalar(0));

  // Tyre streaks along both lanes of each aisle and the cross aisles, in broken pairs of wheels
  // 1.6 m apart; rubber darkens the floor by 10-35 %.
  auto streaks = [&](const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
    const Eigen::Vector2d dir = (to - from).normalized();
    const Eigen::Vector2d n(-dir.y(), dir.x());
    const double length = (to - from).norm();
    for (const double lane : {-1.5, 1.5})
      for (double t = uniform(rng, 0.0, 4.0); t < length;) {
        const double len = uniform(rng, 3.0, 14.0) * (0.5 + 0.5 * s);
        const double offset = lane + uniform(rng, -0.4, 0.4);
        const double dark = uniform(rng, 0.1, 0.35) * s;
        const double width = uniform(rng, 0.06, 0.14);
        for (const double wheel : {-0.8, 0.8}) {
          const Eigen::Vector2d a = from + t * dir + (offset + wheel) * n;
          const Eigen::Vector2d b = from + std::min(length, t + len) * dir + (offset + wheel) * n;
          polyline(tyres, drift(a, b, uniform(rng, 0.05, 0.2), rng), tpm, width, dark);
        }
        t += len + uniform(rng, 0.5, 6.0) / (0.3 + s);
      }
  };
  for (const double y : g.aisle_y) streaks({g.cross_x0, y}, {g.cross_x1, y});
  for (const double x : {g.cross_x0, g.cross_x1}) streaks({x, 1.0}, {x, g.size.y() - 1.0});

  // Slots: arcs of the wheels that turned in, oil under the engine.
  for (const Slot& slot : level.slots) {
    const double side = slot.side;
    const double depth_half = 2.6;
    const Eigen::Vector2d mouth = slot.center - Eigen::Vector2d(0.0, side * depth_half);
    if (uniform(rng, 0.0, 1.0) < 0.45 * s) {
      const double from_x = uniform(rng, 2.5, 5.0) * (uniform(rng, 0, 1) < 0.5 ? -1 : 1);
      const double dark = uniform(rng, 0.12, 0.3) * s;
      for (const double wheel : {-0.8, 0.8}) {
        const Eigen::Vector2d a = mouth + Eigen::Vector2d(from_x + wheel, -side * 2.2);
        const Eigen::Vector2d b = mouth + Eigen::Vector2d(wheel, -side * 1.2);
        const Eigen::Vector2d c = mouth + Eigen::Vector2d(wheel, side * 2.0);
        polyline(tyres, arc(a, b, c), tpm, 0.1, dark);
      }
    }
    const int stains = static_cast<int>(uniform(rng, 0.0, 3.5 * s));
    for (int i = 0; i < stains; ++i) {
      // Under the engine, near either end of a car standing in the slot.
      const double along = (uniform(rng, 0, 1) < 0.7 ? -1.0 : 1.0) * side * uniform(rng, 0.9, 1.7);
      const Eigen::Vector2d c = slot.center + Eigen::Vector2d(uniform(rng, -0.5, 0.5), along);
      const double r = uniform(rng, 0.08, 0.45);
      const int blobs = 3 + static_cast<int>(uniform(rng, 0, 4));
      const double dark = uniform(rng, 0.25, 0.6) * (0.4 + 0.6 * s);
      for (int k = 0; k < blobs; ++k) {
        const Eigen::Vector2d q =
            c + r * Eigen::Vector2d(uniform(rng, -0.8, 0.8), uniform(rng, -0.8, 0.8));
        cv::ellipse(oil, fixedPoint(q.x(), q.y(), tpm),
                    cv::Size(static_cast<int>(r * uniform(rng, 0.4, 1.0) * tpm * 16),
                             static_cast<int>(r * uniform(rng, 0.3, 0.9) * tpm * 16)),
                    uniform(rng, 0, 180), 0, 360, cv::Scalar(dark * 255 * uniform(rng, 0.6, 1.0)),
                    -1, cv::LINE_AA, 4);
      }
    }
  }

  // Hairline cracks: wandering lines with an occasional branch, 1-2 cm wide.
  const int crack_count = static_cast<int>(area / 60.0 * s);
  for (int i = 0; i < crack_count; ++i) {
    Eigen::Vector2d p(uniform(rng, 0, g.size.x()), uniform(rng, 0, g.size.y()));
    double heading = uniform(rng, 0, 6.283);
    const int steps = static_cast<int>(uniform(rng, 10, 60));
    std::vector<Eigen::Vector2d> pts{p};
    const double dark = uniform(rng, 0.3, 0.55);
    for (int k = 0; k < steps; ++k) {
      heading += uniform(rng, -0.5, 0.5);
      p += uniform(rng, 0.05, 0.15) * Eigen::Vector2d(std::cos(heading), std::sin(heading));
      pts.push_back(p);
      if (uniform(rng, 0, 1) < 0.04) {
        const double h = heading + uniform(rng, 0.6, 1.2) * (uniform(rng, 0, 1) < 0.5 ? -1 : 1);
        Eigen::Vector2d q = p;
        std::vector<Eigen::Vector2d> branch{q};
        for (int j = 0; j < 8; ++j) {
          q += 0.08 * Eigen::Vector2d(std::cos(h + uniform(rng, -0.4, 0.4)),
                                      std::sin(h + uniform(rng, -0.4, 0.4)));
          branch.push_back(q);
        }
        polyline(cracks, branch, tpm, 0.01, dark * 0.7);
      }
    }
    polyline(cracks, pts, tpm, 0.015, dark);
  }

  cv::Mat grime(size, CV_32F, cv::Scalar(1.0f));
  // Repair patches: rectangles of concrete poured later, lighter or darker than the slab.
  const int patch_count = static_cast<int>(area / 120.0 * s) + 1;
  for (int i = 0; i < patch_count; ++i) {
    const double w = uniform(rng, 0.8, 3.5), h = uniform(rng, 0.6, 2.5);
    const double x = uniform(rng, 0, g.size.x() - w), y = uniform(rng, 0, g.size.y() - h);
    const double tone =
        uniform(rng, 0.0, 1.0) < 0.5 ? uniform(rng, 0.8, 0.92) : uniform(rng, 1.06, 1.15);
    cv::rectangle(grime, cv::Point(static_cast<int>(x * tpm), static_cast<int>(y * tpm)),
                  cv::Point(static_cast<int>((x + w) * tpm), static_cast<int>((y + h) * tpm)),
                  cv::Scalar(tone), -1);
  }
  cv::GaussianBlur(grime, grime, cv::Size(0, 0), 0.8);
  cv::Mat t, o, c;
  tyres.convertTo(t, CV_32F, 1.0 / 255);
  oil.convertTo(o, CV_32F, 1.0 / 255);
  cracks.convertTo(c, CV_32F, 1.0 / 255);
  cv::GaussianBlur(t, t, cv::Size(0, 0), 0.7);
  // Oil soaks in: a dark core and a wider faint halo.
  cv::Mat halo;
  cv::GaussianBlur(o, halo, cv::Size(0, 0), 4.0);
  cv::GaussianBlur(o, o, cv::Size(0, 0), 1.0);
  o = cv::max(o, 0.5 * halo);
  for (const cv::Mat* layer : {&t, &o, &c}) grime = grime.mul(1.0 - cv::min(*layer, 0.85));
  return grime;
}

}  // namespace parkloc::sim
