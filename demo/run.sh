#!/bin/sh
# Renders the demo scenes through softgl into out/demo/*.png.
set -eu
cd "$(dirname "$0")/.."
mkdir -p build/demo out/demo
${CC:-cc} -std=c99 -O2 -Wall -D_DEFAULT_SOURCE -I include demo/scenes.c -o build/demo/scenes \
  -L build/lib -Wl,-rpath,"$PWD/build/lib" -lGL -lGLU -lm
build/demo/scenes build/demo
for f in build/demo/*.pam; do
  name=$(basename "$f" .pam)
  target/release/imgcmp --to-png "$f" "out/demo/$name.png"
  echo "out/demo/$name.png"
done
