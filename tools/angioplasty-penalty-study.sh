#!/usr/bin/env bash
# Penalty study of the balloon-angioplasty example (issue #4): runs copies of
# examples/balloon-angioplasty.yaml with both contact penalties scaled by each factor
# (default 0.1 1 3 10 100) and prints a Markdown table (see tools/angioplasty_study.py for
# the columns). Runs under nice -n 19, one at a time, in a temporary directory.
#   PLAQUE_ELEMENTS_Z=300 tools/angioplasty-penalty-study.sh 1 10   the same on a plaque
#                                                                     with 300 elements along z
#   TUNICA=path/to/tunica, PYTHON=path/to/python3, KEEP=DIR (keep the runs)
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -gt 0 ] || set -- 0.1 1 3 10 100
exec "${PYTHON:-/usr/bin/python3}" tools/angioplasty_study.py penalty "$@"
