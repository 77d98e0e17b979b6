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
#      2 seconds with LD_LIBRARY_PATH=build/lib and SOFTGL_DUMP: it must
#      report softgl as GL_RENDERER and keep running; its frames must
#      change (spin), the last one must have red, green and blue gears in
#      plausible proportions, each in a range of shades (lit), on black;
#      and its window on an X screenshot (glx_window screenshot, XGetImage
#      of the root) must equal one of its last dumped frames (imgcmp --crop);
#   4. when glxinfo is installed, `glxinfo -B` must report softgl;
#   5. c_tests/glx_drawables.c: MIT-SHM presenting (and XPutImage with
#      SOFTGL_NO_SHM=1), glXCreateContextAttribsARB, share lists (bad
#      handles are GLXBadContext, another screen's context BadMatch: the
#      Xvfb has a second screen for that), a window's visual naming its
#      FBConfig, binned triangles reaching their window across
#      glXMakeCurrent/glXSwapBuffers, several contexts on one window (two
#      threads), a separate read drawable, a pbuffer in two contexts of a
#      share group, a double-buffered GLXPixmap, swap control
#      (EXT/MESA/SGI) and glXCopySubBufferMESA.
#   6. when wflinfo is installed (waffle-utils), `wflinfo -p glx -a gl`
#      must report softgl;
#   7. when freeglut's headers are installed (freeglut3-dev), the freeglut
#      program c_tests/glut_teapot.c (a spinning lit teapot and
#      glutBitmapCharacter text), built against the system's GL and GLUT
#      as any program would be, runs on softgl (LD_LIBRARY_PATH): its own
#      pixel checks on every frame, SOFTGL_DUMP frames that change, and
#      its window on an X screenshot equal to one of them, lit red on the
#      clear colour.
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
    if [ -n "$GPID" ]; then kill "$GPID" 2>/dev/null; kill -CONT "$GPID" 2>/dev/null; wait "$GPID" 2>/dev/null; fi
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

for mode in shm noshm attribs share bind configs rgb deferred multi read pbuffer pixmap swap; do
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

