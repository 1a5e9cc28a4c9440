#!/usr/bin/env bash
# Produces docs/compatibility.md's table: for each driver set-up, what `oasis caps --json`
# reports (GL, renderer, the paths taken), the result of its ctest label, and the median ms per
# frame of each pipeline at 640x360 (`oasis compare --json`, wall time around glFinish), and the
# PSNR of its default frame against llvmpipe's at 320x180 (`oasis compare --driver llvmpipe
# --driver SET-UP --json`, the set-up table of src/cli/driver_setups.cpp), the OpenGL ES tiers
# (--api gles: ES 3.2, ES 3.1 by Mesa's version override, and --force gles30) included.
# usage: docs/compat.sh [build-dir] [frames]   (after a build; run on an idle machine; prints markdown)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
frames=${2:-5}
oasis=$build/oasis
out=$(mktemp -d)
xdg=$(mktemp -d) && chmod 700 "$xdg"
trap 'rm -rf "$out" "$xdg"' EXIT
field() { sed -E "s/.*\"$1\": (\"([^\"]*)\"|([^,}]*)).*/\2\3/" <<<"$2"; }
used() { sed -E "s/.*\"$1\": \\{\"used\": (true|false).*/\1/" <<<"$2"; }

# name ; environment ; ctest label (a regex for ctest -L), or =REGEX for ctest -R ; extra oasis
# options ; frames (softpipe takes ~10 s a frame at 640x360: 1) ; compare --driver set-up
nossbo="MESA_SHADER_CACHE_DISABLE=true MESA_EXTENSION_OVERRIDE=-GL_ARB_shader_storage_buffer_object%-GL_ARB_compute_shader"
setups=(
  "llvmpipe;env;^gpu\$;;$frames;llvmpipe"
  "zink over lavapipe;env LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=zink XDG_RUNTIME_DIR=$xdg;^gpu-zink\$;;$frames;zink"
  "softpipe;env GALLIUM_DRIVER=softpipe;^gpu-softpipe\$;;1;softpipe"
  "llvmpipe without SSBO/compute;env $nossbo;^gpu-no-ssbo-compute\$;;$frames;no-ssbo-compute"
  "softpipe without SSBO/compute/stencil texturing (bare 3.3);env GALLIUM_DRIVER=softpipe $nossbo%-GL_ARB_stencil_texturing;=^cli.softpipe_bare_gl33_tier\$;;1;softpipe-bare"
  "llvmpipe, --force gl33,no-ssbo,no-compute,no-stencil-texturing;env;=^cli.(caps_forced_gl33_tier|force_gl33_draws_the_unforced_image)\$;--force gl33,no-ssbo,no-compute,no-stencil-texturing;$frames;bare-gl33"
  "llvmpipe, OpenGL ES 3.2 (--api gles);env;^gpu-gles\$;--api gles;$frames;gles"
  "llvmpipe, OpenGL ES 3.1 (MESA_GLES_VERSION_OVERRIDE=3.1, --api gles);env MESA_GLES_VERSION_OVERRIDE=3.1;^gpu-gles31\$;--api gles;$frames;gles31"
  "llvmpipe, OpenGL ES 3.0 tier (--api gles --force gles30);env;=^cli.(caps_gles30_tier|gles_frames_equal_desktop|gles_probe_equals_desktop)\$;--api gles --force gles30;$frames;gles30"
)

