#!/usr/bin/env bash
# The .msh corruption campaign (docs/reliability.md): 1,000 random 8-byte corruptions of
# every shipped mesh through `tunica check`; 0 crashes, 0 hangs, every refusal one line
# naming the file. Builds Release first. Not part of the fast suite (it keeps a sample).
#   bash tools/mesh-corruption.sh [TRIALS]     (or: cmake --build build --target mesh-corruption)
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
bash tools/build.sh >/dev/null
python3 tools/mesh-corruption.py build/tunica "${1:-1000}"
