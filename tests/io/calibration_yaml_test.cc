#include "io/calibration_yaml.h"

#include <gtest/gtest.h>

#include <string>

#include "common/error.h"
#include "geometry/rig.h"
#include "test_dir.h"

namespace parkloc::io {
namespace {

// A fresh temporary directory per test, removed afterwards.
class CalibrationYamlTest : public testing::TempDirTest {
 protected:
  // The message of the InputError that loading `text` throws ("" when it loads).
  std::string errorFor(const std::string& text) const {
    const std::string path = write("rig.yaml", text);
    try {
      loadCalibration(path);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
};

// One camera in the file format, with fields that tests replace.
std::string cameraYaml(
    const std::string& name = "front", const std::string& model = "fisheye",
    const std::string& K_rows = "3",
    const std::string& K_data = "[ 365., 0., 639.5, 0., 365., 399.5, 0., 0., 1. ]",
    const std::string& width = "1280",
    const std::string& T_data =
        "[ 0., 0., 1., 3.7, -1., 0., 0., 0., 0., -1., 0., 0.6, 0., 0., 0., 1. ]") {
  return "  - name: " + name + "\n    model: " + model + "\n    image_width: " + width +
         "\n    image_height: 800\n"
         "    K: !!opencv-matrix\n      rows: " +
         K_rows +
         "\n      cols: 3\n      dt: d\n"
         "      data: " +
         K_data +
         "\n"
         "    D: !!opencv-matrix\n      rows: 4\n      cols: 1\n      dt: d\n"
         "      data: [ 0.015, -0.003, 0.0005, -0.00005 ]\n"
         "    T_vehicle_camera: !!opencv-matrix\n      rows: 4\n      cols: 4\n      dt: d\n"
         "      data: " +
         T_data + "\n";
}

std::string rigYaml(const std::string& cameras) {
  return "%YAML:1.0\n---\nrig_name: test\ncameras:\n" + cameras;
}

TEST_F(CalibrationYamlTest, DefaultRigRoundTripsExactly) {
  const geometry::Rig rig = geometry::defaultRig();
  const std::string path = (dir_ / "rig.yaml").string();
  saveCalibration(rig, path);
  const geometry::Rig back = loadCalibration(path);
  ASSERT_EQ(back.cameras.size(), rig.cameras.size());
  for (size_t i = 0; i < rig.cameras.size(); ++i) {
    const auto& a = rig.cameras[i];
    const auto& b = back.cameras[i];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.model.type, b.model.type);
    EXPECT_EQ(a.model.width, b.model.width);
    EXPECT_EQ(a.model.height, b.model.height);
    EXPECT_NEAR(a.model.fx, b.model.fx, 1e-12);
    EXPECT_NEAR(a.model.fy, b.model.fy, 1e-12);
    EXPECT_NEAR(a.model.cx, b.model.cx, 1e-12);
    EXPECT_NEAR(a.model.cy, b.model.cy, 1e-12);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(a.model.distortion[k], b.model.distortion[k], 1e-12);
    EXPECT_NEAR(a.model.max_theta, b.model.max_theta, 1e-12);
    EXPECT_LT(
        (a.vehicle_from_camera.matrix() - b.vehicle_from_camera.matrix()).cwiseAbs().maxCoeff(),
        1e-12);
    ASSERT_TRUE(a.body);
    ASSERT_TRUE(b.body) << b.name;
    EXPECT_EQ(a.body->lo, b.body->lo);
    EXPECT_EQ(a.body->hi, b.body->hi);
  }
}

TEST_F(CalibrationYamlTest, AFileWithoutAVehicleBodyGivesCamerasOnNoBody) {
  const std::string path = write("rig.yaml", rigYaml(cameraYaml()));
  EXPECT_FALSE(loadCalibration(path).cameras.at(0).body);
}

std::string bodyYaml(const std::string& min_data, const std::string& max_data) {
  return "vehicle_body:\n"
         "  min: !!opencv-matrix\n    rows: 3\n    cols: 1\n    dt: d\n    data: " +
         min_data +
         "\n"
         "  max: !!opencv-matrix\n    rows: 3\n    cols: 1\n    dt: d\n    data: " +
         max_data + "\n";
}

TEST_F(CalibrationYamlTest, AVehicleBodyIsReadIntoEveryCamera) {
  const std::string path =
      write("rig.yaml", rigYaml(cameraYaml("front") + cameraYaml("rear")) +
                            bodyYaml("[ -1.0, -0.9, 0.1 ]", "[ 3.5, 0.9, 1.5 ]"));
  const geometry::Rig rig = loadCalibration(path);
  for (const auto& camera : rig.cameras) {
    ASSERT_TRUE(camera.body) << camera.name;
    EXPECT_EQ(camera.body->lo, Eigen::Vector3d(-1.0, -0.9, 0.1));
    EXPECT_EQ(camera.body->hi, Eigen::Vector3d(3.5, 0.9, 1.5));
  }
}

TEST_F(CalibrationYamlTest, AnEmptyOrMalformedVehicleBodyIsRejected) {
  std::string message =
      errorFor(rigYaml(cameraYaml()) + bodyYaml("[ -1.0, 0.9, 0.1 ]", "[ 3.5, 0.9, 1.5 ]"));
  EXPECT_NE(message.find(": vehicle_body: field 'max': must exceed min on every axis"),
            std::string::npos)
      << message;
  message = errorFor(rigYaml(cameraYaml()) + bodyYaml("[ -1.0, 0.9 ]", "[ 3.5, 0.9, 1.5 ]"));
  EXPECT_NE(message.find(": vehicle_body: field 'min': "), std::string::npos) << message;
}

TEST_F(CalibrationYamlTest, PinholeCameraRoundTrips) {
  geometry::Rig rig;
  geometry::RigCamera camera;
  camera.name = "mono";
  camera.model.type = geometry::CameraModelType::kPinhole;
  camera.model.width = 640;
  camera.model.height = 480;
  camera.model.fx = 500.25;
  camera.model.fy = 501.5;
  camera.model.cx = 319.5;
  camera.model.cy = 239.5;
  camera.model.distortion = {-0.1, 0.02, 0.001, -0.0005};
  camera.vehicle_from_camera.linear() = geometry::vehicleFromCameraRotation(0.3, 0.2, 0.01);
  camera.vehicle_from_camera.translation() = Eigen::Vector3d(1.0, -0.25, 1.4);
  rig.cameras.push_back(camera);
  const std::string path = (dir_ / "mono.yaml").string();
  saveCalibration(rig, path);
  const geometry::Rig back = loadCalibration(path);
  ASSERT_EQ(back.cameras.size(), 1u);
  EXPECT_EQ(back.cameras[0].model.type, geometry::CameraModelType::kPinhole);
  EXPECT_NEAR(back.cameras[0].model.fy, 501.5, 1e-12);
  EXPECT_LT((back.cameras[0].vehicle_from_camera.matrix() - camera.vehicle_from_camera.matrix())
                .cwiseAbs()
                .maxCoeff(),
            1e-12);
}

TEST_F(CalibrationYamlTest, HandWrittenFileLoads) {
  EXPECT_EQ(errorFor(rigYaml(cameraYaml())), "");
}

TEST_F(CalibrationYamlTest, MissingFileNamesThePath) {
  const std::string path = (dir_ / "absent.yaml").string();
  try {
    loadCalibration(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "calib " + path + ": file not found");
  }
}

TEST_F(CalibrationYamlTest, UnparseableYamlNamesTheFile) {
  const std::string message = errorFor("%YAML:1.0\n---\ncameras: [ {name: front, : : ]\n  - ]]\n");
  EXPECT_NE(message.find("calib " + (dir_ / "rig.yaml").string() + ": "), std::string::npos)
      << message;
}

TEST_F(CalibrationYamlTest, MissingCamerasSequence) {
  EXPECT_NE(errorFor("%YAML:1.0\n---\nrig_name: x\n").find("field 'cameras': missing"),
            std::string::npos);
}

TEST_F(CalibrationYamlTest, MissingFieldNamesCameraAndField) {
  std::string yaml = rigYaml(cameraYaml());
  yaml.erase(yaml.find("    image_height: 800\n"), std::string("    image_height: 800\n").size());
  EXPECT_NE(errorFor(yaml).find(": camera 'front': field 'image_height': missing"),
            std::string::npos)
      << errorFor(yaml);
}

TEST_F(CalibrationYamlTest, WrongMatrixSizeSaysExpectedAndGot) {
  const std::string message = errorFor(
      rigYaml(cameraYaml("front", "fisheye", "2", "[ 365., 0., 639.5, 0., 365., 399.5 ]")));
  EXPECT_NE(message.find(": camera 'front': field 'K': expected a 3x3 matrix, got 2x3"),
            std::string::npos)
      << message;
}

TEST_F(CalibrationYamlTest, NonFiniteValueIsRejected) {
  const std::string message = errorFor(rigYaml(
      cameraYaml("front", "fisheye", "3", "[ .Nan, 0., 639.5, 0., 365., 399.5, 0., 0., 1. ]")));
  EXPECT_NE(message.find(": camera 'front': field 'K': non-finite value"), std::string::npos)
      << message;
}

TEST_F(CalibrationYamlTest, UnknownModelIsRejected) {
  const std::string message = errorFor(rigYaml(cameraYaml("front", "omnidir")));
  EXPECT_NE(message.find(": camera 'front': field 'model': unknown model 'omnidir'"),
            std::string::npos)
      << message;
}

TEST_F(CalibrationYamlTest, DuplicateCameraNameIsRejected) {
  const std::string message = errorFor(rigYaml(cameraYaml("front") + cameraYaml("front")));
  EXPECT_NE(message.find(": camera 'front': field 'name': duplicate camera name"),
            std::string::npos)
      << message;
}

TEST_F(CalibrationYamlTest, NonPositiveImageSizeIsRejected) {
  const std::string message = errorFor(rigYaml(cameraYaml(
      "front", "fisheye", "3", "[ 365., 0., 639.5, 0., 365., 399.5, 0., 0., 1. ]", "0")));
  EXPECT_NE(message.find(": camera 'front': field 'image_width': must be positive, got 0"),
            std::string::npos)
      << message;
}

TEST_F(CalibrationYamlTest, NonPositiveFocalLengthIsRejected) {
  const std::string message = errorFor(rigYaml(
      cameraYaml("front", "fisheye", "3", "[ -365., 0., 639.5, 0., 365., 399.5, 0., 0., 1. ]")));
  EXPECT_NE(message.find(": camera 'front': field 'K': focal length must be positive"),
            std::string::npos)
      << message;
}

TEST_F(CalibrationYamlTest, NonOrthonormalRotationIsRejected) {
  const std::string message = errorFor(rigYaml(cameraYaml(
      "front", "fisheye", "3", "[ 365., 0., 639.5, 0., 365., 399.5, 0., 0., 1. ]", "1280",
      "[ 0., 0., 1.1, 3.7, -1., 0., 0., 0., 0., -1., 0., 0.6, 0., 0., 0., 1. ]")));
  EXPECT_NE(message.find(": camera 'front': field 'T_vehicle_camera': rotation part is not "
                         "orthonormal"),
            std::string::npos)
      << message;
}

}  // namespace
}  // namespace parkloc::io
