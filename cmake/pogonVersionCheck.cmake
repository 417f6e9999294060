# pogonVersionCheck.cmake — the version is written once, in include/pogon/version.h;
# CMake reads it from there (CMakeLists.txt), and the JavaScript package (package.json,
# package-lock.json), which cannot read a header, must say the same; so must the
# documents' find_package(pogon MAJOR.MINOR) examples, since the package accepts only
# its own minor version before 1.0 (SameMinorVersion). Run by the test
# docs_version_one_place: cmake -DROOT=<source dir> -DVERSION=<project version> -P this.
foreach(file package.json package-lock.json)
  file(READ "${ROOT}/${file}" text)
  string(REGEX MATCH "\"version\": \"([0-9.]+)\"" found "${text}")
  if(NOT CMAKE_MATCH_1 STREQUAL VERSION)
    message(FATAL_ERROR "${file} says version '${CMAKE_MATCH_1}', include/pogon/version.h says '${VERSION}': write the header's version there")
  endif()
endforeach()
string(REGEX MATCH "^[0-9]+\\.[0-9]+" minor "${VERSION}")
file(GLOB documents "${ROOT}/docs/*.md")
foreach(file "${ROOT}/README.md" ${documents})
  file(READ "${file}" text)
  string(REGEX MATCHALL "find_package\\(pogon [0-9]+\\.[0-9]+" asks "${text}")
  foreach(ask ${asks})
    string(REGEX REPLACE "find_package\\(pogon " "" asked "${ask}")
    if(NOT asked STREQUAL minor)
      file(RELATIVE_PATH name "${ROOT}" "${file}")
      message(FATAL_ERROR "${name} shows find_package(pogon ${asked}), which the package of version ${VERSION} refuses (SameMinorVersion): write ${minor}")
    endif()
  endforeach()
endforeach()
message(STATUS "version ${VERSION} in version.h, package.json, package-lock.json and the documents' find_package examples")
