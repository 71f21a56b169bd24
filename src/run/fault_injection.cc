#include "run/fault_injection.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgcodecs.hpp>

#include "common/error.h"
#include "common/split_fields.h"
#include "geometry/pose.h"

namespace parkloc::run {
namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  const auto last = s.find_last_not_of(" \t");
  return s.substr(first, last - first + 1);
}

[[noreturn]] void bad(const std::string& item, const std::string& why) {
  throw InputError(fmt::format("--inject: fault '{}': {}", item, why));
}

double number(const std::string& item, const std::string& field, const std::string& text) {
  size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    bad(item, fmt::format("{} '{}' is not a number", field, text));
  }
  if (used != text.size() || !std::isfinite(value))
    bad(item, fmt::format("{} '{}' is not a number", field, text));
  return value;
}

double probability(const std::string& item, const std::string& text) {
  const double p = number(item, "probability", text);
  if (p < 0.0 || p > 1.0) bad(item, fmt::format("probability {} is outside [0, 1]", text));
  return p;
}

TimeRange timeRange(const std::string& item, const std::string& text) {
  const auto dash = text.find('-', 1);  // a leading '-' would be a sign: rejected below
  if (dash == std::string::npos) bad(item, fmt::format("time range '{}' is not T0-T1", text));
  TimeRange r;
  r.begin = number(item, "start time", text.substr(0, dash));
  r.end = number(item, "end time", text.substr(dash + 1));
  if (r.begin < 0.0 || r.end <= r.begin)
    bad(item, fmt::format("time range '{}' needs 0 <= T0 < T1", text));
  return r;
}

std::string camera(const std::string& item, const std::string& text) {
  if (text.empty()) bad(item, "camera name is empty");
  return text;
}

void expectFields(const std::string& item, const std::vector<std::string>& fields, size_t n,
                  const char* form) {
  if (fields.size() != n) bad(item, fmt::format("expected {}", form));
}

// FAKE@REAL: the text read in place of the real one.
SpoofedSign fakeAtReal(const std::string& item, const std::string& text) {
  const auto at = splitFields(text, '@');
  if (at.size() != 2 || at[0].empty() || at[1].empty())
    bad(item, fmt::format("'{}' is not FAKE@REAL", text));
  if (at[0] == at[1]) bad(item, "the fake text equals the real one");
  return {at[0], at[1], std::nullopt};
}

void parseItem(const std::string& item, InputFaults& f) {
  const auto fields = splitFields(item, ':');
  const std::string& kind = fields[0];
  if (kind == "dark" || kind == "freeze") {
    expectFields(item, fields, 3, fmt::format("{}:CAMERA:T0-T1", kind).c_str());
    CameraFault c{camera(item, fields[1]), timeRange(item, fields[2])};
    (kind == "dark" ? f.dark : f.frozen).push_back(c);
  } else if (kind == "missing") {
    expectFields(item, fields, 2, "missing:CAMERA");
    f.missing_cameras.push_back(camera(item, fields[1]));
  } else if (kind == "drop") {
    expectFields(item, fields, 2, "drop:PROBABILITY");
    f.drop_probability = probability(item, fields[1]);
  } else if (kind == "corrupt") {
    expectFields(item, fields, 2, "corrupt:PROBABILITY");
    f.corrupt_probability = probability(item, fields[1]);
  } else if (kind == "odo-dropout") {
    expectFields(item, fields, 2, "odo-dropout:T0-T1");
    f.odometry_dropouts.push_back(timeRange(item, fields[1]));
  } else if (kind == "yaw-bias") {
    expectFields(item, fields, 2, "yaw-bias:RAD_PER_S");
    f.yaw_rate_bias += number(item, "yaw-rate bias", fields[1]);
  } else if (kind == "spoof") {
    expectFields(item, fields, 2, "spoof:FAKE@REAL");
    f.spoofs.push_back(fakeAtReal(item, fields[1]));
  } else if (kind == "misread") {
    expectFields(item, fields, 3, "misread:FAKE@REAL:T0-T1");
    SpoofedSign misread = fakeAtReal(item, fields[1]);
    misread.during = timeRange(item, fields[2]);
    f.spoofs.push_back(misread);
  } else if (kind == "kidnap") {
    if (fields.size() != 2 && fields.size() != 3) bad(item, "expected kidnap:TIME[:METRES]");
    Kidnap k;
    k.time = number(item, "time", fields[1]);
    if (k.time < 0.0) bad(item, "time is negative");
    if (fields.size() == 3) k.distance_m = number(item, "distance", fields[2]);
    if (k.distance_m <= 0.0) bad(item, "distance must be positive");
    f.kidnaps.push_back(k);
  } else if (kind == "seed") {
    expectFields(item, fields, 2, "seed:N");
    const double s = number(item, "seed", fields[1]);
    if (s < 0.0 || s != std::floor(s) || s > 1e15) bad(item, "seed must be a whole number >= 0");
    f.seed = static_cast<uint64_t>(s);
  } else {
    bad(item,
        "unknown kind (dark, freeze, missing, drop, corrupt, odo-dropout, yaw-bias, spoof, "
        "misread, kidnap, seed)");
  }
}

