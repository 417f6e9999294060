# snapshot.cmake — copy the sources pogon-probe was just built from into the build tree
# (cmake -DSOURCE_DIR=<project> -DDEST=<dir> -DDIRS=<dir,dir...> -P snapshot.cmake).
# Run at build time, right after pogon-probe links: the determinism_* tests compile this
# copy for the other targets, so they test the code the native probe was built from even
# when the working tree is edited between `cmake --build` and `ctest`.
if(NOT SOURCE_DIR OR NOT DEST OR NOT DIRS)
  message(FATAL_ERROR "snapshot.cmake: SOURCE_DIR, DEST and DIRS are required")
endif()
string(REPLACE "," ";" DIRS "${DIRS}")
set(tmp "${DEST}.tmp")
file(REMOVE_RECURSE "${tmp}")
foreach(dir IN LISTS DIRS)
  file(GLOB files LIST_DIRECTORIES false "${SOURCE_DIR}/${dir}/*.c" "${SOURCE_DIR}/${dir}/*.h" "${SOURCE_DIR}/${dir}/*.inc"
    "${SOURCE_DIR}/${dir}/*.ld")
  file(MAKE_DIRECTORY "${tmp}/${dir}")
  if(files)
    file(COPY ${files} DESTINATION "${tmp}/${dir}")
  endif()
endforeach()
file(REMOVE_RECURSE "${DEST}")
file(RENAME "${tmp}" "${DEST}")
