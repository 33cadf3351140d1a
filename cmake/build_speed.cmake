# What makes a build of the same code faster where Debian has it: ccache (its cache outside the
# build tree, ~/.cache/ccache unless CCACHE_DIR says otherwise, so a fresh clone reuses what an
# earlier one compiled) and the mold or lld linker. Either missing, the build is the same, slower.
if(ISURFACE_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  find_program(ISURFACE_CCACHE_PROGRAM ccache)
  if(ISURFACE_CCACHE_PROGRAM)
    # The precompiled headers are cached only with these sloppinesses (ccache's manual,
    # "Precompiled headers"); base_dir makes a clone in
    # another folder hit the same entries.
    set(launcher ${CMAKE_COMMAND} -E env
        "CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime"
        "CCACHE_BASEDIR=${CMAKE_SOURCE_DIR}" "CCACHE_NOHASHDIR=1" ${ISURFACE_CCACHE_PROGRAM})
    set(CMAKE_C_COMPILER_LAUNCHER ${launcher})
    set(CMAKE_CXX_COMPILER_LAUNCHER ${launcher})
    message(STATUS "Compiling through ${ISURFACE_CCACHE_PROGRAM}")
  endif()
endif()

if(NOT ISURFACE_FUZZ AND NOT CMAKE_EXE_LINKER_FLAGS MATCHES "-fuse-ld=")
  foreach(linker mold lld)
    include(CheckCXXSourceCompiles)
    set(CMAKE_REQUIRED_LINK_OPTIONS -fuse-ld=${linker})
    check_cxx_source_compiles("int main() { return 0; }" ISURFACE_LINKS_WITH_${linker})
    unset(CMAKE_REQUIRED_LINK_OPTIONS)
    if(ISURFACE_LINKS_WITH_${linker})
      add_link_options(-fuse-ld=${linker})
      message(STATUS "Linking with ${linker}")
      break()
    endif()
  endforeach()
endif()
