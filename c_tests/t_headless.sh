#!/usr/bin/env bash
# t_headless: unmodified X11 programs with no X server, through softgl's
# headless X client libraries (build/headless, headless/README.md): DISPLAY
# is unset and LD_LIBRARY_PATH=build/headless:build/lib, so programs get the
# stand-in libX11 (and libXext, libXi, libXxf86vm) and softgl's libGL.
#   0. every X function glxgears, glxinfo, glxdemo, libglut and softgl's
#      GLX use is exported by the stand-ins (nm);
#   1. c_tests/headless_xlib.c (built against the system's Xlib headers and
#      -lX11): the stand-in's Display layout, events, atoms, properties,
#      errors and images, and a GLX frame read back from its window; then
#      SOFTGL_EXIT_AFTER_FRAMES=5 ends it presenting (glXSwapBuffers, and
#      glFlush single-buffered) with its atexit handler still calling GLX;
#   2. glxgears as shipped, with SOFTGL_DUMP and SOFTGL_EXIT_AFTER_FRAMES:
#      it must report softgl, exit 0 by itself after exactly that many
#      frames, spin (first and last frames differ) and show red, green and
#      blue lit gears on black in plausible proportions;
#   3. the freeglut program c_tests/glut_teapot.c (glutSolidTeapot,
#      glutBitmapCharacter; its own pixel checks on every frame, exit after
#      1.5 s): frames that change, a lit red teapot on the clear colour in
#      the middle, yellow text in the bottom rows;
#   4. clean failures: glxgears -stereo (no stereo visual) exits with its
#      error message, wflinfo (waffle needs an XCB connection) with
#      waffle's, and a program calling an Xlib function the stand-in lacks
#      stops with the dynamic loader's "symbol lookup error"; never a
#      signal.
# Exit 77 (skip) without build/headless/libX11.so.6 (make headless needs
# the Xlib headers) or build/lib/libGL.so.1.
set -u
cd "$(dirname "$0")/.." || exit 2
ROOT=$PWD
CC=${CC:-cc}
DIR=build/c_tests/headless
IMGCMP=target/release/imgcmp
LIBS="$ROOT/build/headless:$ROOT/build/lib"

if [ ! -e build/lib/libGL.so.1 ]; then
    echo "SKIP t_headless: no build/lib/libGL.so.1"
    exit 77
fi
if [ ! -e build/headless/libX11.so.6 ]; then
    echo "SKIP t_headless: no build/headless/libX11.so.6 (make headless; needs libx11-dev, libxext-dev)"
    exit 77
fi
if ! [ -x "$IMGCMP" ]; then
    echo "FAIL t_headless: $IMGCMP not built (make lib builds the workspace)"
    exit 1
fi
mkdir -p "$DIR"
fails=0

# run NAME ENV... -- CMD...: runs CMD with no X display through the stand-in
# (30 s at most), its output in $DIR/NAME.log; sets RC.
run() {
    local name=$1
    shift
    env -u DISPLAY -u WAYLAND_DISPLAY LD_LIBRARY_PATH="$LIBS" "$@" >"$DIR/$name.log" 2>&1
    RC=$?
}
# in_range NAME VALUE LO HI: a failure unless LO <= VALUE <= HI.
in_range() {
    if [ "$2" -lt "$3" ] || [ "$2" -gt "$4" ]; then
        echo "  failure: $1 is $2, expected $3..$4"
        fails=$((fails + 1))
    fi
}
# stats IMG [X Y W H]: sets W H DARK RED GREEN BLUE OTHER R0 R1 G0 G1 B0 B1.
stats() {
    local out
    out=$("$IMGCMP" --stats "$@") || out="0x0 dark 0 red 0 green 0 blue 0 other 0 levels 0 0 0 0 0 0"
    set -- $out
    W=${1%x*} H=${1#*x} DARK=$3 RED=$5 GREEN=$7 BLUE=$9 OTHER=${11} R0=${13} R1=${14} G0=${15} G1=${16} B0=${17} B1=${18}
}

# 0. Every X function the programs (and libglut) import, and every one
# softgl's GLX looks up (src/winsys/glx/xlib.rs), is exported by the
# stand-ins: a missing one would stop the program at its first call.
if command -v nm >/dev/null 2>&1; then
    nm -D --defined-only build/headless/*.so* | awk '{print $3}' | sort -u >"$DIR/have.txt"
    {
        for p in glxgears glxinfo glxdemo; do
            command -v $p >/dev/null 2>&1 && nm -D --undefined-only "$(command -v $p)"
        done
        for l in /usr/lib/x86_64-linux-gnu/libglut.so.3*; do
            [ -f "$l" ] && [ ! -L "$l" ] && nm -D --undefined-only "$l"
        done
        sed -n 's/.*b"\(X[A-Za-z0-9]*\)\\0".*/ U \1/p' src/winsys/glx/xlib.rs
    } | awk '$1 == "U" {print $2}' | grep '^X' | sort -u >"$DIR/need.txt"
    missing=$(comm -23 "$DIR/need.txt" "$DIR/have.txt" | tr '\n' ' ')
    echo "  exports: $(wc -l <"$DIR/need.txt") X functions needed, ${missing:-none} missing"
    if [ -n "$missing" ] || [ "$(wc -l <"$DIR/need.txt")" -lt 40 ]; then
        echo "  failure: the stand-ins lack $missing"
        fails=$((fails + 1))
    fi