// Independent of the order of calls: one generator per (seed, frame, stream).
std::mt19937_64 generatorFor(uint64_t seed, size_t index, uint64_t stream) {
  std::seed_seq seq{static_cast<uint32_t>(seed), static_cast<uint32_t>(seed >> 32),
                    static_cast<uint32_t>(index), static_cast<uint32_t>(stream)};
  return std::mt19937_64(seq);
}

bool chance(std::mt19937_64& rng, double p) {
  return p > 0.0 && std::uniform_real_distribution<double>(0.0, 1.0)(rng) < p;
}

std::string fmtTime(double t) { return fmt::format("{:.2f}", t); }

}  // namespace

bool InputFaults::empty() const {
  return dark.empty() && frozen.empty() && missing_cameras.empty() && drop_probability <= 0.0 &&
         corrupt_probability <= 0.0 && odometry_dropouts.empty() && yaw_rate_bias == 0.0 &&
         spoofs.empty() && kidnaps.empty();
}

InputFaults parseFaults(const std::string& spec) { return parseFaults(std::vector{spec}); }

InputFaults parseFaults(const std::vector<std::string>& specs) {
  InputFaults faults;
  for (const auto& spec : specs) {
    if (trim(spec).empty()) throw InputError("--inject: empty fault specification");
    for (const auto& raw : splitFields(spec, ',')) {
      const std::string item = trim(raw);
      if (item.empty()) throw InputError(fmt::format("--inject: empty fault in '{}'", spec));
      parseItem(item, faults);
    }
  }
  return faults;
}

std::string describeFaults(const InputFaults& f) {
  std::vector<std::string> lines;
  for (const auto& c : f.dark)
    lines.push_back(fmt::format("camera '{}' dark from {} s to {} s", c.camera,
                                fmtTime(c.range.begin), fmtTime(c.range.end)));
  for (const auto& c : f.frozen)
    lines.push_back(fmt::format("camera '{}' frozen from {} s to {} s", c.camera,
                                fmtTime(c.range.begin), fmtTime(c.range.end)));
  for (const auto& c : f.missing_cameras)
    lines.push_back(fmt::format("camera '{}' missing for the whole drive", c));
  if (f.drop_probability > 0.0)
    lines.push_back(fmt::format("frame sets dropped with probability {}", f.drop_probability));
  if (f.corrupt_probability > 0.0)
    lines.push_back(fmt::format("images corrupt with probability {}", f.corrupt_probability));
  for (const auto& r : f.odometry_dropouts)
    lines.push_back(fmt::format("no odometry from {} s to {} s", fmtTime(r.begin), fmtTime(r.end)));
  if (f.yaw_rate_bias != 0.0)
    lines.push_back(fmt::format("yaw rate biased by {} rad/s", f.yaw_rate_bias));
  for (const auto& s : f.spoofs)
    lines.push_back(s.during ? fmt::format("text '{}' read as '{}' from {} s to {} s", s.real,
                                           s.fake, fmtTime(s.during->begin), fmtTime(s.during->end))
                             : fmt::format("sign '{}' shows '{}' (spoofed)", s.real, s.fake));
  for (const auto& k : f.kidnaps)
    lines.push_back(fmt::format("kidnap at {} s over {} m", fmtTime(k.time), k.distance_m));
  std::string out;
  for (const auto& l : lines) out += (out.empty() ? "" : "\n") + l;
  return out;
}

void checkFaultCameras(const InputFaults& faults, const geometry::Rig& rig) {
  auto check = [&](const std::string& name) {
    if (!rig.find(name)) {
      std::string known;
      for (const auto& c : rig.cameras) known += (known.empty() ? "" : ", ") + c.name;
      throw InputError(fmt::format("--inject: camera '{}' is not in the rig ({})", name, known));
    }
  };
  for (const auto& c : faults.dark) check(c.camera);
  for (const auto& c : faults.frozen) check(c.camera);
  for (const auto& c : faults.missing_cameras) check(c);
}

