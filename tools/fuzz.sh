#!/usr/bin/env bash
# Coverage-guided fuzzing of every reader (libFuzzer, clang, ASan + UBSan):
#   bash tools/fuzz.sh [SECONDS_PER_HARNESS]   (default 30: the CI smoke run)
# Seeds: fuzz/corpus/<reader>/; the growing corpus stays in build-fuzz/corpus/<reader>/.
# A crash, hang or leak stops the run and leaves its input as build-fuzz/<reader>-crash-*:
# copy it to fuzz/regressions/<reader>/ (the test suite replays that folder) and fix the bug.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-30}"
bash tools/build-asan.sh
export LSAN_OPTIONS="suppressions=$PWD/fuzz/lsan.supp"
for harness in build-asan/fuzz/*_fuzzer; do
  name=$(basename "$harness" _fuzzer)
  mkdir -p "build-fuzz/corpus/$name"
  echo "== fuzzing the $name reader for $seconds s"
  "$harness" -max_total_time="$seconds" -max_len=8192 -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -artifact_prefix="build-fuzz/$name-" "build-fuzz/corpus/$name" "fuzz/corpus/$name" 2>&1 |
    grep -E "^(stat::number_of_executed_units|stat::peak_rss_mb)|cov:.*(DONE|INITED)|ERROR|SUMMARY|Test unit written" || true
  if ls "build-fuzz/$name-"* >/dev/null 2>&1; then
    echo "fuzz: the $name reader failed; inputs: $(ls build-fuzz/$name-*)" >&2
    exit 1
  fi
done
echo "fuzz: no crash, hang or leak"
