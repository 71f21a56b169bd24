#include "io/calibration_yaml.h"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <optional>
#include <set>

#include "common/error.h"

namespace parkloc::io {
namespace {

// The top-level key of the vehicle's body box (geometry::RigCamera::body).
constexpr const char* kBodyKey = "vehicle_body";

// Tolerance for R^T R = I in T_vehicle_camera: loose enough for matrices written with
// fewer digits by other tools, tight enough to catch a scaled or sheared rotation.
constexpr double kOrthonormalTolerance = 1e-6;

// OpenCV 4.6 reports YAML syntax errors as "<file>(<line>): <problem>" in cv::Exception::func
// (and a bare function name in err); turn that into "line N: problem".
std::string describeParseError(const cv::Exception& e, const std::string& path) {
  const std::string& where = e.func;
  if (where.rfind(path + "(", 0) == 0) {
    const size_t close = where.find("): ", path.size());
    if (close != std::string::npos)
      return fmt::format("line {}: {}", where.substr(path.size() + 1, close - path.size() - 1),
                         where.substr(close + 3));
  }
  return e.err;
}

// OpenCV's YAML reader (4.6, and the same loop in its master) spins forever when a document's
// top level ends before the file does and the next text starts with a lone '-' after three
// skipped characters: "%YAML:1.0\n--- [1]\n--x-" (found by fuzz/fuzz_calibration). A rig
// calibration is one document whose top level is a block mapping with its keys at column 0,
// so anything else is refused before OpenCV sees the text, as is base64 data. Empty when
// the shape is fine, else "line N: problem".
std::string documentShapeProblem(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  bool in_content = false;
  bool seen_marker = false;
  for (size_t line_no = 1; std::getline(in, line); ++line_no) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    for (const char c : line)
      if ((static_cast<unsigned char>(c) < 0x20 && c != '\t') || c == 0x7f)
        return fmt::format("line {}: control character 0x{:02x}", line_no,
                           static_cast<unsigned char>(c));
    const size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    // OpenCV's base64 reader spins forever on some malformed blocks (found by
    // fuzz/fuzz_calibration); calibrations are plain numbers.
    if (line.find("!!binary") != std::string::npos)
      return fmt::format("line {}: base64 data (!!binary) is not supported", line_no);
    const bool at_key = std::isalnum(static_cast<unsigned char>(line[0])) || line[0] == '_' ||
                        line[0] == '"' || line[0] == '\'';
    if (!in_content) {
      if (line[0] == '%') continue;  // directives such as %YAML:1.0
      if (line.rfind("---", 0) == 0 && !seen_marker) {
        const size_t rest = line.find_first_not_of(" \t", 3);
        if (rest != std::string::npos && line[rest] != '#')
          return fmt::format("line {}: content on the '---' line", line_no);
        seen_marker = true;
        continue;
      }
      if (!at_key)
        return fmt::format("line {}: the top level must be 'key: value' lines at column 0",
                           line_no);
      in_content = true;
    } else if (first == 0 && !at_key) {
      return fmt::format("line {}: expected a key at column 0 (one YAML document only)", line_no);
    }
  }
  return "";
}

class CalibReader {
 public:
  explicit CalibReader(std::string path) : path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(fmt::format("calib {}: {}", path_, what));
  }
  // `camera` names a camera, or the top-level map for its own fields ("vehicle_body").
  [[noreturn]] void fail(const std::string& camera, const std::string& field,
                         const std::string& what) const {
    const std::string where =
        camera == kBodyKey ? std::string(kBodyKey) : fmt::format("camera '{}'", camera);
    throw InputError(fmt::format("calib {}: {}: field '{}': {}", path_, where, field, what));
  }

  void require(const cv::FileNode& parent, const std::string& camera, const std::string& field,
               cv::FileNode& out) const {
    out = parent[field];
    if (out.empty() || out.isNone()) fail(camera, field, "missing");
  }

  double readNumber(const cv::FileNode& parent, const std::string& camera,
                    const std::string& field) const {
    cv::FileNode node;
    require(parent, camera, field, node);
    if (!node.isReal() && !node.isInt()) fail(camera, field, "expected a number");
    const double value = node.real();
    if (!std::isfinite(value))
      fail(
          camera, field,
          fmt::format("non-finite value {}", std::isnan(value) ? "nan" : fmt::format("{}", value)));
    return value;
  }

  int readPositiveInt(const cv::FileNode& parent, const std::string& camera,
                      const std::string& field) const {
    cv::FileNode node;
    require(parent, camera, field, node);
    if (!node.isInt()) fail(camera, field, "expected an integer");
    const int value = static_cast<int>(node);
    if (value <= 0) fail(camera, field, fmt::format("must be positive, got {}", value));
    return value;
  }