std::vector<bool> kidnapSkips(const std::vector<Kidnap>& kidnaps,
                              const std::vector<double>& timestamps,
                              const std::vector<io::StampedPose>& truth,
                              const std::vector<OdometrySample>& odometry) {
  const size_t n = timestamps.size();
  std::vector<bool> skip(n, false);
  if (kidnaps.empty() || n == 0) return skip;
  // Where the vehicle is at each frame set: truth position, or odometry path length.
  std::vector<Eigen::Vector2d> where(n, Eigen::Vector2d::Zero());
  const bool by_truth = !truth.empty();
  if (by_truth) {
    for (size_t i = 0; i < n; ++i) {
      const auto it =
          std::lower_bound(truth.begin(), truth.end(), timestamps[i],
                           [](const io::StampedPose& p, double t) { return p.timestamp < t; });
      const auto& p = (it == truth.end() ? truth.back() : *it).pose;
      where[i] = p.translation().head<2>();
    }
  } else {
    double length = 0.0, previous = timestamps.front();
    size_t s = 0;
    for (size_t i = 0; i < n; ++i) {
      for (; s < odometry.size() && odometry[s].timestamp <= timestamps[i]; ++s) {
        length += std::abs(odometry[s].speed) * std::max(0.0, odometry[s].timestamp - previous);
        previous = odometry[s].timestamp;
      }
      where[i] = Eigen::Vector2d(length, 0.0);
    }
  }
  for (const auto& k : kidnaps) {
    const auto first = std::lower_bound(timestamps.begin(), timestamps.end(), k.time);
    if (first == timestamps.end()) continue;
    const size_t start = static_cast<size_t>(first - timestamps.begin());
    const Eigen::Vector2d from = where[start == 0 ? 0 : start - 1];
    size_t resume = n;  // first frame set processed again
    size_t farthest = start;
    for (size_t i = start; i < n; ++i) {
      const double d = (where[i] - from).norm();
      if (d >= k.distance_m) {
        resume = i;
        break;
      }
      if (d >= (where[farthest] - from).norm()) farthest = i;
    }
    if (resume == n) resume = farthest;
    for (size_t i = start; i < resume; ++i) skip[i] = true;
  }
  return skip;
}

std::vector<std::string> spoofInstances(const std::vector<SpoofedSign>& spoofs,
                                        std::vector<ocr::TextInstance>& instances, double time) {
  std::vector<std::string> notes;
  for (auto& instance : instances)
    for (const auto& s : spoofs)
      // A tracked text is not read, only fitted where REAL stands: the sign's content
      // cannot fool it (its place is REAL's place).
      if (instance.read && instance.text == s.real && (!s.during || s.during->contains(time))) {
        instance.text = s.fake;
        instance.raw_text = s.fake;
        notes.push_back(s.during
                            ? fmt::format("fault: misread: '{}' read as '{}'", s.real, s.fake)
                            : fmt::format("fault: spoofed sign: '{}' reads '{}'", s.real, s.fake));
        break;
      }
  return notes;
}

SpoofingSpotter::SpoofingSpotter(ocr::TextSpotter* inner, std::vector<SpoofedSign> spoofs)
    : inner_(inner), spoofs_(std::move(spoofs)) {}

std::string SpoofingSpotter::name() const { return inner_->name() + "+spoof"; }

std::vector<ocr::TextInstance> SpoofingSpotter::spot(const cv::Mat& image,
                                                     const ocr::SpotRequest& request) {
  auto instances = inner_->spot(image, request);
  auto notes = spoofInstances(spoofs_, instances, time_);
  notes_.insert(notes_.end(), notes.begin(), notes.end());
  return instances;
}

std::vector<std::string> SpoofingSpotter::takeNotes() {
  std::vector<std::string> out;
  out.swap(notes_);
  return out;
}

cv::Mat corruptJpeg(const cv::Mat& image, std::mt19937_64& rng) {
  std::vector<uchar> bytes;
  if (image.empty() || !cv::imencode(".jpg", image, bytes)) return {};
  // Keep the headers (a few hundred bytes) so the decoder gets into the scan data, then
  // lose the tail (a transfer cut short) and flip bytes in what is left.
  const size_t header = std::min<size_t>(bytes.size(), 640);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const size_t keep = header + static_cast<size_t>((0.3 + 0.6 * unit(rng)) *
                                                   static_cast<double>(bytes.size() - header));
  bytes.resize(std::min(keep, bytes.size()));
  if (bytes.size() > header) {
    std::uniform_int_distribution<size_t> where(header, bytes.size() - 1);
    for (int i = 0; i < 16; ++i) bytes[where(rng)] ^= static_cast<uchar>(1 + (rng() % 255));
  }
  try {
    return cv::imdecode(bytes, cv::IMREAD_COLOR);
  } catch (const cv::Exception&) {
    return {};
  }
}

FaultInjector::FaultInjector(InputFaults faults, const std::vector<double>& timestamps,
                             const std::vector<io::StampedPose>& truth,
                             const std::vector<OdometrySample>& odometry)
    : faults_(std::move(faults)),
      skips_(kidnapSkips(faults_.kidnaps, timestamps, truth, odometry)) {}

bool FaultInjector::skip(size_t index) {
  if (index < skips_.size() && skips_[index]) {
    withhold_next_odometry_ = true;
    ++skipped_in_a_row_;
    return true;
  }
  return false;
}

