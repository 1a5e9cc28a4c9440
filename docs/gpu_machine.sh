#!/usr/bin/env bash
# What ran on the lent NVIDIA machine (the workplace's `device` tool) for compatibility.md's NVIDIA
# section: oasis headless through EGL there, its capability report, timings at three sizes, its
# frames against llvmpipe's saved ones, the tiers, the lights, the GPU test suite and the bench.
# Prepare here, in the repository root (the machine is bare and reaches nothing):
#   echo /.gl/ >> .git/info/exclude; mkdir -p .gl/lib
#   (cd .gl && apt-get download libvulkan1 libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2)
#   cp build/oasis build/tests/oasis_gpu_tests .gl/
#   for l in libepoxy.so.0 libstb.so.0 libglfw.so.3 libX11.so.6 libxcb.so.1 libXau.so.6 \
#            libXdmcp.so.6 libbsd.so.0 libmd.so.0; do cp -L /lib/x86_64-linux-gnu/$l .gl/lib/; done
#   for p in deferred forward; do ./build/oasis render --legend off --pipeline $p --out .gl/ref-$p.png; done
# then run it there with `.gl` carried: OUT=$OUT bash docs/gpu_machine.sh (about 4 minutes on an H100).
set -u
exec > >(tee "$OUT/log.txt") 2>&1
G=$PWD/.gl
for f in "$G"/*.deb; do dpkg -x "$f" /; done; ldconfig   # the GL loaders (glvnd) over NVIDIA's driver
export LD_LIBRARY_PATH=$G/lib OASIS_SHADER_DIR=$PWD/shaders
B="$G/oasis"
s() { echo; echo "=== $* ($(date +%T))"; }
s nvidia; nvidia-smi -L; nvidia-smi --query-gpu=driver_version --format=csv
s caps; timeout 60 "$B" caps
s main job; timeout 60 "$B" --out-dir /tmp/main
s compare; for size in 1280x720 1920x1080 3840x2160; do
  timeout 90 "$B" compare --passes --frames 15 --size $size --out-dir /tmp/c-$size; done
s against llvmpipe; for p in deferred forward; do
  timeout 60 "$B" compare --reference "$G/ref-$p.png" --pipeline $p --out-dir /tmp/ref-$p; done
cp /tmp/ref-deferred/difference.png "$OUT/vs-llvmpipe-deferred-diff.png"
s lights; for m in volumes tiled; do
  timeout 60 "$B" compare --frames 9 --hour 21 --lights 4096 --light-method $m --out-dir /tmp/l-$m | grep -E "ms/frame|lights"; done
s tiers; for t in "--force gl33" "--api gles" "--api gles --force gles30" "--gbuffer full --depth reversed-z"; do
  timeout 60 "$B" compare --frames 9 $t --out-dir /tmp/t | grep -E "PSNR|ms/frame|on "; done
s gpu tests; (cd /tmp && timeout 200 "$G/oasis_gpu_tests" --gtest_brief=1 > "$OUT/gpu-tests.txt" 2>&1; echo "rc=$?")
grep -E "^\[  (FAILED|PASSED) " "$OUT/gpu-tests.txt"
s bench; timeout 200 "$B" bench --out-dir /tmp/bench | tail -70; cp /tmp/bench/bench.csv "$OUT/" 2>/dev/null
s done
