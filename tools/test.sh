#!/usr/bin/env bash
# One command: install what is missing, build Release, run the whole test suite through CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
bash tools/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