  cv::Mat readMatrix(const cv::FileNode& parent, const std::string& camera,
                     const std::string& field, int rows, int cols) const {
    cv::FileNode node;
    require(parent, camera, field, node);
    if (!node.isMap() || node["rows"].empty() || node["cols"].empty() || node["data"].empty())
      fail(camera, field, fmt::format("expected a {}x{} opencv-matrix", rows, cols));
    // The size before the data: OpenCV allocates rows x cols before it counts the data, so a
    // forged size would allocate gigabytes (found by fuzz/fuzz_calibration).
    const cv::FileNode rows_node = node["rows"];
    const cv::FileNode cols_node = node["cols"];
    if (!rows_node.isInt() || !cols_node.isInt())
      fail(camera, field, fmt::format("expected a {}x{} opencv-matrix", rows, cols));
    if (static_cast<int>(rows_node) != rows || static_cast<int>(cols_node) != cols)
      fail(camera, field,
           fmt::format("expected a {}x{} matrix, got {}x{}", rows, cols,
                       static_cast<int>(rows_node), static_cast<int>(cols_node)));
    cv::Mat m;
    try {
      node >> m;
    } catch (const cv::Exception& e) {
      fail(camera, field, fmt::format("unreadable matrix ({})", e.err));
    }
    if (m.rows != rows || m.cols != cols || m.channels() != 1)
      fail(camera, field,
           fmt::format("expected a {}x{} matrix, got {}x{}", rows, cols, m.rows, m.cols));
    m.convertTo(m, CV_64F);
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < cols; ++c)
        if (!std::isfinite(m.at<double>(r, c)))
          fail(camera, field,
               fmt::format(
                   "non-finite value {} at ({}, {})",
                   std::isnan(m.at<double>(r, c)) ? "nan" : fmt::format("{}", m.at<double>(r, c)),
                   r, c));
    return m;
  }

  geometry::RigCamera readCamera(const cv::FileNode& node, size_t index) const {
    geometry::RigCamera camera;
    if (!node.isMap()) fail(fmt::format("camera #{}: expected a map", index));
    const cv::FileNode name = node["name"];
    if (name.empty() || !name.isString())
      fail(fmt::format("camera #{}: field 'name': missing or not a string", index));
    camera.name = static_cast<std::string>(name);
    // OpenCV writes " front" without quotes and reads it back as "front" (found by the round
    // trip in fuzz/fuzz_calibration); a name is also a folder name under images/.
    if (camera.name.empty() || std::isspace(static_cast<unsigned char>(camera.name.front())) ||
        std::isspace(static_cast<unsigned char>(camera.name.back())))
      fail(fmt::format("camera #{}: field 'name': '{}' is empty or starts or ends with a space",
                       index, camera.name));
    const std::string& who = camera.name;

    cv::FileNode model_node;
    require(node, who, "model", model_node);
    if (!model_node.isString()) fail(who, "model", "expected a string");
    const std::string model_name = static_cast<std::string>(model_node);
    const auto type = geometry::cameraModelTypeFromString(model_name);
    if (!type)
      fail(who, "model", fmt::format("unknown model '{}' (fisheye or pinhole)", model_name));

    geometry::CameraModel& m = camera.model;
    m.type = *type;
    m.width = readPositiveInt(node, who, "image_width");
    m.height = readPositiveInt(node, who, "image_height");

    const cv::Mat K = readMatrix(node, who, "K", 3, 3);
    m.fx = K.at<double>(0, 0);
    m.fy = K.at<double>(1, 1);
    m.cx = K.at<double>(0, 2);
    m.cy = K.at<double>(1, 2);
    if (m.fx <= 0.0 || m.fy <= 0.0)
      fail(who, "K", fmt::format("focal length must be positive, got fx={} fy={}", m.fx, m.fy));

    const cv::Mat D = readMatrix(node, who, "D", 4, 1);
    for (int i = 0; i < 4; ++i) m.distortion[i] = D.at<double>(i, 0);

    if (!node["max_theta"].empty()) {
      m.max_theta = readNumber(node, who, "max_theta");
      if (m.max_theta <= 0.0)
        fail(who, "max_theta", fmt::format("must be positive, got {}", m.max_theta));
    }

    const cv::Mat T = readMatrix(node, who, "T_vehicle_camera", 4, 4);
    Eigen::Matrix4d E;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) E(r, c) = T.at<double>(r, c);
    if ((E.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).norm() > 1e-9)
      fail(who, "T_vehicle_camera", "last row must be [0, 0, 0, 1]");
    const Eigen::Matrix3d R = E.topLeftCorner<3, 3>();
    const double orth_error = (R.transpose() * R - Eigen::Matrix3d::Identity()).norm();
    if (orth_error > kOrthonormalTolerance || R.determinant() < 0.0)
      fail(who, "T_vehicle_camera",
           fmt::format("rotation part is not orthonormal (|R^T R - I| = {:.3g}, det = {:.6g})",
                       orth_error, R.determinant()));
    camera.vehicle_from_camera.linear() = R;
    camera.vehicle_from_camera.translation() = E.topRightCorner<3, 1>();
    return camera;
  }

  // The optional `vehicle_body: {min: 3x1, max: 3x1}` box, in the vehicle frame.
  std::optional<geometry::VehicleBody> readBody(const cv::FileNode& root) const {
    const cv::FileNode node = root[kBodyKey];
    if (node.empty()) return std::nullopt;
    if (!node.isMap()) fail(fmt::format("field '{}': expected a map with min and max", kBodyKey));
    const cv::Mat lo = readMatrix(node, kBodyKey, "min", 3, 1);
    const cv::Mat hi = readMatrix(node, kBodyKey, "max", 3, 1);
    geometry::VehicleBody body;
    for (int a = 0; a < 3; ++a) {
      body.lo[a] = lo.at<double>(a, 0);
      body.hi[a] = hi.at<double>(a, 0);
      if (!(body.lo[a] < body.hi[a]))
        fail(kBodyKey, "max",
             fmt::format("must exceed min on every axis ({} <= {} on axis {})", body.hi[a],
                         body.lo[a], a));
    }
    return body;
  }

  geometry::Rig read() const {
    if (!std::filesystem::is_regular_file(path_)) fail("file not found");
    if (const std::string problem = documentShapeProblem(path_); !problem.empty())
      fail("cannot parse YAML: " + problem);
    cv::FileStorage fs;
    try {
      if (!fs.open(path_, cv::FileStorage::READ | cv::FileStorage::FORMAT_YAML))
        fail("cannot open or parse the file");
    } catch (const cv::Exception& e) {
      fail("cannot parse YAML: " + describeParseError(e, path_));
    }
    geometry::Rig rig;
    const cv::FileNode cameras = fs["cameras"];
    if (cameras.empty() || !cameras.isSeq()) fail("field 'cameras': missing or not a sequence");
    if (cameras.size() == 0) fail("field 'cameras': no cameras");
    std::set<std::string> names;
    size_t index = 0;
    const std::optional<geometry::VehicleBody> body = readBody(fs.root());
    for (const auto& node : cameras) {
      geometry::RigCamera camera = readCamera(node, index++);
      if (!names.insert(camera.name).second) fail(camera.name, "name", "duplicate camera name");
      camera.body = body;
      rig.cameras.push_back(std::move(camera));
    }
    return rig;
  }

 private:
  std::string path_;
};

