# What keeps a cold build short on a 2-core machine (docs/contributing.md, "Build time").
#
# Unity builds: each target's sources are compiled in batches, one compiler run per batch. Most of
# a plumb object's time is the inline code of header-only libraries (CLI11's parser, GoogleTest,
# Eigen's fixed-size products), which every file that uses it compiles and optimizes again; a batch
# compiles it once. A file's internal names (its anonymous namespace) must therefore be unique in
# its target: shared helpers live in a header, file-local ones have names of their own.
# -DPLUMB_UNITY_BUILD=OFF compiles file by file (faster one-file rebuilds while editing).
option(PLUMB_UNITY_BUILD "Compile each target's sources in batches (unity build)" ON)
set(CMAKE_UNITY_BUILD ${PLUMB_UNITY_BUILD})
set(CMAKE_UNITY_BUILD_BATCH_SIZE 16)

# The code on the paths that docs/benchmarks.md times by its own arithmetic (the estimators, the
# bridge's parser, the recorder) is compiled file by file as it always was: a batch lets the
# optimizer inline across files and changes the machine code; these stay as measured. The
# transports and their generated types are batched: their time is the DDS libraries' (the
# transport benchmark's latency is the same either way, docs/contributing.md).
# A sanitizer build is never timed: it batches these too.
function(plumb_compile_file_by_file target)
  if(NOT PLUMB_SANITIZE)
    set_target_properties(${target} PROPERTIES UNITY_BUILD OFF)
  endif()
endfunction()
