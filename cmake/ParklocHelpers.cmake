# One static library per module (parkloc_<name>, alias parkloc::<name>) and one
# GoogleTest executable per module, with the project's warning flags.
function(parkloc_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
endfunction()

function(parkloc_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC_DEPS;PRIVATE_DEPS" ${ARGN})
  if(NOT ARG_SOURCES)
    message(STATUS "parkloc: module ${name} has no sources yet, skipped")
    return()
  endif()
  add_library(parkloc_${name} STATIC ${ARG_SOURCES})
  add_library(parkloc::${name} ALIAS parkloc_${name})
  # Position-independent: the embeddable shared library (src/api) links these archives.
  set_target_properties(parkloc_${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  target_include_directories(parkloc_${name} PUBLIC ${PROJECT_SOURCE_DIR}/src)
  target_link_libraries(parkloc_${name} PUBLIC ${ARG_PUBLIC_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  parkloc_warnings(parkloc_${name})
endfunction()

function(parkloc_add_test name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} GTest::gmock GTest::gtest_main)
  target_compile_definitions(${name} PRIVATE
    PARKLOC_SOURCE_DIR="${PROJECT_SOURCE_DIR}" PARKLOC_MODEL_DIR="${PARKLOC_MODEL_DIR}")
  parkloc_warnings(${name})
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 120 PROPERTIES LABELS ${name})
endfunction()

function(parkloc_add_benchmark name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_DEPS} benchmark::benchmark)
  target_compile_definitions(${name} PRIVATE
    PARKLOC_SOURCE_DIR="${PROJECT_SOURCE_DIR}" PARKLOC_MODEL_DIR="${PARKLOC_MODEL_DIR}")
  parkloc_warnings(${name})
endfunction()
