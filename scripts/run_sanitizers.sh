#!/usr/bin/env bash
# Builds the unit tests and the fuzzers with clang, AddressSanitizer and UndefinedBehaviorSanitizer
# in build-sanitize/, then runs them: every GoogleTest of the core and of the ROS conversions, and
# each fuzzer for KRP_FUZZ_RUNS inputs from its seed corpus (tests/fuzz/corpus/). A memory error,
# undefined behaviour, a leak, a crash or an exception other than InputError fails the run.
# scripts/run_tests.sh calls this after the main suite; it assumes scripts/install_deps.sh has run.
#
#   scripts/run_sanitizers.sh                  # all of it
#   KRP_FUZZ_RUNS=200000 scripts/run_sanitizers.sh   # longer fuzzing
set -euo pipefail
REPO_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="$REPO_ROOT/build-sanitize"
cd "$REPO_ROOT"
cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ -DKRP_BUILD_FUZZERS=ON \
      -DKRP_FUZZ_RUNS="${KRP_FUZZ_RUNS:-3000}" \
      -DPYTHON_EXECUTABLE=/usr/bin/python3 -DPython3_EXECUTABLE=/usr/bin/python3 >/dev/null
cmake --build "$BUILD" -j"$(nproc)" --target krp_sanitizer_suite
cd "$BUILD"
# halt_on_error for UBSan as well; allocator_may_return_null lets a huge allocation throw
# std::bad_alloc, as it would without ASan, instead of aborting.
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=1:strict_string_checks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
ctest -j"$(nproc)" -L '^(unit|fuzz)$' --output-on-failure
