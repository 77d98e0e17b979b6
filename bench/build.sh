#!/bin/sh
# Builds the benchmark scene program against Mesa's OSMesa (see run.py).
set -eu
cd "$(dirname "$0")/.."
mkdir -p build/bench
${CC:-cc} -O2 -std=c99 -D_DEFAULT_SOURCE -I include bench/scenes.c -o build/bench/bench_scene $(pkg-config --libs osmesa) -lm
# The GLU tessellator benchmark: loads softgl and Mesa's libGLU with dlopen (no link-time GL/GLU).
${CC:-cc} -O2 -std=c99 bench/tess_bench.c -o build/bench/tess_bench -ldl -lm
