#include "localize/pipeline.h"

#include <fmt/format.h>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include <time.h>

#include "common/error.h"
#include "geometry/ground_projection.h"
#include "localize/association_gate.h"
#include "localize/box_plot_filter.h"
#include "localize/floor_heights.h"
#include "localize/paper_projection.h"
#include "localize/pose_ekf.h"
#include "localize/pose_solver.h"
#include "localize/region_budget.h"
#include "localize/roi_prediction.h"
#include "localize/search_window.h"
#include "map/placed_texts.h"

namespace parkloc::localize {
namespace {

using Clock = std::chrono::steady_clock;
// CPU time of the process, all threads, milliseconds.
double processCpuMs() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double positionSigma(const Eigen::Matrix3d& covariance) {
  const Eigen::Matrix2d p = covariance.topLeftCorner<2, 2>();
  return std::sqrt(
      std::max(0.0, Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(p, Eigen::EigenvaluesOnly)
                        .eigenvalues()
                        .maxCoeff()));
}

std::array<Eigen::Vector2d, 4> toEigen(const std::array<cv::Point2f, 4>& polygon) {
  std::array<Eigen::Vector2d, 4> out;
  for (int i = 0; i < 4; ++i) out[i] = {polygon[i].x, polygon[i].y};
  return out;
}

double polygonArea(const std::array<Eigen::Vector2d, 4>& q) {
  double a = 0.0;
  for (int i = 0; i < 4; ++i) {
    const auto& p = q[i];
    const auto& n = q[(i + 1) % 4];
    a += 0.5 * (p.x() * n.y() - p.y() * n.x());
  }
  return std::abs(a);
}

// A fix's covariance as the filter sees it: inflated, grown by how much worse than the
// assumed pixel noise the corners fit (a-posteriori variance factor: a fix from one text
// seen at a grazing angle whose corners fit to 6 px must not count as one that fits to 1),
// with a floor (1 cm, 0.05 degrees).
Eigen::Matrix3d fixCovariance(const SolverResult& fix, const PipelineOptions& options) {
  const double fit = options.pixel_sigma > 0.0 ? fix.rms_px / options.pixel_sigma : 0.0;
  Eigen::Matrix3d R = options.fix_covariance_inflation * std::max(1.0, fit * fit) * fix.covariance;
  const double yaw_floor = 0.05 * M_PI / 180.0;
  R.diagonal() += Eigen::Vector3d(1e-4, 1e-4, yaw_floor * yaw_floor);
  return R;
}

}  // namespace

PipelineOptions PipelineOptions::paper() {
  PipelineOptions o;
  o.paper_mode = true;
  o.use_odometry = false;
  o.map_guided = false;
  o.full_frame_interval = 1;
  o.use_pillar_text = false;
  return o;
}

std::string toString(TrackingStatus status) {
  switch (status) {
    case TrackingStatus::kNotInitialised:
      return "not_initialised";
    case TrackingStatus::kOk:
      return "ok";
    case TrackingStatus::kDeadReckoning:
      return "dead_reckoning";
    case TrackingStatus::kLost:
      return "lost";
  }
  return "unknown";
}

std::string toString(AssociationVerdict verdict) {
  switch (verdict) {
    case AssociationVerdict::kAccepted:
      return "accepted";
    case AssociationVerdict::kWrongClass:
      return "wrong_class";
    case AssociationVerdict::kLowScore:
      return "low_score";
    case AssociationVerdict::kNotInMap:
      return "not_in_map";
    case AssociationVerdict::kAnomaly:
      return "anomaly";
    case AssociationVerdict::kGated:
      return "gated";
    case AssociationVerdict::kFlipped:
      return "flipped";
    case AssociationVerdict::kSolverOutlier:
      return "solver_outlier";
    case AssociationVerdict::kNoGeometry:
      return "no_geometry";
    case AssociationVerdict::kAmbiguous:
      return "ambiguous";
    case AssociationVerdict::kUnconfirmed:
      return "unconfirmed";
    case AssociationVerdict::kPartial:
      return "partial";
  }
  return "unknown";
}

struct Pipeline::Impl {
  geometry::Rig rig;
  map::HdMap map;
  PipelineOptions options;
  ocr::TextSpotter* spotter = nullptr;

  FloorHeights floors;
  std::vector<geometry::GroundHomography> homographies;
  std::vector<std::string> lexicon;        // every text of the map (full-frame spotting)
  std::vector<std::string> floor_lexicon;  // the texts of it painted on the floor
  SolverOptions solver_options;
  GateOptions gate_options;
  RoiOptions roi_options;

  // State.
  BoxPlotFilter afm;
  PoseEkf ekf;
  bool have_frame = false;
  double last_frame_time = 0.0;
  bool have_odometry = false;
  io::OdometrySample hold;  // latest odometry sample (zero-order hold)
  int frames_since_full_frame = 0;
  // Region budget and full-frame round robin: frames processed, tracking frames since the
  // track began, the camera whose turn is next, and when each landmark was last asked for.
  int frame_index = 0;
  int tracking_frames = 0;
  size_t next_full_frame_camera = 0;
  size_t next_search_camera = 0;
  // Searching: texts matched in the last frame sets, carried along by odometry.
  SearchWindow search_window;
  std::map<std::string, int> last_asked;
  // Tracking: the frame index at which each landmark was last read and accepted.
  std::map<std::string, int> last_read;
  std::map<std::string, int> last_read_attempt;
  // Re-localisation: consecutive fixes that disagree with the filter.
  int disagreeing_fixes = 0;
  bool disagreeing_with_consensus = false;  // one of them had two or more landmarks
  geometry::Pose2 last_disagreeing_fix;
  geometry::Pose2 predicted_at_last_disagreeing_fix;
  // The level being driven on when PipelineOptions::level is empty: voted by the texts
  // seen while not tracking (garages repeat parking numbers on every level), kept while
  // tracking.
  std::string active_level;
  // Without odometry: the filtered pose at the last fix and the motion since the one before.
  std::optional<std::pair<double, geometry::Pose2>> last_fix;
  std::optional<io::OdometrySample> visual_motion;
  // Paper mode.
  bool paper_has_pose = false;
  geometry::Pose2 paper_pose;
  double paper_yaw = 0.0;
  Eigen::Vector2d paper_motion_anchor = Eigen::Vector2d::Zero();

