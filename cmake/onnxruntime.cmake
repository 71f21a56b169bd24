# ONNX Runtime as the imported target onnxruntime::onnxruntime.
# Prefer an installation the system already has; fall back to the npm build that
# scripts/setup.sh lays out under third_party/onnxruntime.
find_package(onnxruntime QUIET CONFIG)
if(NOT TARGET onnxruntime::onnxruntime)
  set(_ort_root "${PROJECT_SOURCE_DIR}/third_party/onnxruntime")
  if(NOT EXISTS "${_ort_root}/lib/libonnxruntime.so.1")
    message(FATAL_ERROR "ONNX Runtime not found: run scripts/setup.sh (make build does) to install it from the npm registry")
  endif()
  add_library(onnxruntime::onnxruntime SHARED IMPORTED GLOBAL)
  set_target_properties(onnxruntime::onnxruntime PROPERTIES
    IMPORTED_LOCATION "${_ort_root}/lib/libonnxruntime.so.1"
    IMPORTED_SONAME "libonnxruntime.so.1"
    INTERFACE_INCLUDE_DIRECTORIES "${_ort_root}/include")
  message(STATUS "ONNX Runtime: npm build in ${_ort_root}")
endif()
set(PARKLOC_MODEL_DIR "${PROJECT_SOURCE_DIR}/third_party/models" CACHE PATH "PP-OCRv4 ONNX models")
