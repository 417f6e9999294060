# pogonVersionCheck.cmake — the version is written once, in include/pogon/version.h;
# CMake reads it from there (CMakeLists.txt), and the JavaScript package (package.json,
# package-lock.json), which cannot read a header, must say the same. Run by the test
# docs_version_one_place: cmake -DROOT=<source dir> -DVERSION=<project version> -P this.
foreach(file package.json package-lock.json)
  file(READ "${ROOT}/${file}" text)
  string(REGEX MATCH "\"version\": \"([0-9.]+)\"" found "${text}")
  if(NOT CMAKE_MATCH_1 STREQUAL VERSION)
    message(FATAL_ERROR "${file} says version '${CMAKE_MATCH_1}', include/pogon/version.h says '${VERSION}': write the header's version there")
  endif()
endforeach()
message(STATUS "version ${VERSION} in version.h, package.json and package-lock.json")
