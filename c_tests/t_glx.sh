#!/usr/bin/env bash
# t_glx: softgl's GLX over Xlib, on an Xvfb of its own.
#
# Builds c_tests/glx_window.c against include/ (-lGL from build/lib, -lX11)
# and runs it on a fresh Xvfb (the first display :90..:99 with no socket or
# lock file; only that Xvfb's PID is killed at the end):
#   1. "visual": glXChooseVisual + glXCreateContext, double-buffered window,
#      clear + triangle, glXSwapBuffers, XGetImage checks; then a resize;
#   2. "fbconfig": glXChooseFBConfig + glXCreateNewContext + glXCreateWindow,
#      single-buffered, shown by glFinish, same checks; then a GLXPixmap;
#   3. when glxgears is installed (mesa-utils), Debian's glxgears runs for
#      2 seconds with LD_LIBRARY_PATH=build/lib: it must report softgl as
#      GL_RENDERER, keep running, and leave non-black pixels on the screen;
#   4. when glxinfo is installed, `glxinfo -B` must report softgl;
#   5. c_tests/glx_drawables.c: MIT-SHM presenting (and XPutImage with
#      SOFTGL_NO_SHM=1), glXCreateContextAttribsARB, share lists (bad
#      handles are GLXBadContext, another screen's context BadMatch: the
#      Xvfb has a second screen for that), a window's visual naming its
#      FBConfig, binned triangles reaching their window across
#      glXMakeCurrent/glXSwapBuffers, several contexts on one window (two
#      threads), a separate read drawable, a pbuffer in two contexts of a
#      share group, a double-buffered GLXPixmap.
#   6. when wflinfo is installed (waffle-utils), `wflinfo -p glx -a gl`
#      must report softgl;
#   7. when freeglut's headers are installed (freeglut3-dev), the freeglut
#      program c_tests/glut_teapot.c, built against the system's GL and
#      GLUT as any program would be, runs on softgl (LD_LIBRARY_PATH): its
#      own pixel checks, a SOFTGL_DUMP frame, and its pixels on the screen.
# Exit 77 (skip) without Xvfb, the Xlib headers or build/lib/libGL.so.1.
set -u
cd "$(dirname "$0")/.." || exit 2
ROOT=$PWD
CC=${CC:-cc}
DIR=build/c_tests/glx

if [ ! -e build/lib/libGL.so.1 ]; then
    echo "SKIP t_glx: no build/lib/libGL.so.1 (testing against Mesa only)"
    exit 77
fi
if ! command -v Xvfb >/dev/null 2>&1; then
    echo "SKIP t_glx: Xvfb not installed (apt-get install xvfb)"
    exit 77
fi
if [ ! -f /usr/include/X11/Xlib.h ]; then
    echo "SKIP t_glx: Xlib headers not installed (apt-get install libx11-dev)"
    exit 77
fi

mkdir -p "$DIR"
if ! $CC -std=c99 -O1 -Wall -I include -o "$DIR/glx_window" c_tests/glx_window.c \
    -L build/lib -Wl,-rpath,"$ROOT/build/lib" -lGL -lX11 >"$DIR/build.log" 2>&1; then
    cat "$DIR/build.log"
    echo "FAIL t_glx (glx_window.c does not compile)"
    exit 1
fi
if [ -s "$DIR/build.log" ]; then cat "$DIR/build.log"; fi
if ! $CC -std=c99 -O1 -Wall -I include -o "$DIR/glx_drawables" c_tests/glx_drawables.c \
    -L build/lib -Wl,-rpath,"$ROOT/build/lib" -lGL -lX11 -lpthread >"$DIR/build2.log" 2>&1; then
    cat "$DIR/build2.log"
    echo "FAIL t_glx (glx_drawables.c does not compile)"
    exit 1
fi

# Our own Xvfb on a free display.
disp=""
for n in 90 91 92 93 94 95 96 97 98 99; do
    if [ ! -e "/tmp/.X11-unix/X$n" ] && [ ! -e "/tmp/.X$n-lock" ]; then
        disp=$n
        break
    fi
done
if [ -z "$disp" ]; then
    echo "SKIP t_glx: no free X display in :90..:99"
    exit 77
fi
Xvfb ":$disp" -screen 0 640x480x24 -screen 1 320x240x24 -br -noreset -nolisten tcp >"$DIR/xvfb.log" 2>&1 &
XPID=$!
GPID=""
cleanup() {
    if [ -n "$GPID" ]; then kill "$GPID" 2>/dev/null; wait "$GPID" 2>/dev/null; fi
    kill "$XPID" 2>/dev/null
    wait "$XPID" 2>/dev/null
}
trap cleanup EXIT
for _ in $(seq 50); do
    [ -e "/tmp/.X11-unix/X$disp" ] && break
    kill -0 "$XPID" 2>/dev/null || break
    sleep 0.1
done
if [ ! -e "/tmp/.X11-unix/X$disp" ]; then
    cat "$DIR/xvfb.log"
    echo "SKIP t_glx: Xvfb :$disp did not start"
    exit 77
fi
export DISPLAY=":$disp"
echo "  Xvfb :$disp (pid $XPID)"

