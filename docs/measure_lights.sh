#!/usr/bin/env bash
# Produces docs/lights.md's table: median ms per frame of each pipeline at 1280x720 (default
# frame, 21:00, standard G-buffer) for 0..4096 of the scene's point lights, wall time around
# glFinish, plus the deferred light-volume passes alone. Runs the GPU suite's disabled
# LightsTable test. usage: docs/measure_lights.sh [build dir] [frames] [most lights to time forward at]   (an idle machine; markdown)
set -euo pipefail
build=${1:-build}
OASIS_LIGHT_FRAMES=${2:-5} OASIS_LIGHT_FORWARD_MAX=${3:-4096} "$build/tests/oasis_gpu_tests" --gtest_also_run_disabled_tests \
  --gtest_filter='GpuTest.DISABLED_LightsTable' | grep -E '^\||^renderer'
echo "$(nproc) cores"
