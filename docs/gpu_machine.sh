#!/usr/bin/env bash
# What ran on the lent NVIDIA machine (the workplace's `device` tool) for compatibility.md's NVIDIA
# section: oasis headless through EGL there, its capability report, the frame's time and traffic at
# three sizes beside an older build's (the same card, the same call: a before/after), `oasis check`
# on desktop GL and ES, the frames against llvmpipe's saved ones, the lights, the tiers, the GPU
# test suite and the bench.
# Prepare here, in the repository root (the machine is bare and reaches nothing):
#   echo /.gl/ >> .git/info/exclude; mkdir -p .gl/lib
#   (cd .gl && apt-get download libvulkan1 libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2)
#   cp build/oasis build/tests/oasis_gpu_tests .gl/
#   for l in libepoxy.so.0 libstb.so.0 libglfw.so.3 libX11.so.6 libxcb.so.1 libXau.so.6 \
#            libXdmcp.so.6 libbsd.so.0 libmd.so.0; do cp -L /lib/x86_64-linux-gnu/$l .gl/lib/; done
#   for p in deferred forward; do ./build/oasis render --legend off --pipeline $p --out .gl/ref-$p.png; done
#   optional, the "before" of a before/after: an older commit's build/oasis and shaders/ in
#   .gl/before/oasis and .gl/before/shaders (git worktree add ../before COMMIT; build it there)
# then run it there with `.gl` carried: OUT=$OUT bash docs/gpu_machine.sh (about 4.5 minutes on an
# H200), or some of its steps: OUT=$OUT bash docs/gpu_machine.sh compare gpu_tests.
# The timed steps come first and alone; the correctness steps (check, tests) after them.
set -u
exec > >(tee "$OUT/log.txt") 2>&1
G=$PWD/.gl
for f in "$G"/*.deb; do dpkg -x "$f" /; done; ldconfig   # the GL loaders (glvnd) over NVIDIA's driver
export LD_LIBRARY_PATH=$G/lib OASIS_SHADER_DIR=$PWD/shaders
B="$G/oasis"
s() { echo; echo "=== $* ($(date +%T))"; }
nvidia() { nvidia-smi -L; nvidia-smi --query-gpu=driver_version --format=csv; }
caps() { timeout 60 "$B" caps; }
main_job() { timeout 60 "$B" --out-dir /tmp/main; }
compare() {  # the before (an older build, when carried) and the after in turn, on the same card
  for size in 1280x720 1920x1080 3840x2160; do
    if [ -x "$G/before/oasis" ]; then echo "--- before, $size"
      timeout 90 env OASIS_SHADER_DIR="$G/before/shaders" "$G/before/oasis" compare --passes --frames 15 \
        --size $size --out-dir /tmp/b-$size; echo "--- after, $size"; fi
    timeout 90 "$B" compare --passes --frames 15 --size $size --out-dir /tmp/c-$size; done; }
lights() { for m in volumes tiled; do timeout 60 "$B" compare --frames 9 --hour 21 --lights 4096 \
  --light-method $m --out-dir /tmp/l-$m | grep -E "ms/frame|lights|than forward|no difference|no verdict"; done; }
tiers() { for t in "--force gl33" "--api gles" "--api gles --force gles30" "--gbuffer full --depth reversed-z"; do
  timeout 60 "$B" compare --frames 9 $t --out-dir /tmp/t | grep -E "PSNR|ms/frame|on |than forward|no difference|no verdict"; done; }
bench() { timeout 170 "$B" bench --out-dir /tmp/bench | tail -70; cp /tmp/bench/bench.csv "$OUT/" 2>/dev/null; }
check() {
  timeout 150 "$B" check --references tests/check-references --out-dir /tmp/check; echo "rc=$?"
  cp /tmp/check/report.json "$OUT/check.json"; cp /tmp/check/report.html "$OUT/check.html"
  timeout 150 "$B" check --api gles --references tests/check-references --out-dir /tmp/check-gles; echo "rc=$?"
  cp /tmp/check-gles/report.json "$OUT/check-gles.json"; }
against_llvmpipe() {
  for p in deferred forward; do
    timeout 60 "$B" compare --reference "$G/ref-$p.png" --pipeline $p --out-dir /tmp/ref-$p; done
  cp /tmp/ref-deferred/difference.png "$OUT/vs-llvmpipe-deferred-diff.png"; }
gpu_tests() {
  (cd /tmp && timeout 200 "$G/oasis_gpu_tests" --gtest_brief=1 > "$OUT/gpu-tests.txt" 2>&1; echo "rc=$?")
  grep -E "^\[  (FAILED|PASSED) " "$OUT/gpu-tests.txt"; }
for step in ${@:-nvidia caps main_job compare lights tiers bench check against_llvmpipe gpu_tests}; do
  s "$step"; "$step"; done
s done