  Impl(geometry::Rig r, map::HdMap m, const PipelineOptions& o, ocr::TextSpotter* s)
      : rig(std::move(r)), map(std::move(m)), options(o), spotter(s), floors(map) {
    for (const auto& camera : rig.cameras)
      homographies.push_back(geometry::GroundHomography::fromCamera(camera));
    for (const auto& l : map.landmarks())
      if (options.level.empty() || l.level == options.level) {
        lexicon.push_back(l.text);
        if (l.surface == map::Surface::kGround) floor_lexicon.push_back(l.text);
      }
    solver_options.pixel_sigma = options.pixel_sigma;
    solver_options.huber_threshold_px = options.huber_threshold_px;
    solver_options.max_iterations = options.solver_max_iterations;
    solver_options.inlier_threshold_px = options.inlier_threshold_px;
    gate_options.min_radius_m = options.gate_min_radius_m;
    roi_options.margin_px = options.roi_margin_px;
    roi_options.min_size_px = options.roi_min_size_px;
    EkfOptions ekf_options;
    ekf_options.speed_sigma = options.odo_speed_sigma;
    ekf_options.yaw_rate_sigma = options.odo_yaw_rate_sigma;
    ekf_options.yaw_rate_bias_sigma = options.odo_yaw_rate_bias_sigma;
    ekf_options.yaw_rate_bias_walk = options.odo_yaw_rate_bias_walk;
    ekf_options.no_odometry_position_sigma = options.no_odometry_pos_sigma;
    ekf_options.no_odometry_yaw_sigma = options.no_odometry_yaw_sigma;
    ekf = PoseEkf(ekf_options);
    reset();
  }

  void reset() {
    BoxPlotFilterOptions afm_options;
    afm_options.queue_length = static_cast<size_t>(std::max(1, options.afm_queue_length));
    afm_options.iqr_factor = options.afm_iqr_factor;
    afm_options.reset_after_rejections =
        static_cast<size_t>(std::max(0, options.afm_reset_after_rejections));
    afm = BoxPlotFilter(afm_options);
    ekf.reset();
    have_frame = false;
    have_odometry = false;
    hold = {};
    frames_since_full_frame = 0;
    frame_index = 0;
    tracking_frames = 0;
    next_full_frame_camera = 0;
    next_search_camera = 0;
    search_window = SearchWindow(searchWindowFrames());
    last_asked.clear();
    last_read.clear();
    last_read_attempt.clear();
    disagreeing_fixes = 0;
    disagreeing_with_consensus = false;
    paper_has_pose = false;
    paper_yaw = 0.0;
    active_level.clear();
    last_fix.reset();
    visual_motion.reset();
    if (options.initial_pose) {
      paper_pose = *options.initial_pose;
      paper_yaw = options.initial_pose->yaw;
      paper_has_pose = options.paper_mode;
      paper_motion_anchor = paper_pose.translation();
      if (!options.paper_mode) {
        const double yaw_sigma = 2.0 * M_PI / 180.0;
        ekf.initialise(*options.initial_pose,
                       Eigen::Vector3d(0.1 * 0.1, 0.1 * 0.1, yaw_sigma * yaw_sigma).asDiagonal(),
                       0.0);
      }
    }
  }

  // One camera per frame set: the window spans a turn of the others.
  size_t searchWindowFrames() const {
    const int per = options.search_cameras_per_frame;
    if (per <= 0 || static_cast<size_t>(per) >= rig.cameras.size()) return 0;
    return (rig.cameras.size() + static_cast<size_t>(per) - 1) / static_cast<size_t>(per) - 1;
  }

  bool tracking() const {
    return ekf.initialised() && positionSigma(ekf.covariance()) <= options.lost_position_sigma_m;
  }

  // Moves the filter to time t with the held odometry (or a random walk without it).
  void predictTo(double t, std::vector<std::string>& warnings) {
    if (!ekf.initialised()) return;
    const double dt = t - ekf.time();
    if (!(dt > 0.0)) return;
    if (options.use_odometry && have_odometry) {
      const double age = t - hold.timestamp;
      const double covered =
          std::min(dt, std::max(0.0, options.odometry_gap_s - (ekf.time() - hold.timestamp)));
      if (age > options.odometry_gap_s)
        warnings.push_back(fmt::format("odometry gap: the last sample is {:.3f} s old", age));
      ekf.predictWithOdometry(hold.speed, hold.yaw_rate, dt);
      if (dt > covered) ekf.predictWithoutOdometry(dt - covered);
    } else if (visual_motion) {
      // No odometry: a constant-velocity guess from the last two fixes, with the random
      // walk on top for its uncertainty.
      ekf.predictWithOdometry(visual_motion->speed, visual_motion->yaw_rate, dt);
      ekf.predictWithoutOdometry(dt);
    } else {
      ekf.predictWithoutOdometry(dt);
    }
    ekf.setTime(t);
  }

