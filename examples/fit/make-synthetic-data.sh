#!/usr/bin/env bash
# Regenerates examples/fit/rat-aorta-synthetic.csv from its plan with the same thin-tube
# and material code that `tunica fit` and the FE solver use (`tunica synthesize`, a
# hidden subcommand). TUNICA=path/to/tunica to use another binary (default build/tunica).
set -euo pipefail
cd "$(dirname "$0")/../.."
tunica="${TUNICA:-./build/tunica}"
[ -x "$tunica" ] || { echo "make-synthetic-data: $tunica is not built (bash tools/build.sh, or set TUNICA)" >&2; exit 1; }
"$tunica" synthesize examples/fit/rat-aorta-synthetic.yaml -o examples/fit/rat-aorta-synthetic.csv
