#!/usr/bin/env bash
# The whole test suite under AddressSanitizer + UndefinedBehaviorSanitizer (clang,
# build-asan/ from tools/build-asan.sh); any sanitizer report fails a test.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/build-asan.sh
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
export LSAN_OPTIONS="suppressions=$PWD/fuzz/lsan.supp"
# The angioplasty examples (Angioplasty*, 25 s in Release, several minutes under the
# sanitizers) run in the Release suite only; every kernel and assembly path they use
# (solid, membrane, shell, smooth and faceted contact, entering parts) has its own tests here.
ctest --test-dir build-asan --output-on-failure -j"$(nproc)" -E '^Angioplasty'
