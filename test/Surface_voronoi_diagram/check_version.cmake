# Checks that the package has one version everywhere (ctest test `version_agrees`):
#   cmake -DSOURCE_DIR=<source tree> [-DCONFIG_VERSION_FILE=<build>/Surface_voronoi_diagramConfigVersion.cmake] -P check_version.cmake
# The version is project()'s in CMakeLists.txt. Every "version X.Y.Z" of the README and of the
# manual's .txt files must be it (the README, the manual and PackageDescription.txt must each
# say it at least once), the generated package version file must hold it, and every
# find_package(Surface_voronoi_diagram X.Y ...) there and in the downstream project must ask
# for its X.Y.
cmake_minimum_required(VERSION 3.14)
if(NOT SOURCE_DIR)
  message(FATAL_ERROR "check_version.cmake: give -DSOURCE_DIR=<the package's source tree>")
endif()
set(errors "")

file(READ "${SOURCE_DIR}/CMakeLists.txt" text)
if(NOT text MATCHES "project\\(Surface_voronoi_diagram VERSION ([0-9]+)\\.([0-9]+)\\.([0-9]+)")
  message(FATAL_ERROR "CMakeLists.txt: no project(Surface_voronoi_diagram VERSION X.Y.Z ...)")
endif()
set(version "${CMAKE_MATCH_1}.${CMAKE_MATCH_2}.${CMAKE_MATCH_3}")
set(major_minor "${CMAKE_MATCH_1}.${CMAKE_MATCH_2}")

if(CONFIG_VERSION_FILE)
  file(READ "${CONFIG_VERSION_FILE}" text)
  if(NOT text MATCHES "set\\(PACKAGE_VERSION \"([^\"]*)\"\\)" OR NOT CMAKE_MATCH_1 STREQUAL version)
    list(APPEND errors "${CONFIG_VERSION_FILE}: PACKAGE_VERSION is not ${version}")
  endif()
endif()

set(must_say README.md doc/Surface_voronoi_diagram/Surface_voronoi_diagram.txt doc/Surface_voronoi_diagram/PackageDescription.txt)
file(GLOB manual RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/doc/Surface_voronoi_diagram/*.txt")
foreach(file README.md ${manual} test/Surface_voronoi_diagram/downstream/CMakeLists.txt)
  file(READ "${SOURCE_DIR}/${file}" text)
  string(REGEX MATCHALL "[Vv]ersion [0-9]+\\.[0-9]+\\.[0-9]+" said "${text}")
  if(NOT said AND file IN_LIST must_say)
    list(APPEND errors "${file}: does not say \"version ${version}\"")
  endif()
  foreach(one IN LISTS said)
    string(REGEX REPLACE "^[Vv]ersion " "" one "${one}")
    if(NOT one STREQUAL version)
      list(APPEND errors "${file}: says version ${one}, not ${version}")
    endif()
  endforeach()
  string(REGEX MATCHALL "find_package\\(Surface_voronoi_diagram[ \t\n]+[0-9][0-9.]*" asked "${text}")
  foreach(one IN LISTS asked)
    string(REGEX REPLACE "^find_package\\(Surface_voronoi_diagram[ \t\n]+" "" one "${one}")
    if(NOT one STREQUAL major_minor AND NOT one STREQUAL version)
      list(APPEND errors "${file}: find_package(Surface_voronoi_diagram ${one}), not ${major_minor}")
    endif()
  endforeach()
endforeach()

if(errors)
  list(JOIN errors "\n  " errors)
  message(FATAL_ERROR "the package's version is ${version}, but:\n  ${errors}")
endif()
message(STATUS "version ${version} everywhere")