  // After a filter update without odometry: the motion between this and the last fix.
  void updateVisualMotion(double t) {
    if (options.use_odometry && have_odometry) return;
    if (last_fix && t > last_fix->first && t - last_fix->first < 0.5) {
      const double dt = t - last_fix->first;
      const geometry::Pose2 delta = last_fix->second.inverse() * ekf.pose();
      io::OdometrySample m;
      m.timestamp = t;
      m.speed = delta.x / dt;
      m.yaw_rate = delta.yaw / dt;
      visual_motion = m;
    } else {
      visual_motion.reset();
    }
    last_fix = std::make_pair(t, ekf.pose());
  }

  // Returns the samples it accepted (finite, each after the last), in order.
  std::vector<io::OdometrySample> consumeOdometry(const FrameInput& frame, bool time_ok,
                                                  std::vector<std::string>& warnings) {
    std::vector<io::OdometrySample> accepted;
    for (const auto& s : frame.odometry) {
      if (!std::isfinite(s.timestamp) || !std::isfinite(s.speed) || !std::isfinite(s.yaw_rate)) {
        warnings.push_back(
            fmt::format("odometry sample at {} is not finite: skipped", s.timestamp));
        continue;
      }
      if (have_odometry && s.timestamp <= hold.timestamp) {
        warnings.push_back(fmt::format("odometry sample at {:.6f} not after {:.6f}: skipped",
                                       s.timestamp, hold.timestamp));
        continue;
      }
      if (time_ok && s.timestamp > frame.timestamp) {
        warnings.push_back(fmt::format(
            "odometry sample at {:.6f} is after the frame: used from now", s.timestamp));
      }
      if (time_ok && ekf.initialised() && !options.paper_mode)
        predictTo(std::min(s.timestamp, frame.timestamp), warnings);
      if (options.paper_mode && options.paper_heading == PaperHeadingSource::kOdometry &&
          have_odometry)
        paper_yaw += hold.yaw_rate * (s.timestamp - hold.timestamp);
      hold = s;
      have_odometry = true;
      accepted.push_back(s);
    }
    if (options.paper_mode && options.paper_heading == PaperHeadingSource::kOdometry &&
        have_odometry && time_ok && frame.timestamp > hold.timestamp) {
      // Integrate up to the frame without consuming the sample.
      paper_yaw += hold.yaw_rate * (frame.timestamp - hold.timestamp);
      hold.timestamp = frame.timestamp;
    }
    return accepted;
  }

  // Tracking: texts read lately are only fitted; of the others, the largest are read,
  // at most max_reads_per_frame over all cameras; the rest wait for a later frame.
  void chooseReadsAndFits(std::vector<std::vector<RegionCandidate>>& candidates, bool sweeping) {
    struct Unread {
      size_t camera, index;
      double size;
    };
    // Whether `when` holds a frame index for `id` within the last reread_interval_frames.
    const auto lately = [&](const std::map<std::string, int>& when, const std::string& id) {
      const auto it = when.find(id);
      return it != when.end() && frame_index - it->second < options.reread_interval_frames;
    };
    std::vector<Unread> unread;
    std::vector<std::vector<bool>> keep(candidates.size());
    for (size_t c = 0; c < candidates.size(); ++c) {
      keep[c].assign(candidates[c].size(), false);
      for (size_t i = 0; i < candidates[c].size(); ++i) {
        RegionCandidate& r = candidates[c][i];
        if (lately(last_read, r.landmark_id)) {
          r.roi.read = false;
          keep[c][i] = r.height_px >= options.tracked_min_height_px;
        } else if (!lately(last_read_attempt, r.landmark_id)) {
          // (A region tried lately and not read, occluded or blurred, waits a while.)
          unread.push_back({c, i, r.size_px});
        }
      }
    }
    std::stable_sort(unread.begin(), unread.end(),
                     [](const Unread& a, const Unread& b) { return a.size > b.size; });
    const size_t reads = sweeping ? 0
                         : options.max_reads_per_frame > 0
                             ? std::min(unread.size(), size_t(options.max_reads_per_frame))
                             : unread.size();
    for (size_t k = 0; k < reads; ++k) {
      keep[unread[k].camera][unread[k].index] = true;
      last_read_attempt[candidates[unread[k].camera][unread[k].index].landmark_id] = frame_index;
    }
    for (size_t c = 0; c < candidates.size(); ++c) {
      std::vector<RegionCandidate> kept;
      for (size_t i = 0; i < candidates[c].size(); ++i)
        if (keep[c][i]) kept.push_back(std::move(candidates[c][i]));
      candidates[c] = std::move(kept);
    }
  }

