# world_hash_check.cmake — does the library define pg_world_hash() yet?
# Included by tools/CMakeLists.txt (pogon-probe) and tests/targets/CMakeLists.txt (the
# probe's cross builds), so both compile tools/probe/probe.c with the same
# POGON_PROBE_HAVE_WORLD_HASH.

# pogon_probe_world_hash_check(<out-var>): 1 when the library's sources define
# pg_world_hash() (include/pogon/replay.h), else 0. A source-level check, because the
# library is not built yet when CMake configures. While the function is missing, the
# library's sources are configure dependencies, so the build notices when it appears
# (once it is there they are not, and editing src/ does not re-run CMake).
function(pogon_probe_world_hash_check out)
  get_target_property(sources pogon SOURCES)
  get_target_property(source_dir pogon SOURCE_DIR)
  set(found 0)
  set(scanned "")
  foreach(source IN LISTS sources)
    if(NOT IS_ABSOLUTE "${source}")
      set(source "${source_dir}/${source}")
    endif()
    if(source MATCHES "\\.c$" AND EXISTS "${source}")
      list(APPEND scanned "${source}")
      file(STRINGS "${source}" lines REGEX "^uint64_t[ \t]+pg_world_hash[ \t]*\\(")
      foreach(line IN LISTS lines)
        if(NOT line MATCHES ";[ \t]*$")
          set(found 1)
        endif()
      endforeach()
    endif()
  endforeach()
  if(NOT found)
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${scanned})
  endif()
  set(${out} ${found} PARENT_SCOPE)
endfunction()
