# world_hash_check.cmake — pogon-probe prints pg_world_hash(), always.
# Included by tools/CMakeLists.txt (pogon-probe) and tests/targets/CMakeLists.txt (the
# probe's cross builds), so both compile tools/probe/probe.c with the same
# POGON_PROBE_HAVE_WORLD_HASH.

# pogon_probe_world_hash_check(<out-var>): sets <out-var> to 1. pg_world_hash() is part of
# the library (include/pogon/replay.h), so the world= hashes are always in the probe's
# output and the determinism_* tests always compare them. This used to be detected from
# the library's source text, which would have dropped the hashes silently had the
# definition merely been reformatted; now a library without pg_world_hash() fails to
# build pogon-probe instead.
function(pogon_probe_world_hash_check out)
  set(${out} 1 PARENT_SCOPE)
endfunction()
