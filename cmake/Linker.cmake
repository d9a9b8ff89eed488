# LLVM's linker where the compiler can use it: it links a sanitized test
# program (200 MB with debug information) in 2 s where GNU ld takes 7 s, and
# the build links about twenty. Used by the main build and by fuzz/.
include(CheckLinkerFlag)
check_linker_flag(CXX "-fuse-ld=lld" VIEWPIPE_LINKS_WITH_LLD)
if(VIEWPIPE_LINKS_WITH_LLD)
  add_link_options(-fuse-ld=lld)
endif()
