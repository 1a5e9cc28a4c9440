#!/bin/sh
# `oasis caps --json` on one driver set-up must report the fallbacks that set-up really needs.
# usage: caps_setup.sh OASIS XDG_DIR SETUP [oasis caps options] -- REGEX...
# Exits 77 (ctest: Skipped), saying why, when the set-up's driver is not on this machine.
oasis=$1; xdg=$2; setup=$3; shift 3
args=""
while [ $# -gt 0 ] && [ "$1" != "--" ]; do args="$args $1"; shift; done
[ "$1" = "--" ] && shift
case $setup in
  llvmpipe) driver=llvmpipe; json=$("$oasis" caps --json $args) ;;
  zink) driver=zink
    json=$(LIBGL_ALWAYS_SOFTWARE=1 GALLIUM_DRIVER=zink XDG_RUNTIME_DIR=$xdg "$oasis" caps --json $args) ;;
  softpipe) driver=softpipe; json=$(GALLIUM_DRIVER=softpipe "$oasis" caps --json $args) ;;
  no-ssbo-compute) driver=llvmpipe
    json=$(MESA_SHADER_CACHE_DISABLE=true \
           MESA_EXTENSION_OVERRIDE="-GL_ARB_shader_storage_buffer_object -GL_ARB_compute_shader" \
           "$oasis" caps --json $args) ;;
  # ES 3.1 by Mesa's override (--api gles in the options); without gpu_shader5 too (Mesa lists
  # EXT_ and OES_gpu_shader5 behind one flag: removing one removes both; shader cache off).
  gles31) driver=llvmpipe; json=$(MESA_GLES_VERSION_OVERRIDE=3.1 "$oasis" caps --json $args) ;;
  gles31-no-gpu-shader5) driver=llvmpipe
    json=$(MESA_GLES_VERSION_OVERRIDE=3.1 MESA_SHADER_CACHE_DISABLE=true \
           MESA_EXTENSION_OVERRIDE="-GL_EXT_gpu_shader5 -GL_OES_gpu_shader5" "$oasis" caps --json $args) ;;
  # OpenGL ES without 16-bit unorm colour targets (--api gles in the options), as WebGL 2 on SwiftShader.
  gles-no-norm16) driver=llvmpipe
    json=$(MESA_SHADER_CACHE_DISABLE=true MESA_EXTENSION_OVERRIDE=-GL_EXT_texture_norm16 "$oasis" caps --json $args) ;;
  *) echo "unknown set-up $setup"; exit 1 ;;
esac
if [ -z "$json" ]; then
  [ "$setup" = zink ] && { echo "SKIPPED: zink is not available here (no context; mesa-vulkan-drivers missing?)"; exit 77; }
  echo "oasis caps failed on $setup"; exit 1
fi
case $json in
  *"\"renderer\": \"$driver"*) ;;
  *) echo "SKIPPED: driver set-up $setup is not available here: $json"; exit 77 ;;
esac
echo "$json"
status=0
for pattern in "$@"; do
  echo "$json" | grep -qE -- "$pattern" || { echo "MISSING on $setup: $pattern"; status=1; }
done
exit $status
