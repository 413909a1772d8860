# The include rules the layer views cannot enforce (run by the build before any layer compiles,
# again whenever a source changes; docs/architecture.md, "Layers"):
#  - no relative #include ("../x.hpp", "./x.hpp"): it resolves beside the real file and so
#    reaches folders outside the layer's view; include by folder ("output/atomic_file.hpp");
#  - yaml-cpp only in src/io (it is a system include path, visible to every layer).
# cmake -DSRC=<src dir> -DSTAMP=<file> -P check_includes.cmake
file(GLOB_RECURSE files RELATIVE ${SRC} ${SRC}/*.cpp ${SRC}/*.hpp)
set(problems "")
foreach(f IN LISTS files)
  file(STRINGS ${SRC}/${f} lines REGEX "^[ \t]*#[ \t]*include")
  string(REGEX MATCH "^[^/]+" folder ${f})
  foreach(l IN LISTS lines)
    if(l MATCHES "#[ \t]*include[ \t]*\"\\.\\.?/")
      string(APPEND problems "\n  src/${f}: ${l}: a relative include reaches past the layer's view; include by folder, from a layer beneath")
    endif()
    if(l MATCHES "yaml-cpp/" AND NOT folder STREQUAL "io")
      string(APPEND problems "\n  src/${f}: ${l}: yaml-cpp belongs to src/io (the deck reader) alone")
    endif()
  endforeach()
endforeach()
if(problems)
  message(FATAL_ERROR "include rules broken (docs/architecture.md, Layers):${problems}")
endif()
file(TOUCH ${STAMP})
