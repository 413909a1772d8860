#!/usr/bin/env bash
# Builds everything (tests and the libFuzzer harnesses) with clang under
# AddressSanitizer + UndefinedBehaviorSanitizer in build-asan/. One build serves
# both tools/test-sanitizers.sh and tools/fuzz.sh, so CI compiles Tunica twice
# (Release and this), not three times.
set -euo pipefail
cd "$(dirname "$0")/.."
missing=()
for p in clang libclang-rt-14-dev libomp-14-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  sudo_cmd=""; [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
bash tools/install-deps.sh
# -O1 -g1: a third of the compile time of -O2 -g, and the same reports.
CXX=clang++ cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -g1" -DTUNICA_FUZZ=ON >/dev/null
cmake --build build-asan -j"$(nproc)"
