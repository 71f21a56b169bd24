#include "sim/drive.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace parkloc::sim {
namespace {

constexpr double kStep = 0.02;  // metres between path points

struct PathPoint {
  double x, y, yaw;
  int direction;     // +1 forward, -1 reverse
  double curvature;  // of the path traced by the rear axle, 1/m
  bool stop_before = false;
};

// Builds a path piece by piece, like a turtle.
class PathBuilder {
 public:
  PathBuilder(double x, double y, double yaw) : x_(x), y_(y), yaw_(yaw) {
    points_.push_back({x, y, yaw, +1, 0.0, false});
  }
  void straight(double length, int direction) { piece(length, 0.0, direction); }
  // Arc turning the heading by `angle` (positive = counter-clockwise) at radius r, driving
  // forward or in reverse.
  void arc(double r, double angle, int direction) {
    piece(r * std::abs(angle), (angle > 0 ? 1.0 : -1.0) / r, direction);
  }
  double length() const { return (points_.size() - 1) * kStep; }
  std::vector<PathPoint>& points() { return points_; }
  double x() const { return x_; }
  double y() const { return y_; }

 private:
  // yaw_per_metre: the signed heading change per metre travelled (either direction).
  void piece(double length, double yaw_per_metre, int direction) {
    const int n = std::max(1, static_cast<int>(std::lround(length / kStep)));
    const double ds = length / n;
    const bool reversal =
        !points_.empty() && points_.back().direction != direction && points_.size() > 1;
    for (int i = 0; i < n; ++i) {
      // Midpoint integration of the unicycle.
      const double mid = yaw_ + 0.5 * yaw_per_metre * ds;
      x_ += direction * ds * std::cos(mid);
      y_ += direction * ds * std::sin(mid);
      yaw_ += yaw_per_metre * ds;
      points_.push_back({x_, y_, yaw_, direction, yaw_per_metre, reversal && i == 0});
    }
    if (points_.size() == static_cast<size_t>(n) + 1) points_.front().direction = direction;
  }
  double x_, y_, yaw_;
  std::vector<PathPoint> points_;
};

// Time-parameterises the path: trapezoidal speeds per run of one direction, stopping
// (and waiting `pause` s) where the direction changes, limited lateral acceleration.
std::vector<DriveState> timeParameterise(const std::vector<PathPoint>& pts, double cruise,
                                         double reverse_speed, double pause, double end_pause) {
  const size_t n = pts.size();
  std::vector<double> vmax(n), v(n);
  const double accel = 0.9, decel = 1.2, lateral = 1.4;
  for (size_t i = 0; i < n; ++i) {
    vmax[i] = pts[i].direction > 0 ? cruise : reverse_speed;
    const double yaw_rate_per_m = std::abs(pts[i].curvature);
    if (yaw_rate_per_m > 1e-6) vmax[i] = std::min(vmax[i], std::sqrt(lateral / yaw_rate_per_m));
  }
  // Zero speed at the ends and at every reversal.
  std::vector<bool> zero(n, false);
  zero[0] = zero[n - 1] = true;
  for (size_t i = 1; i < n; ++i)
    if (pts[i].stop_before) zero[i - 1] = true;
  for (size_t i = 0; i < n; ++i) v[i] = zero[i] ? 0.0 : vmax[i];
  for (size_t i = 1; i < n; ++i)
    if (!zero[i]) v[i] = std::min(v[i], std::sqrt(v[i - 1] * v[i - 1] + 2 * accel * kStep));
  for (size_t i = n - 1; i-- > 0;)
    if (!zero[i]) v[i] = std::min(v[i], std::sqrt(v[i + 1] * v[i + 1] + 2 * decel * kStep));
  // Points along the path with their times.
  std::vector<DriveState> timed;
  double t = 0.0;
  timed.push_back({0.0, geometry::Pose2(pts[0].x, pts[0].y, pts[0].yaw), 0.0, 0.0});
  for (size_t i = 1; i < n; ++i) {
    if (zero[i - 1] && i > 1) {
      t += pause;
      timed.push_back({t, geometry::Pose2(pts[i - 1].x, pts[i - 1].y, pts[i - 1].yaw), 0.0, 0.0});
    }
    const double vm = 0.5 * (v[i - 1] + v[i]);
    t += kStep / std::max(vm, 0.05);
    timed.push_back(
        {t, geometry::Pose2(pts[i].x, pts[i].y, pts[i].yaw), pts[i].direction * v[i], 0.0});
  }
  t += end_pause;
  timed.push_back({t, timed.back().pose, 0.0, 0.0});
  // Resample at 100 Hz and differentiate the heading for the yaw rate.
  std::vector<DriveState> out;
  const double dt = 0.01;
  size_t j = 0;
  for (double s = 0.0; s <= t + 1e-9; s += dt) {
    while (j + 2 < timed.size() && timed[j + 1].t < s) ++j;
    const DriveState& a = timed[j];
    const DriveState& b = timed[j + 1];
    const double w = b.t > a.t ? std::clamp((s - a.t) / (b.t - a.t), 0.0, 1.0) : 0.0;
    DriveState st;
    st.t = s;
    st.pose =
        geometry::Pose2(a.pose.x + w * (b.pose.x - a.pose.x), a.pose.y + w * (b.pose.y - a.pose.y),
                        a.pose.yaw + w * geometry::wrapAngle(b.pose.yaw - a.pose.yaw));
    st.speed = a.speed + w * (b.speed - a.speed);
    out.push_back(st);
  }
  for (size_t i = 0; i < out.size(); ++i) {
    const size_t lo = i > 0 ? i - 1 : i, hi = i + 1 < out.size() ? i + 1 : i;
    if (hi > lo)
      out[i].yaw_rate =
          geometry::wrapAngle(out[hi].pose.yaw - out[lo].pose.yaw) / (out[hi].t - out[lo].t);
  }
  return out;
}

}  // namespace