cv::Mat toCv(const Eigen::MatrixXd& e) {
  cv::Mat m(static_cast<int>(e.rows()), static_cast<int>(e.cols()), CV_64F);
  for (int r = 0; r < m.rows; ++r)
    for (int c = 0; c < m.cols; ++c) m.at<double>(r, c) = e(r, c);
  return m;
}

}  // namespace

geometry::Rig loadCalibration(const std::string& path) {
  try {
    return CalibReader(path).read();
  } catch (const InputError&) {
    throw;
  } catch (const cv::Exception& e) {
    // FileStorage may throw from deep inside on malformed content.
    throw InputError(
        fmt::format("calib {}: cannot parse YAML: {}", path, describeParseError(e, path)));
  } catch (const std::exception& e) {
    // OpenCV 4.6's YAML parser can even throw std::length_error on garbage.
    throw InputError(fmt::format("calib {}: cannot parse YAML ({})", path, e.what()));
  }
}

void saveCalibration(const geometry::Rig& rig, const std::string& path) {
  cv::FileStorage fs;
  try {
    fs.open(path, cv::FileStorage::WRITE | cv::FileStorage::FORMAT_YAML);
  } catch (const cv::Exception& e) {
    throw IoError(fmt::format("calib {}: cannot write ({})", path, e.err));
  }
  if (!fs.isOpened()) throw IoError(fmt::format("calib {}: cannot open for writing", path));
  fs << "rig_name" << std::filesystem::path(path).stem().string();
  fs << "cameras"
     << "[";
  for (const auto& camera : rig.cameras) {
    const geometry::CameraModel& m = camera.model;
    Eigen::Matrix3d K = Eigen::Matrix3d::Identity();
    K(0, 0) = m.fx;
    K(1, 1) = m.fy;
    K(0, 2) = m.cx;
    K(1, 2) = m.cy;
    const Eigen::Vector4d D(m.distortion[0], m.distortion[1], m.distortion[2], m.distortion[3]);
    fs << "{";
    fs << "name" << camera.name;
    fs << "model" << geometry::toString(m.type);
    fs << "image_width" << m.width;
    fs << "image_height" << m.height;
    fs << "K" << toCv(K);
    fs << "D" << toCv(D);
    if (m.type == geometry::CameraModelType::kFisheye) fs << "max_theta" << m.max_theta;
    fs << "T_vehicle_camera" << toCv(camera.vehicle_from_camera.matrix());
    fs << "}";
  }
  fs << "]";
  for (const auto& camera : rig.cameras)
    if (camera.body) {
      fs << kBodyKey << "{"
         << "min" << toCv(camera.body->lo) << "max" << toCv(camera.body->hi) << "}";
      break;
    }
  fs.release();
}

}  // namespace parkloc::io
