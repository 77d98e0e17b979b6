#!/bin/sh
# Builds the benchmark scene program against Mesa's OSMesa and GLU (see
# run.py). The book scenes (bench/book_*.c) include the C ports of
# c_tests/book and are compiled against the system's (Mesa's) GL headers,
# so that the ports draw into the benchmark's OSMesa context.
set -eu
cd "$(dirname "$0")/.."
mkdir -p build/bench
CC=${CC:-cc}
CFLAGS="-O2 -std=c99 -D_DEFAULT_SOURCE"
objs=""
for f in book_dino book_decal book_winding; do
  $CC $CFLAGS -w -I c_tests -I c_tests/book -c bench/$f.c -o build/bench/$f.o
  objs="$objs build/bench/$f.o"
done
$CC $CFLAGS -w -I c_tests -c c_tests/harness.c -o build/bench/harness.o
$CC $CFLAGS -I include -I bench bench/scenes.c bench/scenes_features.c $objs build/bench/harness.o \
  -o build/bench/bench_scene $(pkg-config --libs osmesa) -lGLU -lm
# The GLU tessellator benchmark: loads softgl and Mesa's libGLU with dlopen (no link-time GL/GLU).
$CC -O2 -std=c99 bench/tess_bench.c -o build/bench/tess_bench -ldl -lm
