#!/usr/bin/env bash
# Produces docs/lights.md's tables, both at 1280x720 (default frame, 21:00, standard G-buffer),
# wall time around glFinish, from the GPU suite's disabled tests:
#   docs/measure_lights.sh [build dir] [frames] [most lights to time forward at]
#     median ms per frame of each pipeline for 0..4096 of the scene's point lights, plus the
#     deferred light-volume passes alone (LightsTable)
#   docs/measure_lights.sh --methods [build dir] [rounds]
#     the two deferred light methods, volumes and tiled, interleaved in rounds over 0..4096 lights:
#     the ms each spends on the lights, the frame, and each one's marginal cost of a light (the
#     slope of a least-squares line over the counts) and where the lines cross (LightMethodsTable)
# (an idle machine; markdown)
set -euo pipefail
if [[ ${1:-} == --methods ]]; then
  build=${2:-build}
  OASIS_LIGHT_ROUNDS=${3:-3} "$build/tests/oasis_gpu_tests" --gtest_also_run_disabled_tests \
    --gtest_filter='GpuTest.DISABLED_LightMethodsTable' | grep -E '^\||^marginal|^lines|^tiled at|^renderer'
else
  build=${1:-build}
  OASIS_LIGHT_FRAMES=${2:-5} OASIS_LIGHT_FORWARD_MAX=${3:-4096} "$build/tests/oasis_gpu_tests" --gtest_also_run_disabled_tests \
    --gtest_filter='GpuTest.DISABLED_LightsTable' | grep -E '^\||^renderer'
fi
echo "$(nproc) cores"
