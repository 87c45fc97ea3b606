# Warnings on for everything we compile; generated vendor code gets them off (plumb_relax_warnings).
find_program(CCACHE_PROGRAM ccache)
if(CCACHE_PROGRAM)
  set(CMAKE_C_COMPILER_LAUNCHER ${CCACHE_PROGRAM})
  set(CMAKE_CXX_COMPILER_LAUNCHER ${CCACHE_PROGRAM})
endif()

option(PLUMB_WERROR "Treat warnings as errors" OFF)
set(PLUMB_SANITIZE "" CACHE STRING "Sanitizers to build with, e.g. address,undefined")

add_library(plumb_warnings INTERFACE)
target_compile_options(plumb_warnings INTERFACE -Wall -Wextra -Wpedantic
  $<$<BOOL:${PLUMB_WERROR}>:-Werror>)

if(PLUMB_SANITIZE)
  add_compile_options(-fsanitize=${PLUMB_SANITIZE} -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=${PLUMB_SANITIZE})
endif()

# Generated DDS code is not ours to fix: compile it quietly.
function(plumb_relax_warnings target)
  target_compile_options(${target} PRIVATE -w)
endfunction()