fi

# 1. The stand-in itself.
if [ -f /usr/include/X11/Xlib.h ] && $CC -std=c99 -O1 -Wall -I include -o "$DIR/headless_xlib" c_tests/headless_xlib.c \
    -L build/lib -lGL -lX11 -ldl >"$DIR/build.log" 2>&1; then
    run headless_xlib SOFTGL_HEADLESS_SCREEN=800x600 timeout 30 "$DIR/headless_xlib"
    sed 's/^/  headless_xlib: /' "$DIR/headless_xlib.log"
    if [ $RC -ne 0 ]; then
        echo "  failure: headless_xlib (exit status $RC)"
        fails=$((fails + 1))
    fi
    # SOFTGL_EXIT_AFTER_FRAMES=5: the process exits 0 in the 5th
    # presenting call (glXSwapBuffers, or glFlush single-buffered), and the
    # program's atexit handler (which calls GLX) runs; 5 frames dumped.
    for mode in double single; do
        rm -rf "$DIR/exit-$mode"
        run exit-$mode SOFTGL_DUMP="$DIR/exit-$mode" SOFTGL_EXIT_AFTER_FRAMES=5 timeout 30 "$DIR/headless_xlib" exit $mode
        frames=$(ls "$DIR/exit-$mode" 2>/dev/null | grep -c '^frame-0000[0-4]\.png$')
        echo "  SOFTGL_EXIT_AFTER_FRAMES=5, $mode-buffered: exit status $RC, $(tr '\n' ' ' <"$DIR/exit-$mode.log")"
        if [ $RC -ne 0 ] || ! grep -qx 'atexit after 5 frames' "$DIR/exit-$mode.log" || [ "$frames" -ne 5 ]; then
            echo "  failure: SOFTGL_EXIT_AFTER_FRAMES=5 ($mode-buffered): status $RC, $frames of frames 0-4 dumped"
            fails=$((fails + 1))
        fi
    done
else
    cat "$DIR/build.log"
    echo "  failure: headless_xlib.c does not compile"
    fails=$((fails + 1))
fi