DriveState Drive::at(double t) const {
  if (states_.empty()) return {};
  if (t <= states_.front().t) return states_.front();
  if (t >= states_.back().t) return states_.back();
  const double dt = states_[1].t - states_[0].t;
  const size_t i = std::min(states_.size() - 2, static_cast<size_t>((t - states_[0].t) / dt));
  const DriveState& a = states_[i];
  const DriveState& b = states_[i + 1];
  const double w = std::clamp((t - a.t) / (b.t - a.t), 0.0, 1.0);
  DriveState s;
  s.t = t;
  s.pose =
      geometry::Pose2(a.pose.x + w * (b.pose.x - a.pose.x), a.pose.y + w * (b.pose.y - a.pose.y),
                      a.pose.yaw + w * geometry::wrapAngle(b.pose.yaw - a.pose.yaw));
  s.speed = a.speed + w * (b.speed - a.speed);
  s.yaw_rate = a.yaw_rate + w * (b.yaw_rate - a.yaw_rate);
  return s;
}

Drive planDrive(const Garage& g, int level, const DriveSpec& spec, uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto uniform = [&](double a, double b) {
    return std::uniform_real_distribution<double>(a, b)(rng);
  };
  const GarageSpec& gs = g.spec;
  const int aisles = static_cast<int>(g.aisle_y.size());
  const double cruise = uniform(2.0, 3.8);
  const double reverse_speed = uniform(1.0, 1.4);
  auto lane = [&](int aisle, int dir) { return g.aisle_y[aisle] - 0.6 * dir; };

  if (spec.route == "park") {
    // A free slot with room for the approach and the reverse arc.
    const GarageLevel& L = g.levels.at(level);
    std::vector<size_t> free;
    for (size_t i = 0; i < L.slots.size(); ++i)
      if (!L.slots[i].occupied) free.push_back(i);
    if (free.empty()) free.push_back(0);
    // The reverse arc starts R past the slot; the car (front bumper 3.7 m ahead of the rear
    // axle, rear camera 1 m behind) must stay inside the walls there: pick a slot and a
    // direction that allow it.
    const double R = 4.5;
    int dir = std::uniform_int_distribution<int>(0, 1)(rng) ? 1 : -1;
    const double approach = uniform(7.0, 13.0);
    auto fits = [&](const Slot& s, int d) {
      const double x_rev = s.center.x() + d * R;
      return x_rev + d * 4.2 > 0.5 && x_rev + d * 4.2 < g.size.x() - 0.5 && x_rev - d * 1.5 > 0.5 &&
             x_rev - d * 1.5 < g.size.x() - 0.5;
    };
    size_t pick = std::uniform_int_distribution<size_t>(0, free.size() - 1)(rng);
    for (size_t tries = 0;
         tries < free.size() && !fits(L.slots[free[pick]], dir) && !fits(L.slots[free[pick]], -dir);
         ++tries)
      pick = (pick + 1) % free.size();
    const Slot& slot = L.slots[free[pick]];
    if (!fits(slot, dir)) dir = -dir;
    const double x_rev = slot.center.x() + dir * R;
    const double x_start = std::clamp(x_rev - dir * approach, 1.5, g.size.x() - 1.5);
    const double y_lane = g.aisle_y[slot.aisle] - 0.8 * slot.side;
    PathBuilder path(x_start, y_lane, dir > 0 ? 0.0 : M_PI);
    path.straight(std::abs(x_rev - x_start), +1);
    // Relative to the heading the slot is on the left when side * dir > 0.
    const int left = slot.side * dir;
    path.arc(R, -left * M_PI / 2, -1);
    const double y_edge = g.aisle_y[slot.aisle] + slot.side * gs.aisle_width / 2;
    const double y_final = y_edge + slot.side * (gs.slot_depth - 1.25);
    path.straight(std::max(0.2, std::abs(y_final - path.y())), -1);
    return Drive(timeParameterise(path.points(), cruise, reverse_speed, 1.0, 1.0));
  }

  // Tour: along an aisle, through the cross aisle into the next, and on.
  int a = std::uniform_int_distribution<int>(0, aisles - 1)(rng);
  int dir = std::uniform_int_distribution<int>(0, 1)(rng) ? 1 : -1;
  int dy = a + 1 < aisles ? 1 : -1;
  const double R = 3.0;
  const double x_turn0 = (dir > 0 ? g.cross_x1 : g.cross_x0) - dir * R;
  const double x_start = x_turn0 - dir * uniform(8.0, 25.0);
  PathBuilder path(std::clamp(x_start, 1.5, g.size.x() - 1.5), lane(a, dir), dir > 0 ? 0.0 : M_PI);
  const double wanted = cruise * spec.duration_s + 10.0;
  while (path.length() < wanted) {
    const double x_turn = (dir > 0 ? g.cross_x1 : g.cross_x0) - dir * R;
    path.straight(std::max(0.1, dir * (x_turn - path.x())), +1);
    if (aisles == 1) {
      path.arc(R, M_PI / 2, +1);
      path.straight(2.0, +1);
      break;
    }
    if (a + dy < 0 || a + dy >= aisles) dy = -dy;
    const int next = a + dy;
    path.arc(R, dir * dy * M_PI / 2, +1);
    path.straight(std::max(0.1, std::abs(lane(next, -dir) - path.y()) - R), +1);
    path.arc(R, dir * dy * M_PI / 2, +1);
    a = next;
    dir = -dir;
  }
  std::vector<DriveState> states = timeParameterise(path.points(), cruise, reverse_speed, 1.0, 0.0);
  // Cut at the requested duration.
  while (!states.empty() && states.back().t > spec.duration_s) states.pop_back();
  return Drive(std::move(states));
}

std::vector<OdometrySample> simulateOdometry(const Drive& drive, double rate, uint64_t seed,
                                                 const OdometryNoise& noise) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const double scale = 1.0 + noise.speed_scale_sigma * gauss(rng);
  const double bias = noise.yaw_rate_bias_sigma * gauss(rng);
  std::vector<OdometrySample> out;
  const int n = static_cast<int>(std::floor(drive.duration() * rate + 1e-9)) + 1;
  for (int k = 0; k < n; ++k) {
    const double t = k / rate;
    const DriveState s = drive.at(t);
    OdometrySample o;
    o.timestamp = t;
    o.speed = std::abs(s.speed) < 1e-3 ? 0.0 : scale * s.speed + noise.speed_sigma * gauss(rng);
    o.yaw_rate = s.yaw_rate + bias + noise.yaw_rate_sigma * gauss(rng);
    out.push_back(o);
  }
  return out;
}

}  // namespace parkloc::sim
