#!/usr/bin/env bash
# The whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer (clang,
# build-asan/ from tools/build-asan.sh); any sanitizer report fails a test.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build-asan.sh
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
export LSAN_OPTIONS="suppressions=$PWD/fuzz/lsan.supp"
ctest --test-dir build-asan --output-on-failure -j"$(nproc)"
