# `cmake --install`: the embeddable library and what it needs at run time, laid out as
#   include/parkloc/parkloc.h           the facade (src/api)
#   lib/libparkloc.so*                  the library; lib/libonnxruntime.so.1 beside it when
#                                       ONNX Runtime is the set-up's copy in third_party/
#   lib/cmake/parkloc/                  the CMake package: find_package(parkloc CONFIG)
#   share/parkloc/models/               the networks and class heads the spotter loads
#   share/parkloc/config/default.yaml   every option with its default (parkloc config dump)
#   share/parkloc/config/realtime.yaml  the overlay for a vehicle: heavy work on worker threads
include(CMakePackageConfigHelpers)
set(PARKLOC_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/parkloc)

install(TARGETS parkloc_api EXPORT parklocTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/parkloc DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
get_target_property(_ort_location onnxruntime::onnxruntime IMPORTED_LOCATION)
if(_ort_location AND _ort_location MATCHES "^${PROJECT_SOURCE_DIR}/third_party/")
  install(FILES ${_ort_location} DESTINATION ${CMAKE_INSTALL_LIBDIR})
endif()
install(DIRECTORY ${PARKLOC_MODEL_DIR}/ DESTINATION ${CMAKE_INSTALL_DATADIR}/parkloc/models
  FILES_MATCHING PATTERN "*.onnx" PATTERN "*.txt" PATTERN "*.yml"
  PATTERN "paddleocr" EXCLUDE)
install(FILES ${PROJECT_SOURCE_DIR}/data/config/default.yaml ${PROJECT_SOURCE_DIR}/data/config/realtime.yaml
  DESTINATION ${CMAKE_INSTALL_DATADIR}/parkloc/config)

install(EXPORT parklocTargets NAMESPACE parkloc:: DESTINATION ${PARKLOC_INSTALL_CMAKEDIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/parklocConfig.cmake.in
  ${PROJECT_BINARY_DIR}/parklocConfig.cmake INSTALL_DESTINATION ${PARKLOC_INSTALL_CMAKEDIR}
  PATH_VARS CMAKE_INSTALL_DATADIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/parklocConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/parklocConfig.cmake
  ${PROJECT_BINARY_DIR}/parklocConfigVersion.cmake DESTINATION ${PARKLOC_INSTALL_CMAKEDIR})