# 2. glxgears, stopped by SOFTGL_EXIT_AFTER_FRAMES.
if command -v glxgears >/dev/null 2>&1; then
    N=40
    rm -rf "$DIR/gears"
    run glxgears SOFTGL_DUMP="$DIR/gears" SOFTGL_EXIT_AFTER_FRAMES=$N timeout 60 glxgears -info
    frames=$(ls "$DIR/gears" 2>/dev/null | grep -c '^frame-.*\.png$')
    echo "  glxgears: exit status $RC, $(grep -m1 GL_RENDERER "$DIR/glxgears.log"); $frames frames"
    if [ $RC -ne 0 ] || ! grep -q 'GL_RENDERER *= softgl' "$DIR/glxgears.log"; then
        sed 's/^/    /' "$DIR/glxgears.log" | head -20
        echo "  failure: glxgears did not run on softgl and exit 0 by itself"
        fails=$((fails + 1))
    fi
    in_range "glxgears' frame count (SOFTGL_EXIT_AFTER_FRAMES=$N)" "$frames" $N $N
    first="$DIR/gears/frame-00000.png"
    last="$DIR/gears/$(ls "$DIR/gears" 2>/dev/null | grep '^frame-' | tail -1)"
    if [ "$frames" -ge 2 ] && "$IMGCMP" "$last" "$first" --tol 0 >/dev/null 2>&1; then
        echo "  failure: glxgears' first and last frames are the same (not spinning)"
        fails=$((fails + 1))
    fi
    stats "$last"
    echo "  glxgears: last frame $W x $H: dark $DARK red $RED green $GREEN blue $BLUE other $OTHER; shades red $R0..$R1 green $G0..$G1 blue $B0..$B1"
    px=$((W * H))
    if [ "$px" -eq 0 ]; then
        echo "  failure: glxgears' last frame cannot be read"
        fails=$((fails + 1))
    else
        in_range "glxgears' width" "$W" 300 300
        in_range "glxgears' dark %" $((DARK * 100 / px)) 50 90
        in_range "glxgears' red %" $((RED * 100 / px)) 8 35
        in_range "glxgears' green %" $((GREEN * 100 / px)) 2 15
        in_range "glxgears' blue %" $((BLUE * 100 / px)) 2 15
        in_range "glxgears' other %" $((OTHER * 100 / px)) 0 5
        in_range "glxgears' red shades" $((R1 - R0)) 60 255
        in_range "glxgears' green shades" $((G1 - G0)) 60 255
        in_range "glxgears' blue shades" $((B1 - B0)) 60 255
        # Where the gears are (glxgears' layout): the big red one lower
        # left, the green one lower right, the blue one at the top left;
        # each region mostly its own colour and none of the others'.
        stats "$last" 0 150 150 150
        in_range "glxgears' red % in the lower left quarter" $((RED * 100 / (150 * 150))) 40 75
        in_range "glxgears' green + blue pixels in the lower left quarter" $((GREEN + BLUE)) 0 0
        stats "$last" 150 150 150 150
        in_range "glxgears' green % in the lower right quarter" $((GREEN * 100 / (150 * 150))) 8 30
        in_range "glxgears' blue pixels in the lower right quarter" "$BLUE" 0 0
        stats "$last" 40 20 110 110
        in_range "glxgears' blue % at the top left" $((BLUE * 100 / (110 * 110))) 15 50
        in_range "glxgears' green pixels at the top left" "$GREEN" 0 0
    fi

    # 4a. A visual the stand-in and softgl do not have: a clean error.
    run glxgears-stereo timeout 30 glxgears -stereo
    echo "  glxgears -stereo: exit status $RC: $(head -1 "$DIR/glxgears-stereo.log")"
    if [ $RC -eq 0 ] || [ $RC -ge 124 ] || ! grep -qi 'stereo' "$DIR/glxgears-stereo.log"; then
        echo "  failure: glxgears -stereo should fail cleanly for want of a stereo visual"
        fails=$((fails + 1))
    fi
else
    echo "  note: glxgears not installed (mesa-utils); not run"
fi

