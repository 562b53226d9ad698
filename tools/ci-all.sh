#!/usr/bin/env bash
# Everything CI checks, in three build directories (the README's test command runs this after
# installing the packages):
#   build       the normal build (warnings are errors) and the whole suite offscreen;
#   build-asan  the same code with AddressSanitizer + UndefinedBehaviorSanitizer and the whole suite
#               again (leaks and undefined behaviour fail a test; benchmarks are not built), built
#               with clang: it compiles the sanitized code in about half GCC's time, and its
#               warnings check the code a second way;
#   build-fuzz  clang's libFuzzer targets for every reader of outside bytes, each fuzzed for
#               FOOTPATH_FUZZ_SECONDS (default 20) from its seed corpus.
# Any failure stops the script with a non-zero exit.
set -euo pipefail
cd "$(dirname "$0")/.."
fuzzSeconds=${FOOTPATH_FUZZ_SECONDS:-20}
jobs=$(nproc)  # tests and fuzz targets run in parallel, one per core
step() { printf '\n==== %s (%s)\n' "$1" "$(date -u +%H:%M:%S)"; }

step "normal build and suite"
cmake -S . -B build -G Ninja -DFOOTPATH_WERROR=ON
cmake --build build
QT_QPA_PLATFORM=offscreen ctest --test-dir build --output-on-failure -j"$jobs"

step "sanitizer build and suite"
CC=clang CXX=clang++ cmake -S . -B build-asan -G Ninja -DFOOTPATH_WERROR=ON -DFOOTPATH_SANITIZE=ON \
    -DFOOTPATH_BUILD_BENCHMARKS=OFF
cmake --build build-asan
QT_QPA_PLATFORM=offscreen ctest --test-dir build-asan --output-on-failure -j"$jobs"

step "fuzz build and bounded fuzzing"
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DFOOTPATH_WERROR=ON -DFOOTPATH_FUZZ=ON \
    -DFOOTPATH_FUZZ_SECONDS="$fuzzSeconds"
cmake --build build-fuzz
ctest --test-dir build-fuzz --output-on-failure -j"$jobs"
step "done"
