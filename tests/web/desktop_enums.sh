#!/usr/bin/env bash
# Regenerates src/gl/web_shim/epoxy/desktop_gl_enums.h: every GL_ token the shared sources name that
# emscripten's ES 3 headers lack, with its value from libepoxy's registry header (libepoxy-dev).
set -euo pipefail
cd "$(dirname "$0")/../.."
inc=/usr/share/emscripten/system/include
out=src/gl/web_shim/epoxy/desktop_gl_enums.h
{
    echo "// Desktop GL / KHR_debug tokens the shared sources name and the ES 3 headers lack (values from libepoxy's"
    echo "// registry header), each only where no header defined it; regenerate with tests/web/desktop_enums.sh."
    for name in $(grep -rhoE '\bGL_[A-Z0-9_]+' src passes debug | sort -u); do
        grep -qE "#define $name\b" "$inc/GLES3/gl3.h" "$inc/GLES2/gl2ext.h" "$inc/GLES2/gl2.h" && continue
        value=$(grep -E "#define $name " /usr/include/epoxy/gl_generated.h | awk '{print $3}' | head -1 || true)
        if [ -n "$value" ]; then printf '#ifndef %s\n#define %s %s\n#endif\n' "$name" "$name" "$value"; fi
    done
} > "$out.tmp"
mv "$out.tmp" "$out"