  FrameResult process(const FrameInput& frame);
  void voteLevel(const std::vector<CameraResult>& cameras);
  void measureParkloc(const std::vector<LandmarkObservation>& inside,
                      const std::vector<LandmarkObservation>& outside, FrameResult& result);
  void measurePaper(const std::vector<LandmarkObservation>& accepted, FrameResult& result);
  std::vector<LandmarkObservation> selectForModules(std::vector<LandmarkObservation> obs) const;
  void markSolve(const std::vector<LandmarkObservation>& obs, const SolverResult& solve,
                 FrameResult& result) const;
};

void Pipeline::Impl::voteLevel(const std::vector<CameraResult>& cameras) {
  std::map<std::string, int> votes;
  for (const auto& c : cameras) {
    for (const auto& t : c.instances) {
      if (t.cls != map::TextClass::kParkingNumber && t.cls != map::TextClass::kPillar) continue;
      std::set<std::string> levels;
      for (const auto* l : map.findByText(t.text)) levels.insert(l->level);
      for (const auto& level : levels) ++votes[level];
    }
  }
  int best = 0;
  bool tie = false;
  std::string winner;
  for (const auto& [level, n] : votes) {
    if (n > best) {
      best = n;
      winner = level;
      tie = false;
    } else if (n == best) {
      tie = true;
    }
  }
  if (best > 0 && !tie) active_level = winner;
}

std::vector<LandmarkObservation> Pipeline::Impl::selectForModules(
    std::vector<LandmarkObservation> obs) const {
  // Without MCRP one camera per landmark (the first in rig order); without MCAP only the
  // landmark that looks largest (the nearest, the most precise).
  if (!options.mcrp) {
    std::vector<LandmarkObservation> kept;
    for (const auto& o : obs) {
      bool seen = false;
      for (const auto& k : kept) seen = seen || k.landmark_id == o.landmark_id;
      if (!seen) kept.push_back(o);
    }
    obs = std::move(kept);
  }
  if (!options.mcap && !obs.empty()) {
    size_t best = 0;
    for (size_t i = 1; i < obs.size(); ++i)
      if (polygonArea(obs[i].pixels) > polygonArea(obs[best].pixels)) best = i;
    const std::string id = obs[best].landmark_id;
    std::vector<LandmarkObservation> kept;
    for (const auto& o : obs)
      if (o.landmark_id == id) kept.push_back(o);
    obs = std::move(kept);
  }
  return obs;
}

void Pipeline::Impl::markSolve(const std::vector<LandmarkObservation>& obs,
                               const SolverResult& solve, FrameResult& result) const {
  for (size_t o = 0; o < obs.size(); ++o) {
    auto& a = result.associations[obs[o].tag];
    if (o < solve.residual_px.size() && std::isfinite(solve.residual_px[o]))
      a.residual_px = solve.residual_px[o];
    if (o < solve.inlier.size() && !solve.inlier[o]) a.verdict = AssociationVerdict::kSolverOutlier;
  }
}

void Pipeline::Impl::measureParkloc(const std::vector<LandmarkObservation>& inside,
                                    const std::vector<LandmarkObservation>& outside,
                                    FrameResult& result) {
  const auto t_solver = Clock::now();
  const bool was_tracking = tracking();
  std::optional<SolverResult> fix;          // agrees with the filter (or initialises it)
  std::optional<SolverResult> disagreeing;  // a good fix far from the prediction
  auto landmarksIn = [](const std::vector<LandmarkObservation>& obs, const SolverResult& s) {
    std::vector<std::string> ids;
    for (size_t o = 0; o < obs.size(); ++o)
      if (s.inlier[o] && std::find(ids.begin(), ids.end(), obs[o].landmark_id) == ids.end())
        ids.push_back(obs[o].landmark_id);
    return static_cast<int>(ids.size());
  };
  int disagreeing_landmarks = 0;

  if (was_tracking) {
    if (!inside.empty()) {
      const SolverResult s = solvePose(rig, inside, ekf.pose(), solver_options);
      result.solver_iterations = s.iterations;
      result.solver_converged = s.converged;
      markSolve(inside, s, result);
      if (s.ok) {
        const Eigen::Matrix3d R = fixCovariance(s, options);
        result.measurement = s.pose;
        result.measurement_covariance = R;
        if (ekf.mahalanobis2(s.pose, R) <= options.fix_gate_chi2) {
          fix = s;
        } else {
          disagreeing = s;
          disagreeing_landmarks = landmarksIn(inside, s);
          result.warnings.push_back("pose fix outside the filter's gate");
        }
      } else {
        result.warnings.push_back("solver: " + s.failure);
      }
    }
    if (!fix && !outside.empty()) {
      // Everything seen is far from the prediction: is it a consistent other place?
      std::vector<LandmarkObservation> all = inside;
      all.insert(all.end(), outside.begin(), outside.end());
      const SolverResult s = solvePose(rig, all, std::nullopt, solver_options);
      const Eigen::Matrix3d R = s.ok ? fixCovariance(s, options) : Eigen::Matrix3d::Zero();
      if (s.ok && ekf.mahalanobis2(s.pose, R) > options.fix_gate_chi2) {
        disagreeing = s;
        disagreeing_landmarks = landmarksIn(all, s);
        if (!result.measurement) {
          result.measurement = s.pose;
          result.measurement_covariance = R;
        }
      }
    }
  } else if (!inside.empty()) {
    // Searching: this frame set's texts and those of the last few, carried by odometry.
    const SearchWindow::Combined all = search_window.combine(rig, inside);
    SolverResult s = solvePose(all.rig, all.observations, std::nullopt, solver_options);
    s.residual_px.resize(std::min(s.residual_px.size(), all.current));
    s.inlier.resize(std::min(s.inlier.size(), all.current));
    result.solver_iterations = s.iterations;
    result.solver_converged = s.converged;
    markSolve(inside, s, result);
    if (s.ok) {
      // Reported whether or not it starts the filter.
      result.measurement = s.pose;
      result.measurement_covariance = fixCovariance(s, options);
    }
    const double sigma = s.ok ? positionSigma(*result.measurement_covariance) : 0.0;
    const bool certain =
        options.first_fix_max_sigma_m <= 0.0 || sigma <= options.first_fix_max_sigma_m;
    if (s.ok && certain) {
      search_window.clear();
      fix = s;
    } else if (s.ok) {
      search_window.add(inside);
      result.warnings.push_back(fmt::format(
          "first fix too uncertain ({:.2f} m, 1 sigma): waiting for more texts", sigma));
    } else {
      search_window.add(inside);
      result.warnings.push_back("solver: " + s.failure);
    }
  }
  result.timings.solver_ms += msSince(t_solver);
  if (was_tracking) search_window.clear();

  const auto t_filter = Clock::now();
  if (fix) {
    const Eigen::Matrix3d R = fixCovariance(*fix, options);
    if (was_tracking) {
      ekf.update(fix->pose, R);
    } else {
      // First fix, or re-localisation after the filter got lost.
      ekf.initialise(fix->pose, R, result.timestamp);
      result.reinitialised = true;
      last_fix.reset();
    }
    updateVisualMotion(result.timestamp);
    disagreeing_fixes = 0;
    disagreeing_with_consensus = false;
    result.status = TrackingStatus::kOk;
  } else if (disagreeing) {
    // A kidnapped vehicle (or a filter that went wrong): several consecutive fixes that
    // agree with each other but not with the filter re-initialise it.
    bool consistent = disagreeing_fixes > 0;
    if (consistent) {
      const geometry::Pose2 motion = predicted_at_last_disagreeing_fix.inverse() * ekf.pose();
      const geometry::Pose2 expected = last_disagreeing_fix * motion;
      consistent =
          (expected.translation() - disagreeing->pose.translation()).norm() < 1.0 &&
          std::abs(geometry::wrapAngle(expected.yaw - disagreeing->pose.yaw)) < 10.0 * M_PI / 180.0;
    }
    disagreeing_fixes = consistent ? disagreeing_fixes + 1 : 1;
    disagreeing_with_consensus =
        (consistent && disagreeing_with_consensus) || disagreeing_landmarks >= 2;
    last_disagreeing_fix = disagreeing->pose;
    predicted_at_last_disagreeing_fix = ekf.pose();
    const int needed = std::max(1, options.reinit_after_rejected_fixes);
    if (disagreeing_fixes >= (disagreeing_with_consensus ? needed : 2 * needed)) {
      ekf.initialise(disagreeing->pose, fixCovariance(*disagreeing, options), result.timestamp);
      result.reinitialised = true;
      result.status = TrackingStatus::kOk;
      result.warnings.push_back(
          fmt::format("re-initialised from {} consecutive disagreeing fixes", disagreeing_fixes));
      disagreeing_fixes = 0;
      disagreeing_with_consensus = false;
    }
  }
  result.timings.filter_ms += msSince(t_filter);

  if (ekf.initialised()) {
    result.has_pose = true;
    result.pose = ekf.pose();
    result.covariance = ekf.covariance();
    if (result.status != TrackingStatus::kOk)
      result.status = tracking() ? TrackingStatus::kDeadReckoning : TrackingStatus::kLost;
  }
}

void Pipeline::Impl::measurePaper(const std::vector<LandmarkObservation>& accepted,
                                  FrameResult& result) {
  const auto t_solver = Clock::now();
  std::vector<PaperObservation> observations;
  for (const auto& o : accepted) {
    const auto& camera = rig.cameras[o.camera];
    auto p = paperObserve(homographies[o.camera], camera.model, o.pixels,
                          options.paper_centre_from_polygon);
    auto& association = result.associations[o.tag];
    if (!p) {
      association.verdict = AssociationVerdict::kNoGeometry;
      continue;
    }
    const map::Landmark* landmark = map.findById(o.landmark_id);
    p->camera = o.camera;
    p->landmark_id = o.landmark_id;
    p->map_position = landmark->position.head<2>();
    p->map_heading = landmark->heading;
    observations.push_back(*p);
  }
  if (options.paper_heading == PaperHeadingSource::kTextDirection ||
      (options.paper_heading == PaperHeadingSource::kOdometry && !paper_has_pose)) {
    if (const auto yaw = headingFromTextDirections(observations)) paper_yaw = *yaw;
  }
  const auto fix = paperFuse(observations, paper_yaw, options.mcrp, options.mcap);
  if (fix) {
    if (options.paper_heading == PaperHeadingSource::kMotionDirection) {
      const Eigen::Vector2d moved = fix->position - paper_motion_anchor;
      if (paper_has_pose && moved.norm() > 0.5) {
        paper_yaw = std::atan2(moved.y(), moved.x());
        paper_motion_anchor = fix->position;
      } else if (!paper_has_pose) {
        paper_motion_anchor = fix->position;
      }
    }
    paper_pose = geometry::Pose2(fix->position.x(), fix->position.y(), paper_yaw);
    paper_has_pose = true;
    result.status = TrackingStatus::kOk;
    result.measurement = paper_pose;
    result.solver_converged = true;
  }
  result.timings.solver_ms += msSince(t_solver);
  if (paper_has_pose) {
    result.has_pose = true;
    result.pose = geometry::Pose2(paper_pose.x, paper_pose.y, paper_yaw);
    // Nominal: the paper reports about 5 cm with all modules; no heading estimate of its own.
    const double sigma = fix ? 0.1 / std::sqrt(std::max(1, fix->landmarks)) : 0.5;
    const double yaw_sigma = 5.0 * M_PI / 180.0;
    result.covariance =
        Eigen::Vector3d(sigma * sigma, sigma * sigma, yaw_sigma * yaw_sigma).asDiagonal();
    if (fix) result.measurement_covariance = result.covariance;
    if (result.status != TrackingStatus::kOk) result.status = TrackingStatus::kDeadReckoning;
  }
}

FrameResult Pipeline::Impl::process(const FrameInput& frame) {
  const auto t_start = Clock::now();
  const double cpu_start = processCpuMs();
  FrameResult result;
  result.timestamp = frame.timestamp;

  // 1. Motion prediction to this frame.
  auto t_filter = Clock::now();
  bool time_ok = std::isfinite(frame.timestamp);
  if (!time_ok) result.warnings.push_back("frame timestamp is not finite: no prediction");
  if (time_ok && have_frame && frame.timestamp <= last_frame_time) {
    result.warnings.push_back(
        fmt::format("frame at {:.6f} is not after the previous one ({:.6f}): "
                    "no prediction",
                    frame.timestamp, last_frame_time));
    time_ok = false;
  }
  // A filter started from options.initial_pose starts its clock at the first frame.
  if (time_ok && !have_frame && ekf.initialised()) ekf.setTime(frame.timestamp);
  const std::optional<io::OdometrySample> held_before =
      have_odometry ? std::optional<io::OdometrySample>(hold) : std::nullopt;
  const bool had_frame = have_frame;
  const double previous_frame_time = last_frame_time;
  const auto samples = consumeOdometry(frame, time_ok, result.warnings);
  if (!search_window.empty()) {
    // The search window's texts follow the vehicle (odometry since the last frame set).
    std::optional<geometry::Pose2> motion;
    if (time_ok && had_frame && options.use_odometry)
      motion = integrateOdometry(held_before, samples, previous_frame_time, frame.timestamp);
    search_window.advance(motion);
  }
  if (time_ok && !options.paper_mode) predictTo(frame.timestamp, result.warnings);
  if (time_ok) {
    have_frame = true;
    last_frame_time = frame.timestamp;
  }
  result.timings.filter_ms += msSince(t_filter);
  const bool is_tracking = !options.paper_mode && tracking();

  // 2. Where to look: map-guided regions while tracking, the full frame now and then.
  const auto t_roi = Clock::now();
  const size_t n_cameras = rig.cameras.size();
  const int interval = std::max(1, options.full_frame_interval);
  const bool all_full_frame =
      options.paper_mode || !options.map_guided || !is_tracking || interval == 1 ||
      (!options.full_frame_round_robin && frames_since_full_frame + 1 >= interval);
  frames_since_full_frame = all_full_frame ? 0 : frames_since_full_frame + 1;
  std::vector<bool> full_frame(n_cameras, all_full_frame);
  bool one_full_frame = false;
  if (!all_full_frame && options.full_frame_round_robin && n_cameras > 0) {
    // One camera per slot, n_cameras slots spread evenly over every `interval` tracking
    // frames: the same full-frame images as all cameras every `interval` frames, but never
    // more than one in a frame set (the p99 latency).
    const long t = tracking_frames;
    const long per = static_cast<long>(n_cameras);
    if ((t + 1) * per / interval > t * per / interval) {
      full_frame[next_full_frame_camera % n_cameras] = true;
      next_full_frame_camera = (next_full_frame_camera + 1) % n_cameras;
      one_full_frame = true;
    }
  }
  // Searching (no pose yet): the full frame of a few cameras per frame set, in turn.
  const bool searching =
      !options.paper_mode && options.map_guided && !ekf.initialised() && interval > 1;
  const int per_search = options.search_cameras_per_frame;
  if (searching && per_search > 0 && static_cast<size_t>(per_search) < n_cameras) {
    full_frame.assign(n_cameras, false);
    for (int k = 0; k < per_search; ++k)
      full_frame[(next_search_camera + static_cast<size_t>(k)) % n_cameras] = true;
    next_search_camera = (next_search_camera + static_cast<size_t>(per_search)) % n_cameras;
  }
  tracking_frames = is_tracking ? tracking_frames + 1 : 0;
  std::vector<const map::Landmark*> nearby;
  if (!all_full_frame)
    nearby = map.withinRadius(ekf.pose().translation(), options.roi_radius_m,
                              options.level.empty() ? active_level : options.level);
  // Regions of every guided camera, then the budget over all of them.
  std::vector<std::vector<RegionCandidate>> candidates(n_cameras);
  if (!all_full_frame) {
    for (size_t c = 0; c < n_cameras; ++c)
      if (!full_frame[c])
        candidates[c] = predictRegionCandidates(rig.cameras[c], nearby, floors, ekf.pose(),
                                                ekf.covariance(), roi_options);
    RegionBudgetOptions budget;
    budget.max_regions = one_full_frame ? std::min(options.max_regions_per_frame,
                                                   options.max_regions_with_full_frame)
                                        : options.max_regions_per_frame;
    if (options.max_regions_per_frame <= 0)
      budget.max_regions = 0;
    else if (budget.max_regions <= 0)
      budget.max_regions = -1;  // nothing on this frame
    budget.first_camera = frame_index % static_cast<int>(std::max<size_t>(n_cameras, 1));
    budget.min_height_px = options.roi_min_height_px;
    std::vector<std::vector<RegionCandidate>> kept(n_cameras);
    if (budget.max_regions >= 0) {
      const auto chosen = selectRegionsWithinBudget(candidates, last_asked, frame_index, budget);
      for (size_t c = 0; c < n_cameras; ++c)
        for (size_t i : chosen[c]) {
          last_asked[candidates[c][i].landmark_id] = frame_index;
          kept[c].push_back(std::move(candidates[c][i]));
        }
    }
    candidates = std::move(kept);
    // A frame set that sweeps a camera on the full frame spends its reads there.
    if (options.reread_interval_frames > 0) chooseReadsAndFits(candidates, one_full_frame);
  }
  ++frame_index;
  result.timings.roi_ms += msSince(t_roi);

  // 3. Spotting, camera by camera in rig order.
  for (const auto& input : frame.cameras)
    if (!rig.find(input.camera))
      result.warnings.push_back("camera '" + input.camera + "' is not in the rig: ignored");
  std::vector<bool> supplied(n_cameras, false);  // instances came with the frame
  for (size_t c = 0; c < n_cameras; ++c) {
    const auto& camera = rig.cameras[c];
    CameraResult camera_result;
    camera_result.camera = camera.name;
    camera_result.full_frame = full_frame[c];
    const CameraInput* input = nullptr;
    for (const auto& in : frame.cameras)
      if (in.camera == camera.name) input = &in;
    if (!input) {
      camera_result.image_ok = false;
      result.warnings.push_back("camera '" + camera.name + "': no input this frame");
      result.cameras.push_back(std::move(camera_result));
      continue;
    }
    if (input->instances) {
      camera_result.instances = *input->instances;
      supplied[c] = true;
    } else if (input->image.empty()) {
      camera_result.image_ok = false;
      result.warnings.push_back("camera '" + camera.name + "': image missing or corrupt, skipped");
    } else if (!spotter) {
      result.warnings.push_back("camera '" + camera.name + "': no spotter and no instances");
    } else {
      ocr::SpotRequest request;
      request.camera = &camera;
      if (!full_frame[c]) {
        for (auto& r : candidates[c]) {
          request.lexicon.insert(request.lexicon.end(), r.roi.expected_texts.begin(),
                                 r.roi.expected_texts.end());
          request.regions.push_back(std::move(r.roi));
        }
        camera_result.regions = static_cast<int>(request.regions.size());
      } else {
        request.lexicon = lexicon;
        request.floor_lexicon = floor_lexicon;
        request.second_opinions = options.second_opinions;
        // While tracking, the full frame is a sweep for what the prediction missed.
        if (is_tracking && options.reread_interval_frames > 0) {
          request.max_reads = std::max(0, options.max_reads_per_frame);
          request.detection_scale = static_cast<float>(options.sweep_detection_scale);
          if (options.sweep_places_floor_texts) {
            request.placed_floor_texts =
                map::placeFloorTexts(map, ekf.pose(), options.sweep_placement_range_m,
                                     options.level.empty() ? active_level : options.level);
            request.placement_radius_m = options.sweep_placement_radius_m;
            request.narrow_to_placed_texts = false;
            // Numbers beyond the floor view are seen at a grazing angle, and their corners
            // fix the pose less well (docs/OCR.md, session 16).
            request.look_beyond_the_view = false;
          }
        } else if (searching) {
          request.max_reads = std::max(0, options.search_max_reads);
          request.detection_scale = static_cast<float>(options.search_detection_scale);
        }
      }
      const auto t_spot = Clock::now();
      if (full_frame[c] || !request.regions.empty()) {
        try {
          camera_result.instances = spotter->spot(input->image, request);
        } catch (const InputError& e) {
          camera_result.image_ok = false;
          result.warnings.push_back("camera '" + camera.name + "': " + e.what());
        }
      }
      result.timings.spotting_ms += msSince(t_spot);
    }
    result.cameras.push_back(std::move(camera_result));
  }

  // 4. Association: class, score, AFM (paper 3.3), exact matching (3.3), gating.
  const auto t_assoc = Clock::now();
  if (options.level.empty() && (!is_tracking || active_level.empty()) && !options.paper_mode)
    voteLevel(result.cameras);
  if (options.paper_mode && options.level.empty() && active_level.empty())
    voteLevel(result.cameras);
  const std::string& level = options.level.empty() ? active_level : options.level;
  std::vector<LandmarkObservation> inside, outside;
  // The box plot (paper 3.3) assumes the numbers in view change slowly; after a turn into
  // another aisle they jump and it rejects the new ones for a while. While parkloc
  // tracks, the pose gate tests every reading against where its landmark must be, so the
  // box plot filters only before the first fix (and in the paper's pipeline); the gated
  // numbers keep its queue current for when the track is lost.
  const bool afm_filters_readings = options.afm && (options.paper_mode || !is_tracking);
  for (size_t c = 0; c < result.cameras.size(); ++c) {
    const auto& instances = result.cameras[c].instances;
    const bool use_corners =
        options.polygon_model == PipelineOptions::PolygonModel::kCorners ||
        (options.polygon_model == PipelineOptions::PolygonModel::kAuto && supplied[c]);
    for (size_t i = 0; i < instances.size(); ++i) {
      const auto& instance = instances[i];
      Association a;
      a.camera = result.cameras[c].camera;
      a.instance_index = static_cast<int>(i);
      a.text = instance.text;
      const int tag = static_cast<int>(result.associations.size());
      // The numeric part of a parking number, for the box plot.
      const std::optional<int> number = parkingNumberValue(instance.text);
      const bool is_number = instance.cls == map::TextClass::kParkingNumber && number.has_value();
      const bool usable_class =
          (instance.cls == map::TextClass::kParkingNumber && options.use_parking_numbers) ||
          (instance.cls == map::TextClass::kPillar && options.use_pillar_text &&
           !options.paper_mode);
      if (!usable_class) {
        a.verdict = AssociationVerdict::kWrongClass;
      } else if (instance.recognition_score < options.min_recognition_score) {
        a.verdict = AssociationVerdict::kLowScore;
      } else if (afm_filters_readings && instance.read && is_number && !afm.accept(*number)) {
        a.verdict = AssociationVerdict::kAnomaly;
      } else if (instance.partial) {
        a.verdict = AssociationVerdict::kPartial;
      } else if (instance.second_opinion && !is_tracking) {
        // One wrong second opinion made a first fix 16.6 m off that the track never left
        // (docs/OCR.md, session 8): only the pose gate may vouch for one.
        a.verdict = AssociationVerdict::kUnconfirmed;
      } else {
        const auto candidates = map.findByText(instance.text, level);
        const auto observe = [&](const map::Landmark& landmark) {
          LandmarkObservation o;
          o.camera = static_cast<int>(c);
          o.landmark_id = landmark.id;
          o.pixels = toEigen(instance.polygon);
          o.map_corners = floors.cornersAboveFloor(landmark);
          o.tag = tag;
          o.use_corners = use_corners;
          return o;
        };
        LandmarkObservation o;
        if (candidates.empty()) {
          a.verdict = AssociationVerdict::kNotInMap;
        } else if (is_tracking) {
          // Gate every landmark with this text (pillar faces, other levels): the one that
          // fits the prediction best, reading the right way round, is the association.
          AssociationVerdict best_verdict = AssociationVerdict::kGated;
          double best_m2 = std::numeric_limits<double>::infinity();
          for (const map::Landmark* l : candidates) {
            const LandmarkObservation candidate = observe(*l);
            const auto gate = gateObservation(rig.cameras[c], candidate, ekf.pose(),
                                              ekf.covariance(), gate_options);
            if (!gate) continue;
            const AssociationVerdict verdict =
                !gate->reading_order_agrees              ? AssociationVerdict::kFlipped
                : gate->mahalanobis2 > options.gate_chi2 ? AssociationVerdict::kGated
                                                         : AssociationVerdict::kAccepted;
            // Accepted beats flipped beats gated; then the smaller distance.
            const auto rank = [](AssociationVerdict v) {
              return v == AssociationVerdict::kAccepted  ? 0
                     : v == AssociationVerdict::kFlipped ? 1
                                                         : 2;
            };
            if (rank(verdict) < rank(best_verdict) ||
                (rank(verdict) == rank(best_verdict) && gate->mahalanobis2 < best_m2)) {
              best_verdict = verdict;
              best_m2 = gate->mahalanobis2;
              o = candidate;
            }
          }
          if (o.camera < 0) o = observe(*candidates.front());  // projects nowhere: gated
          a.verdict = best_verdict;
          a.landmark_id = o.landmark_id;
          if (std::isfinite(best_m2)) a.mahalanobis2 = best_m2;
        } else if (candidates.size() > 1 && !options.paper_mode) {
          a.verdict = AssociationVerdict::kAmbiguous;
        } else {
          o = observe(*candidates.front());
          a.landmark_id = o.landmark_id;
          a.verdict = AssociationVerdict::kAccepted;
        }
        if (o.camera >= 0) {
          if (a.verdict == AssociationVerdict::kAccepted) inside.push_back(o);
          // Re-localisation uses unique texts only, first opinions only: a gated pillar face
          // could be any face, and a gated second opinion is likelier a misreading.
          if (a.verdict == AssociationVerdict::kGated && candidates.size() == 1 &&
              !instance.second_opinion)
            outside.push_back(o);
        }
      }
      // A text read and accepted needs no reading for a while; a fitted one that does
      // not fit the prediction is read again.
      if (!a.landmark_id.empty()) {
        if (a.verdict == AssociationVerdict::kAccepted && options.afm && !afm_filters_readings &&
            is_number)
          afm.remember(*number);
        if (a.verdict == AssociationVerdict::kAccepted && instance.read)
          last_read[a.landmark_id] = frame_index - 1;
        else if (a.verdict != AssociationVerdict::kAccepted && !instance.read)
          last_read.erase(a.landmark_id);
      }
      result.associations.push_back(std::move(a));
    }
  }
  inside = selectForModules(std::move(inside));
  outside = selectForModules(std::move(outside));
  result.timings.association_ms += msSince(t_assoc);

  // 5./6. Measurement and filter.
  if (options.paper_mode)
    measurePaper(inside, result);
  else
    measureParkloc(inside, outside, result);

  result.timings.total_ms = msSince(t_start);
  result.timings.cpu_ms = processCpuMs() - cpu_start;
  return result;
}

Pipeline::Pipeline(geometry::Rig rig, map::HdMap map, PipelineOptions options,
                   ocr::TextSpotter* spotter)
    : impl_(std::make_unique<Impl>(std::move(rig), std::move(map), options, spotter)) {}
Pipeline::~Pipeline() = default;
Pipeline::Pipeline(Pipeline&&) noexcept = default;
Pipeline& Pipeline::operator=(Pipeline&&) noexcept = default;

FrameResult Pipeline::process(const FrameInput& frame) { return impl_->process(frame); }
void Pipeline::reset() { impl_->reset(); }
const PipelineOptions& Pipeline::options() const { return impl_->options; }
const geometry::Rig& Pipeline::rig() const { return impl_->rig; }
const map::HdMap& Pipeline::map() const { return impl_->map; }

}  // namespace parkloc::localize
