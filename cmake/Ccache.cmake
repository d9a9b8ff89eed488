# A second build, or a fresh clone's, compiles only what changed: ccache keyed
# on paths relative to the source tree (CCACHE_BASEDIR), not on the folder.
# Used by the main build and by fuzz/, a project of its own over the same tree.
option(VIEWPIPE_CCACHE "Cache compiles with ccache where it is installed" ON)
find_program(VIEWPIPE_CCACHE_PROGRAM ccache)
get_filename_component(VIEWPIPE_SOURCE_ROOT "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)
if(VIEWPIPE_CCACHE AND VIEWPIPE_CCACHE_PROGRAM AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  set(CMAKE_CXX_COMPILER_LAUNCHER
      ${CMAKE_COMMAND} -E env CCACHE_BASEDIR=${VIEWPIPE_SOURCE_ROOT} CCACHE_NOHASHDIR=1 ${VIEWPIPE_CCACHE_PROGRAM})
  set(CMAKE_C_COMPILER_LAUNCHER ${CMAKE_CXX_COMPILER_LAUNCHER})
endif()