IMGCMP=target/release/imgcmp
# frame_on_screen SCREEN.ppm X Y FRAME...: the first FRAME (PNG) equal to
# the rectangle of the screenshot at (X, Y) (within 1 per channel), or
# nothing.
frame_on_screen() {
    local shot=$1 x=$2 y=$3 f
    shift 3
    for f in "$@"; do
        if "$IMGCMP" "$shot" "$f" --crop "$x" "$y" --tol 1 >/dev/null 2>&1; then
            echo "$f"
            return
        fi
    done
}
# in_range NAME VALUE LO HI: a failure unless LO <= VALUE <= HI.
in_range() {
    if [ "$2" -lt "$3" ] || [ "$2" -gt "$4" ]; then
        echo "  failure: $1 is $2, expected $3..$4"
        fails=$((fails + 1))
    fi
}
# stats IMG [X Y W H]: sets W H DARK RED GREEN BLUE OTHER R0 R1 G0 G1 B0 B1
# from imgcmp --stats.
stats() {
    local out
    out=$("$IMGCMP" --stats "$@") || out="0x0 dark 0 red 0 green 0 blue 0 other 0 levels 0 0 0 0 0 0"
    set -- $out
    W=${1%x*} H=${1#*x} DARK=$3 RED=$5 GREEN=$7 BLUE=$9 OTHER=${11} R0=${13} R1=${14} G0=${15} G1=${16} B0=${17} B1=${18}
}

if ! [ -x "$IMGCMP" ]; then
    echo "  failure: $IMGCMP not built (make lib builds the workspace)"
    fails=$((fails + 1))
elif command -v glxgears >/dev/null 2>&1; then
    # glxgears as shipped (built against Mesa/GLVND), on softgl: it runs for
    # 2 seconds writing every frame (SOFTGL_DUMP); then it is stopped, the
    # X screen is grabbed, and it is ended.
    rm -rf "$DIR/gears"
    mkdir -p "$DIR/gears"
    LD_LIBRARY_PATH="$ROOT/build/lib" SOFTGL_DUMP="$DIR/gears" stdbuf -oL glxgears -info >"$DIR/glxgears.log" 2>&1 &
    GPID=$!
    sleep 2
    if kill -STOP "$GPID" 2>/dev/null; then
        shot=$("$DIR/glx_window" screenshot "$DIR/gears-screen.ppm")
        kill -TERM "$GPID" 2>/dev/null
        kill -CONT "$GPID" 2>/dev/null
        wait "$GPID" 2>/dev/null
        GPID=""
        frames=$(ls "$DIR/gears" | grep -c '^frame-.*\.png$')
        first="$DIR/gears/frame-00000.png"
        # The newest frame may have been cut short by the kill: the one
        # before it is whole.
        last="$DIR/gears/$(ls "$DIR/gears" | grep '^frame-' | tail -2 | head -1)"
        echo "  glxgears: $(grep GL_RENDERER "$DIR/glxgears.log"); $frames SOFTGL_DUMP frames in 2 s; on the screen: $shot"
        if ! grep -q 'GL_RENDERER *= softgl' "$DIR/glxgears.log"; then
            echo "  failure: glxgears does not report softgl"
            fails=$((fails + 1))
        fi
        in_range "glxgears' frame count" "$frames" 10 1000000
        # Spinning: the last frame is not the first.
        if [ "$frames" -ge 2 ] && "$IMGCMP" "$last" "$first" --tol 0 >/dev/null 2>&1; then
            echo "  failure: glxgears' first and last frames are the same (not spinning)"
            fails=$((fails + 1))
        fi
        # The gears: red, green and blue, lit (each spans a range of
        # shades), on black; fractions of the frame in per cent.
        stats "$last"
        echo "  glxgears: last frame $W x $H: dark $DARK red $RED green $GREEN blue $BLUE other $OTHER; shades red $R0..$R1 green $G0..$G1 blue $B0..$B1"
        px=$((W * H))
        if [ "$px" -eq 0 ]; then
            echo "  failure: glxgears' last frame cannot be read"
            fails=$((fails + 1))
        else
            in_range "glxgears' dark %" $((DARK * 100 / px)) 50 90
            in_range "glxgears' red %" $((RED * 100 / px)) 8 35
            in_range "glxgears' green %" $((GREEN * 100 / px)) 2 15
            in_range "glxgears' blue %" $((BLUE * 100 / px)) 2 15
            in_range "glxgears' other %" $((OTHER * 100 / px)) 0 5
            in_range "glxgears' red shades" $((R1 - R0)) 60 255
            in_range "glxgears' green shades" $((G1 - G0)) 60 255
            in_range "glxgears' blue shades" $((B1 - B0)) 60 255
        fi
        # The window on the X screen shows one of the last frames dumped
        # (a frame is written just before it is put on the screen).
        set -- $shot
        if [ "${1:-}" != window ] || [ "${2:-none}" = none ] || [ "${4:-0}" != "$W" ] || [ "${5:-0}" != "$H" ]; then
            echo "  failure: no ${W}x$H window on the X screen ($shot)"
            fails=$((fails + 1))
        else
            recent=$(ls "$DIR/gears" | grep '^frame-' | tail -3 | sort -r | sed "s|^|$DIR/gears/|")
            on=$(frame_on_screen "$DIR/gears-screen.ppm" "$2" "$3" $recent)
            echo "  glxgears: the window at ($2,$3) on the X screen shows ${on:-none of the last 3 frames}"
            if [ -z "$on" ]; then
                "$IMGCMP" "$DIR/gears-screen.ppm" "$last" --crop "$2" "$3" --tol 1
                echo "  failure: glxgears' window on the X screen is not one of its last frames"
                fails=$((fails + 1))
            fi
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
        # A spinning lit teapot with text, from an unmodified freeglut
        # program (its own checks on every frame, exit after 1.5 s); the X
        # screen is grabbed after 1 second (each frame reaches the window
        # in one request, so the grab shows a whole frame).
        rm -rf "$DIR/dump"
        mkdir -p "$DIR/dump"
        LD_LIBRARY_PATH="$ROOT/build/lib" SOFTGL_DUMP="$DIR/dump" timeout 30 "$DIR/glut_teapot" >"$DIR/glut.log" 2>&1 &
        GPID=$!
        sleep 1
        shot=$("$DIR/glx_window" screenshot "$DIR/glut-screen.ppm")
        wait "$GPID"
        rc=$?
        GPID=""
        sed 's/^/  glut_teapot: /' "$DIR/glut.log"
        frames=$(ls "$DIR/dump" | grep -c '^frame-.*\.png$')
        echo "  glut_teapot: $frames SOFTGL_DUMP frames; on the screen: $shot"
        if [ $rc -ne 0 ] || ! grep -q '^renderer softgl' "$DIR/glut.log"; then
            echo "  failure: glut_teapot (exit status $rc)"
            fails=$((fails + 1))
        fi
        in_range "glut_teapot's frame count" "$frames" 5 1000
        first="$DIR/dump/frame-00000.png"
        last="$DIR/dump/$(ls "$DIR/dump" | grep '^frame-' | tail -1)"
        if [ "$frames" -ge 2 ] && "$IMGCMP" "$last" "$first" --tol 0 >/dev/null 2>&1; then
            echo "  failure: glut_teapot's first and last frames are the same (not spinning)"
            fails=$((fails + 1))
        fi
        set -- $shot
        if [ "${1:-}" != window ] || [ "${2:-none}" = none ]; then
            echo "  failure: no glut_teapot window on the X screen ($shot)"
            fails=$((fails + 1))
        else
            on=$(frame_on_screen "$DIR/glut-screen.ppm" "$2" "$3" $(ls "$DIR/dump" | grep '^frame-' | sort -r | sed "s|^|$DIR/dump/|"))
            echo "  glut_teapot: the window at ($2,$3) on the X screen shows ${on:-none of its frames}"
            if [ -z "$on" ]; then
                echo "  failure: glut_teapot's window on the X screen is not one of its frames"
                fails=$((fails + 1))
            else
                # The frame on the screen: the red teapot, lit (a range of
                # shades), on the dark blue clear colour.
                stats "$DIR/glut-screen.ppm" "$2" "$3" "$4" "$5"
                echo "  glut_teapot: on the screen $W x $H: red $RED blue $BLUE other $OTHER; red shades $R0..$R1"
                px=$((W * H))
                in_range "glut_teapot's red % on the screen" $((RED * 100 / (px + 1))) 10 40
                in_range "glut_teapot's blue (clear colour) % on the screen" $((BLUE * 100 / (px + 1))) 50 90
                in_range "glut_teapot's red shades on the screen" $((R1 - R0)) 60 255
            fi
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