echo "| set-up | GL (GLSL) | renderer | light list | plants | stencil view | tests | forward ms | deferred ms | PSNR vs llvmpipe |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"
for setup in "${setups[@]}"; do
  IFS=';' read -r name environment label extra setupFrames driver <<<"$setup"
  # One environment word may hold a space, written as %.
  read -r -a envwords <<<"$environment"
  envwords=("${envwords[@]//%/ }")
  # shellcheck disable=SC2086
  if ! caps=$("${envwords[@]}" "$oasis" caps --json $extra 2>/dev/null); then
    echo "| $name | not available here | | | | | skipped | | | |"
    continue
  fi
  light=$([[ $(used ssbo-light-list "$caps") == true ]] && echo SSBO || echo UBO)
  plants=$([[ $(used compute-plant-interpretation "$caps") == true ]] && echo "compute" || echo "CPU")
  stencil=$([[ $(used stencil-texturing "$caps") == true ]] && echo "stencil texturing" || echo "read-back")
  if [[ $label == =* ]]; then
    summary=$(ctest --test-dir "$build" -R "${label#=}" 2>&1 | grep -E "tests passed" || true)
    summary="$summary (${label#=})"
  else
    log=$(ctest --test-dir "$build" -L "$label" -V 2>&1 || true)
    summary=$(grep -E "tests passed" <<<"$log" || true)
    # A set-up's label is one ctest test running the whole binary: add gtest's own counts.
    if [[ $(grep -c "Test #" <<<"$log") -eq 1 ]]; then
      gtests=$(grep -E "^[0-9]+: \[ *(PASSED|SKIPPED|FAILED) *\] [0-9]+ tests?" <<<"$log" |
               sed -E 's/.*\[ *([A-Z]+) *\] ([0-9]+) tests?.*/\2 \L\1/' | paste -sd, - || true)
      [[ -n $gtests ]] && summary="$summary (gtest: ${gtests//,/, })"
      if grep -q '\*\*\*Skipped' <<<"$log"; then
        summary="skipped: $(grep -o 'SKIPPED: .*' <<<"$log" | head -1 || true)"
      fi
    fi
  fi
  summary=$(sed -E 's/^ *//; s/, 0 tests failed out of/ of/' <<<"$summary")
  summary=${summary//|/\\|}  # a regex's | must not end the Markdown cell
  # shellcheck disable=SC2086
  cmp=$("${envwords[@]}" "$oasis" compare --size 640x360 --frames "$setupFrames" --json --out-dir "$out" $extra 2>/dev/null) || cmp=""
  # The default frame against llvmpipe's: "identical" at max abs 0, else the PSNR and max abs.
  if [[ $driver == llvmpipe ]]; then
    psnr="(the reference)"
  elif drv=$("$oasis" compare --driver llvmpipe --driver "$driver" --size 320x180 --json --out-dir "$out/drivers" 2>/dev/null); then
    if [[ $(field max_abs "$drv") == 0 ]]; then psnr="identical"
    else psnr=$(printf "%.1f dB (max abs %s)" "$(field psnr_db "$drv")" "$(field max_abs "$drv")"); fi
  else
    psnr="failed"
  fi
  printf "| %s | %s.%s (%s) | %s | %s | %s | %s | %s | %.1f | %.1f | %s |\n" "$name" "$(field major "$caps")" \
    "$(field minor "$caps")" "$(field glsl_version "$caps")" "$(field renderer "$caps")" "$light" "$plants" \
    "$stencil" "$summary" "$(field forward_ms "$cmp")" "$(field deferred_ms "$cmp")" "$psnr"
done
echo "| NVIDIA H100 (EGL headless) | not on this machine: measured on a lent one, see [the NVIDIA section](#nvidia-h100-a-lent-machine) | | | | | | | | |"
echo "| NVIDIA H200 (EGL headless) | not on this machine: measured on a lent one, see [the H200 section](#nvidia-h200-a-second-loan-the-frame-before-and-after-issue-30s-clears) | | | | | | | | |"
echo
echo "ms: median of $frames frames (softpipe: 1) at 640x360, wall time around glFinish, $(nproc) cores, load average at the end $(cut -d' ' -f1-3 /proc/loadavg); tests: the set-up's ctest label (or tests); PSNR vs llvmpipe: the default frame at 320x180, deferred, over 8-bit RGB (\`oasis compare --driver llvmpipe --driver SET-UP\`)"
