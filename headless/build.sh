#!/bin/sh
# Builds softgl's headless X client libraries into build/headless/ (see
# headless/README.md): libX11.so.6, libXext.so.6, libXi.so.6,
# libXxf86vm.so.1 and libX11-xcb.so.1, each with its real SONAME so that programs and
# libraries linked against the real ones load these instead when
# build/headless is on LD_LIBRARY_PATH. Needs the Xlib headers
# (libx11-dev, libxext-dev); without them it says so and builds nothing.
set -eu
cd "$(dirname "$0")/.."
CC=${CC:-cc}
OUT=build/headless
if [ ! -f /usr/include/X11/Xlib.h ] || [ ! -f /usr/include/X11/extensions/XShm.h ]; then
    echo "headless: no Xlib headers (apt-get install libx11-dev libxext-dev): not built"
    exit 0
fi
mkdir -p "$OUT"
build() { # soname sources...
    so=$1
    shift
    # Only the X API is exported; -z defs: every symbol it uses is resolved.
    $CC -std=c11 -O2 -g -Wall -Wextra -Werror -fPIC -shared -fvisibility=hidden \
        -Wl,-soname,"$so" -Wl,-z,defs -o "$OUT/$so.tmp" "$@" -lpthread
    mv -f "$OUT/$so.tmp" "$OUT/$so"
}
build libX11.so.6 headless/x11.c
build libXext.so.6 headless/xext.c
build libXi.so.6 headless/xi.c
build libXxf86vm.so.1 headless/xxf86vm.c
build libX11-xcb.so.1 headless/x11xcb.c