# 3. A freeglut program.
if [ -f /usr/include/GL/freeglut.h ]; then
    if $CC -std=c99 -O1 -o "$DIR/glut_teapot" c_tests/glut_teapot.c -lglut -lGL >"$DIR/build3.log" 2>&1; then
        rm -rf "$DIR/teapot"
        run glut_teapot SOFTGL_DUMP="$DIR/teapot" timeout 30 "$DIR/glut_teapot"
        sed 's/^/  glut_teapot: /' "$DIR/glut_teapot.log"
        frames=$(ls "$DIR/teapot" 2>/dev/null | grep -c '^frame-.*\.png$')
        echo "  glut_teapot: exit status $RC, $frames frames"
        if [ $RC -ne 0 ] || ! grep -q '^renderer softgl' "$DIR/glut_teapot.log"; then
            echo "  failure: glut_teapot (exit status $RC)"
            fails=$((fails + 1))
        fi
        in_range "glut_teapot's frame count" "$frames" 5 1000
        first="$DIR/teapot/frame-00000.png"
        last="$DIR/teapot/$(ls "$DIR/teapot" 2>/dev/null | grep '^frame-' | tail -1)"
        if [ "$frames" -ge 2 ] && "$IMGCMP" "$last" "$first" --tol 0 >/dev/null 2>&1; then
            echo "  failure: glut_teapot's first and last frames are the same (not spinning)"
            fails=$((fails + 1))
        fi
        # The whole frame: the teapot lit red on the dark blue clear colour.
        stats "$last"
        echo "  glut_teapot: last frame $W x $H: red $RED blue $BLUE other $OTHER; red shades $R0..$R1"
        px=$((W * H))
        in_range "glut_teapot's width" "$W" 240 240
        in_range "glut_teapot's red %" $((RED * 100 / (px + 1))) 10 40
        in_range "glut_teapot's blue (clear colour) %" $((BLUE * 100 / (px + 1))) 50 90
        in_range "glut_teapot's red shades" $((R1 - R0)) 60 255
        # The middle 60x60 is teapot; the bottom 24 rows hold the yellow
        # text (counted as "other") on the clear colour.
        stats "$last" 90 90 60 60
        in_range "glut_teapot's red % in the middle" $((RED * 100 / 3600)) 90 100
        stats "$last" 0 216 240 24
        in_range "glut_teapot's text pixels in the bottom rows" "$OTHER" 60 2000
        in_range "glut_teapot's red pixels in the bottom rows" "$RED" 0 0
    else
        cat "$DIR/build3.log"
        echo "  failure: glut_teapot.c does not compile against freeglut"
        fails=$((fails + 1))
    fi
else
    echo "  note: freeglut3-dev not installed; glut_teapot not run"
fi

# 4c. waffle (wflinfo) wants the XCB connection under Xlib, which the
# headless display does not have: libX11-xcb's stand-in says so and waffle
# reports it (the real libX11-xcb would read Xlib's private fields: a crash).
if command -v wflinfo >/dev/null 2>&1; then
    run wflinfo timeout 30 wflinfo -p glx -a gl
    echo "  wflinfo: exit status $RC: $(head -1 "$DIR/wflinfo.log")"
    if [ $RC -eq 0 ] || [ $RC -ge 124 ] || ! grep -q 'XGetXCBConnection' "$DIR/wflinfo.log"; then
        echo "  failure: wflinfo should fail cleanly for want of an XCB connection"
        fails=$((fails + 1))
    fi
else
    echo "  note: wflinfo not installed (waffle-utils); not run"
fi

# 4b. An Xlib function the stand-in does not have (XkbGetMap): the dynamic
# loader stops the program when it is called, with status 127.
cat >"$DIR/missing.c" <<'EOF'
#include <X11/XKBlib.h>
#include <stdio.h>
int main(void)
{
    Display *dpy = XOpenDisplay(NULL);
    printf("display %s\n", dpy ? "opened" : "none");
    fflush(stdout);
    XkbDescPtr k = dpy ? XkbGetMap(dpy, XkbAllClientInfoMask, XkbUseCoreKbd) : NULL;
    printf("keyboard map %p\n", (void *)k);
    return 0;
}
EOF
if $CC -std=c99 -O1 -Wl,-z,lazy -o "$DIR/missing" "$DIR/missing.c" -lX11 >"$DIR/build4.log" 2>&1; then
    run missing timeout 30 "$DIR/missing"
    echo "  missing symbol: exit status $RC: $(tr '\n' ' ' <"$DIR/missing.log")"
    if [ $RC -ne 127 ] || ! grep -q 'display opened' "$DIR/missing.log" || ! grep -q 'symbol lookup error.*XkbGetMap' "$DIR/missing.log"; then
        echo "  failure: a missing Xlib function should stop the program with the loader's error (127)"
        fails=$((fails + 1))
    fi
else
    cat "$DIR/build4.log"
    echo "  failure: missing.c does not compile"
    fails=$((fails + 1))
fi

if [ $fails -ne 0 ]; then
    echo "FAIL t_headless ($fails failures)"
    exit 1
fi
echo "PASS t_headless"
