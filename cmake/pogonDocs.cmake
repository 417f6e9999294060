# The documentation's build target and checks (label "docs"):
#   target docs                  HTML API reference from the public headers (Doxygen),
#                                in <build>/docs/html/index.html
#   test docs_api_complete       Doxygen over the public headers warns about nothing:
#                                every public function, type, field and enumerator is
#                                documented
#   test docs_readme_example     the README's C example compiles and runs against the library
#   test docs_version_one_place  package.json and its lock name the version of version.h
#   test docs_generated_regions  every generated table in README.md and docs/ is what its
#                                tool renders from the committed results (tools/docs/regions.js)
find_program(POGON_DOXYGEN doxygen)
find_program(POGON_NODE node)

if(POGON_DOXYGEN)
  set(POGON_DOCS_OUT "${PROJECT_BINARY_DIR}/docs")
  set(POGON_DOCS_HTML YES)
  configure_file(${PROJECT_SOURCE_DIR}/cmake/Doxyfile.in ${PROJECT_BINARY_DIR}/docs/Doxyfile @ONLY)
  add_custom_target(docs
    COMMAND ${POGON_DOXYGEN} ${PROJECT_BINARY_DIR}/docs/Doxyfile
    COMMAND ${CMAKE_COMMAND} -E echo "API reference: ${PROJECT_BINARY_DIR}/docs/html/index.html"
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
    COMMENT "Generating the API reference with Doxygen"
    VERBATIM)
  set(POGON_DOCS_OUT "${PROJECT_BINARY_DIR}/docs-check")
  set(POGON_DOCS_HTML NO)
  configure_file(${PROJECT_SOURCE_DIR}/cmake/Doxyfile.in ${PROJECT_BINARY_DIR}/docs-check/Doxyfile @ONLY)
  if(POGON_TESTING)
    add_test(NAME docs_api_complete
      COMMAND ${CMAKE_COMMAND} -DDOXYGEN=${POGON_DOXYGEN} -DDOXYFILE=${PROJECT_BINARY_DIR}/docs-check/Doxyfile
              -DLOG=${PROJECT_BINARY_DIR}/docs-check/warnings.log
              -P ${PROJECT_SOURCE_DIR}/cmake/pogonDoxygenCheck.cmake)
    set_tests_properties(docs_api_complete PROPERTIES LABELS "docs" TIMEOUT 120)
  endif()
elseif(POGON_TESTING)
  message(STATUS "pogon: doxygen not found: target docs not made, docs_api_complete skips (scripts/setup-deps.sh)")
  add_test(NAME docs_api_complete COMMAND sh -c "echo 'doxygen not found: install it with scripts/setup-deps.sh'; exit 77")
  set_tests_properties(docs_api_complete PROPERTIES LABELS "docs" SKIP_RETURN_CODE 77)
endif()

if(POGON_TESTING AND TARGET pogon-accuracy)
  if(POGON_NODE)
    add_test(NAME docs_generated_regions
      COMMAND ${POGON_NODE} ${PROJECT_SOURCE_DIR}/tools/docs/regions.js
              --tool pogon-accuracy=$<TARGET_FILE:pogon-accuracy>)
    set_tests_properties(docs_generated_regions PROPERTIES LABELS "docs" TIMEOUT 120)
  else()
    add_test(NAME docs_generated_regions COMMAND sh -c "echo 'node not found: install it with scripts/setup-deps.sh'; exit 77")
    set_tests_properties(docs_generated_regions PROPERTIES LABELS "docs" SKIP_RETURN_CODE 77)
  endif()
endif()

# The README's example, compiled as a user would (static library builds only: the test
# links the archive directly).
if(POGON_TESTING AND NOT BUILD_SHARED_LIBS AND NOT CMAKE_CROSSCOMPILING)
  add_test(NAME docs_readme_example
    COMMAND ${CMAKE_COMMAND} -DREADME=${PROJECT_SOURCE_DIR}/README.md -DOUT=${PROJECT_BINARY_DIR}/readme-example
            -DCC=${CMAKE_C_COMPILER} "-DCFLAGS=${CMAKE_C_FLAGS}" -DINCLUDE=${PROJECT_SOURCE_DIR}/include -DLIB=$<TARGET_FILE:pogon>
            -P ${PROJECT_SOURCE_DIR}/cmake/pogonReadmeExample.cmake)
  set_tests_properties(docs_readme_example PROPERTIES LABELS "docs" TIMEOUT 120)
endif()

# The version in its one place and in the JavaScript package, which cannot read it.
if(POGON_TESTING)
  add_test(NAME docs_version_one_place
    COMMAND ${CMAKE_COMMAND} -DROOT=${PROJECT_SOURCE_DIR} -DVERSION=${PROJECT_VERSION}
            -P ${PROJECT_SOURCE_DIR}/cmake/pogonVersionCheck.cmake)
  set_tests_properties(docs_version_one_place PROPERTIES LABELS "docs" TIMEOUT 30)
endif()