ocr::TextSpotter* FaultInjector::wrapSpotter(ocr::TextSpotter* inner) {
  if (!inner || faults_.spoofs.empty()) return inner;
  spoofing_ = std::make_unique<SpoofingSpotter>(inner, faults_.spoofs);
  return spoofing_.get();
}

std::vector<std::string> FaultInjector::takeSpotterNotes() {
  return spoofing_ ? spoofing_->takeNotes() : std::vector<std::string>{};
}

void FaultInjector::apply(size_t index, localize::FrameInput& frame,
                          std::vector<std::string>& warnings) {
  const double t = frame.timestamp;
  if (spoofing_) spoofing_->setTime(t);

  // Odometry: kidnap (withheld since the last processed frame set), dropouts, bias.
  if (withhold_next_odometry_) {
    warnings.push_back(
        fmt::format("fault: kidnapped: {} frame sets skipped, {} odometry samples withheld",
                    skipped_in_a_row_, frame.odometry.size()));
    frame.odometry.clear();
    withhold_next_odometry_ = false;
    skipped_in_a_row_ = 0;
  }
  const size_t before = frame.odometry.size();
  frame.odometry.erase(std::remove_if(frame.odometry.begin(), frame.odometry.end(),
                                      [&](const OdometrySample& s) {
                                        for (const auto& r : faults_.odometry_dropouts)
                                          if (r.contains(s.timestamp)) return true;
                                        return false;
                                      }),
                       frame.odometry.end());
  if (frame.odometry.size() < before)
    warnings.push_back(fmt::format("fault: odometry dropout: {} samples withheld",
                                   before - frame.odometry.size()));
  if (faults_.yaw_rate_bias != 0.0 && !frame.odometry.empty()) {
    for (auto& s : frame.odometry) s.yaw_rate += faults_.yaw_rate_bias;
    warnings.push_back(fmt::format("fault: yaw rate biased by {} rad/s", faults_.yaw_rate_bias));
  }

  // The whole frame set lost in transport.
  auto drop_rng = generatorFor(faults_.seed, index, 1);
  if (chance(drop_rng, faults_.drop_probability)) {
    for (const auto& c : frame.cameras)
      if (!c.image.empty() || c.instances) last_seen_[c.camera] = c;
    frame.cameras.clear();
    warnings.push_back("fault: frame set dropped (no images), odometry only");
    return;
  }

  std::vector<localize::CameraInput> kept;
  for (size_t ci = 0; ci < frame.cameras.size(); ++ci) {
    localize::CameraInput c = std::move(frame.cameras[ci]);
    const auto& name = c.camera;
    if (std::find(faults_.missing_cameras.begin(), faults_.missing_cameras.end(), name) !=
        faults_.missing_cameras.end()) {
      warnings.push_back(fmt::format("fault: camera '{}' missing", name));
      continue;
    }
    bool frozen_now = false;
    for (const auto& f : faults_.frozen)
      if (f.camera == name && f.range.contains(t)) frozen_now = true;
    if (frozen_now) {
      if (!frozen_.count(name)) frozen_[name] = last_seen_.count(name) ? last_seen_[name] : c;
      const localize::CameraInput& repeat = frozen_[name];
      c.image = repeat.image;
      c.instances = repeat.instances;
      warnings.push_back(fmt::format("fault: camera '{}' frozen (repeats its image)", name));
    } else {
      frozen_.erase(name);
      last_seen_[name] = c;
    }
    bool dark_now = false;
    for (const auto& f : faults_.dark)
      if (f.camera == name && f.range.contains(t)) dark_now = true;
    if (dark_now) {
      if (!c.image.empty()) c.image = cv::Mat::zeros(c.image.size(), c.image.type());
      if (c.instances) c.instances->clear();  // nothing can be read in the dark
      warnings.push_back(fmt::format("fault: camera '{}' dark", name));
    }
    auto corrupt_rng = generatorFor(faults_.seed, index, 100 + ci);
    if (chance(corrupt_rng, faults_.corrupt_probability)) {
      if (!c.image.empty()) c.image = corruptJpeg(c.image, corrupt_rng);
      // Oracle text comes from labels of the intact image: a corrupt image has none.
      if (c.instances) c.instances->clear();
      warnings.push_back(fmt::format("fault: camera '{}' corrupt JPEG ({})", name,
                                     c.image.empty() ? "undecodable" : "decoded garbled"));
    }
    if (c.instances && !faults_.spoofs.empty()) {
      auto notes = spoofInstances(faults_.spoofs, *c.instances, t);
      warnings.insert(warnings.end(), notes.begin(), notes.end());
    }
    kept.push_back(std::move(c));
  }
  frame.cameras = std::move(kept);
}

}  // namespace parkloc::run
