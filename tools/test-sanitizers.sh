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
# So do the mesh-refinement studies and long round trips that repeat, on finer meshes, the code
# a smaller sibling of theirs runs here (1 to 4 minutes each under the sanitizers):
#   AneurysmZeroPressure (InverseStep.*, FixedPointInverse.* on the tube and octant),
#   InverseStep.OctantRoundTrip… (its axisymmetric and 6-node siblings), InverseSphere3d
#   (InverseThenForward, InverseStep.Sphere…), FixedPointInverse.OctantAgrees… (the other
#   FixedPointInverse tests), Sphere3d.ErrorFalls… (the other Sphere3d tests),
#   ComputeThreads.ARunComputes… (ComputeThreads.ResultsAreIdentical…, SolidSystem.Parallel…),
#   ResourceLimits.PartsTogether… (the other ResourceLimits tests and the deck fuzzer).
slow='^Angioplasty|^AneurysmZeroPressure\.|^InverseStep\.OctantRoundTrip|^InverseSphere3d\.'
slow+='|^FixedPointInverse\.OctantAgrees|^Sphere3d\.ErrorFalls|^ComputeThreads\.ARunComputes'
slow+='|^ResourceLimits\.PartsTogether'
ctest --test-dir build-asan --output-on-failure -j"$(nproc)" -E "$slow"
