# Sanitizer and fuzzing builds, driven by scripts/run_sanitizers.sh in their own build folder.
# Everything compiled in such a build (the core, the ROS wrapper, the tests) is instrumented; the
# system libraries (MRPT, OpenCV, ROS, onnxruntime) are not.
option(KRP_SANITIZE "Instrument with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(KRP_BUILD_FUZZERS "Build the libFuzzer targets of tests/fuzz (needs clang; turns KRP_SANITIZE on)" OFF)

if(KRP_BUILD_FUZZERS)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "KRP_BUILD_FUZZERS needs clang (libFuzzer); configure with -DCMAKE_CXX_COMPILER=clang++ "
                        "(scripts/install_deps.sh installs it)")
  endif()
  set(KRP_SANITIZE ON CACHE BOOL "" FORCE)
  # Coverage feedback for the code under test; only the fuzzers themselves link libFuzzer's main.
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()

if(KRP_SANITIZE)
  # Undefined behaviour stops the program (no recovery), so a test or a fuzz run cannot pass over it.
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()