fails=0
for mode in visual fbconfig; do
    out=$(timeout 30 "$DIR/glx_window" "$mode" 2>&1)
    rc=$?
    echo "$out" | sed 's/^/  /'
    if [ $rc -ne 0 ]; then
        echo "  failure: glx_window $mode (exit status $rc)"
        fails=$((fails + 1))
    fi
done

for mode in shm noshm attribs share configs deferred multi read pbuffer pixmap; do
    if [ $mode = noshm ]; then
        out=$(SOFTGL_NO_SHM=1 timeout 30 "$DIR/glx_drawables" shm 2>&1)
    else
        out=$(timeout 30 "$DIR/glx_drawables" $mode 2>&1)
    fi
    rc=$?
    echo "$out" | sed 's/^/  /'
    if [ $rc -ne 0 ]; then
        echo "  failure: glx_drawables $mode (exit status $rc)"
        fails=$((fails + 1))
    fi
done

if command -v glxinfo >/dev/null 2>&1; then
    out=$(LD_LIBRARY_PATH="$ROOT/build/lib" timeout 20 glxinfo -B 2>&1)
    rc=$?
    echo "$out" | grep -E 'direct rendering|renderer string' | sed 's/^/  glxinfo: /'
    if [ $rc -ne 0 ] || ! echo "$out" | grep -q 'renderer string: softgl'; then
        echo "$out" | sed 's/^/    /'
        echo "  failure: glxinfo -B does not report softgl (exit status $rc)"
        fails=$((fails + 1))
    fi
else
    echo "  note: glxinfo not installed (mesa-utils); not run"
fi

if command -v glxgears >/dev/null 2>&1; then
    before=$("$DIR/glx_window" rootcount)
    LD_LIBRARY_PATH="$ROOT/build/lib" stdbuf -oL glxgears -info >"$DIR/glxgears.log" 2>&1 &
    GPID=$!
    sleep 2
    if kill -0 "$GPID" 2>/dev/null; then
        after=$("$DIR/glx_window" rootcount)
        kill "$GPID" 2>/dev/null
        wait "$GPID" 2>/dev/null
        GPID=""
        echo "  glxgears: $(grep GL_RENDERER "$DIR/glxgears.log"); non-black pixels on the screen: $before before, $after while running"
        if ! grep -q 'GL_RENDERER *= softgl' "$DIR/glxgears.log"; then
            echo "  failure: glxgears does not report softgl"
            fails=$((fails + 1))
        fi
        if [ "${after:-0}" -lt 1000 ]; then
            echo "  failure: glxgears drew fewer than 1000 pixels"
            fails=$((fails + 1))
        fi
    else
        wait "$GPID"
        rc=$?
        GPID=""
        sed 's/^/    /' "$DIR/glxgears.log"
        echo "  failure: glxgears exited within 2 seconds (status $rc)"
        fails=$((fails + 1))
    fi
else
    echo "  note: glxgears not installed (mesa-utils); not run"
fi

if command -v wflinfo >/dev/null 2>&1; then
    out=$(LD_LIBRARY_PATH="$ROOT/build/lib" timeout 20 wflinfo -p glx -a gl 2>&1)
    rc=$?
    echo "$out" | grep 'renderer string' | sed 's/^/  wflinfo: /'
    if [ $rc -ne 0 ] || ! echo "$out" | grep -q 'renderer string: softgl'; then
        echo "$out" | sed 's/^/    /'
        echo "  failure: wflinfo does not report softgl (exit status $rc)"
        fails=$((fails + 1))
    fi
else
    echo "  note: wflinfo not installed (waffle-utils); not run"
fi

if [ -f /usr/include/GL/freeglut.h ]; then
    if $CC -std=c99 -O1 -o "$DIR/glut_teapot" c_tests/glut_teapot.c -lglut -lGL >"$DIR/build3.log" 2>&1; then
        rm -rf "$DIR/dump"
        mkdir -p "$DIR/dump"
        before=$("$DIR/glx_window" rootcount)
        LD_LIBRARY_PATH="$ROOT/build/lib" SOFTGL_DUMP="$DIR/dump" timeout 30 "$DIR/glut_teapot" >"$DIR/glut.log" 2>&1 &
        GPID=$!
        sleep 1
        during=$("$DIR/glx_window" rootcount)
        wait "$GPID"
        rc=$?
        GPID=""
        sed 's/^/  glut_teapot: /' "$DIR/glut.log"
        frames=$(ls "$DIR/dump" | grep -c '\.png$')
        echo "  glut_teapot: $frames SOFTGL_DUMP frames; non-background pixels on the screen: $before before, $during while running"
        if [ $rc -ne 0 ] || ! grep -q '^renderer softgl' "$DIR/glut.log"; then
            echo "  failure: glut_teapot (exit status $rc)"
            fails=$((fails + 1))
        fi
        if [ "$frames" -lt 1 ] || [ "${during:-0}" -lt $((${before:-0} + 5000)) ]; then
            echo "  failure: glut_teapot left no dumped frame or too few pixels on the screen"
            fails=$((fails + 1))
        fi
    else
        cat "$DIR/build3.log"
        echo "  failure: glut_teapot.c does not compile against freeglut"
        fails=$((fails + 1))
    fi
else
    echo "  note: freeglut3-dev not installed; glut_teapot not run"
fi

if [ $fails -ne 0 ]; then
    echo "FAIL t_glx ($fails failures)"
    exit 1
fi
echo "PASS t_glx"
