#!/usr/bin/env bash
# t_ld_preload: softgl is a drop-in replacement for Mesa's libraries.
#
# A small OSMesa program is compiled against MESA's headers and library
# (pkg-config osmesa) and run three ways:
#   1. as built: Mesa renders (its GL_RENDERER is printed);
#   2. with LD_PRELOAD=$PWD/build/lib/libGL.so.1: softgl's symbols win;
#   3. with LD_LIBRARY_PATH=$PWD/build/lib: the loader finds softgl's
#      libOSMesa.so.8 instead of Mesa's.
# In 2 and 3, GL_RENDERER must contain "softgl" and the pixels (a clear and
# a flat-coloured quad, read straight from the OSMesa buffer) must be right.
# Exit 77 (skip) without pkg-config/osmesa, or without build/lib/libGL.so.1
# (when the suite runs against Mesa only).
set -u
cd "$(dirname "$0")/.." || exit 2
ROOT=$PWD
CC=${CC:-cc}
DIR=build/c_tests/ld_preload

if ! command -v pkg-config >/dev/null 2>&1; then
    echo "SKIP t_ld_preload: pkg-config not installed"
    exit 77
fi
if ! pkg-config --exists osmesa; then
    echo "SKIP t_ld_preload: Mesa's osmesa (pkg-config osmesa) not installed"
    exit 77
fi

mkdir -p "$DIR"
cat >"$DIR/prog.c" <<'PROG'
/* Renders a 16x16 OSMESA_RGBA image: clear to blue, a green quad over
 * [4,12)x[4,12); prints GL_RENDERER; exits 0 iff every pixel is right. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <stdio.h>

int main(void)
{
    static unsigned char buf[16 * 16 * 4];
    int x, y, bad = 0;
    const char *r;
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    if (!ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 16, 16)) {
        printf("could not create/make current an OSMesa context\n");
        return 1;
    }
    r = (const char *)glGetString(GL_RENDERER);
    printf("GL_RENDERER: %s\n", r ? r : "(null)");
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 16, 0, 16, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glShadeModel(GL_FLAT);
    glColor3ub(0, 255, 0);
    glBegin(GL_QUADS);
    glVertex2i(4, 4);
    glVertex2i(12, 4);
    glVertex2i(12, 12);
    glVertex2i(4, 12);
    glEnd();
    glFinish();
    for (y = 0; y < 16; y++)
        for (x = 0; x < 16; x++) {
            const unsigned char *p = &buf[(y * 16 + x) * 4];
            int in = x >= 4 && x < 12 && y >= 4 && y < 12;
            if (p[0] != 0 || p[1] != (in ? 255 : 0) || p[2] != (in ? 0 : 255) || p[3] != 255) {
                if (bad++ < 5)
                    printf("pixel (%d,%d) = %d,%d,%d,%d, expected %s\n", x, y, p[0], p[1], p[2], p[3],
                           in ? "0,255,0,255" : "0,0,255,255");
            }
        }
    if (bad)
        printf("%d wrong pixels\n", bad);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    return bad ? 1 : 0;
}
PROG

# shellcheck disable=SC2046  # pkg-config output is meant to split
if ! $CC -std=c99 -O1 -Wall $(pkg-config --cflags osmesa) -o "$DIR/prog" "$DIR/prog.c" \
    $(pkg-config --libs osmesa) >"$DIR/build.log" 2>&1; then
    cat "$DIR/build.log"
    echo "FAIL t_ld_preload (could not build the program against Mesa)"
    exit 1
fi

fails=0

out=$("$DIR/prog" 2>&1)
rc=$?
echo "  as built (Mesa): $(echo "$out" | head -1)"
if [ $rc -ne 0 ]; then
    echo "$out" | sed 's/^/    /'
    echo "  failure: the program does not render correctly with Mesa itself"
    fails=$((fails + 1))
fi

if [ ! -e build/lib/libGL.so.1 ]; then
    if [ $fails -ne 0 ]; then
        echo "FAIL t_ld_preload ($fails failures)"
        exit 1
    fi
    echo "SKIP t_ld_preload: no build/lib/libGL.so.1 (testing against Mesa only)"
    exit 77
fi

check_softgl() { # label, env assignments...
    local label=$1 out rc
    shift
    out=$(env "$@" "$DIR/prog" 2>&1)
    rc=$?
    echo "  $label: $(echo "$out" | head -1)"
    if ! echo "$out" | head -1 | grep -q softgl; then
        echo "  failure: $label: GL_RENDERER does not contain \"softgl\" (Mesa still in use?)"
        fails=$((fails + 1))
    fi
    if [ $rc -ne 0 ]; then
        echo "$out" | tail -n +2 | sed 's/^/    /'
        echo "  failure: $label: wrong pixels or no context (exit status $rc)"
        fails=$((fails + 1))
    fi
}

check_softgl "LD_PRELOAD=build/lib/libGL.so.1" LD_PRELOAD="$ROOT/build/lib/libGL.so.1"
if [ ! -e build/lib/libOSMesa.so.8 ]; then
    echo "  note: build/lib/libOSMesa.so.8 does not exist; the LD_LIBRARY_PATH run needs it"
fi
check_softgl "LD_LIBRARY_PATH=build/lib" LD_LIBRARY_PATH="$ROOT/build/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"

if [ $fails -ne 0 ]; then
    echo "FAIL t_ld_preload ($fails failures)"
    exit 1
fi
echo "PASS t_ld_preload"
