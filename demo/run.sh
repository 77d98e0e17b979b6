#!/bin/sh
# Renders the demo scenes through softgl into out/demo/*.png, runs the C
# ports of the books' programs (c_tests/book/, with their pixel checks;
# images into out/book/*.png) and writes the gallery out/index.html.
# Exits non-zero if a book program fails its checks (after the gallery).
set -eu
cd "$(dirname "$0")/.."
mkdir -p build/demo out/demo out/book
${CC:-cc} -std=c99 -O2 -Wall -D_DEFAULT_SOURCE -I include demo/scenes.c -o build/demo/scenes \
  -L build/lib -Wl,-rpath,"$PWD/build/lib" -lGL -lGLU -lm
build/demo/scenes build/demo
for f in build/demo/*.pam; do
  name=$(basename "$f" .pam)
  target/release/imgcmp --to-png "$f" "out/demo/$name.png"
  echo "out/demo/$name.png"
done

# The books' programs: rendered (goldens are compared by `make test`).
rm -rf build/demo/book-out
status=0
SOFTGL_TEST_OUT=build/demo/book-out BOOK_NO_GOLDEN=1 bash c_tests/run.sh t_book_ \
  >build/demo/book.log 2>&1 || status=$?
grep -E '^(PASS|FAIL|SKIP)|passed' build/demo/book.log || true
for f in build/demo/book-out/book/*.pam; do
  target/release/imgcmp --to-png "$f" "out/book/$(basename "$f" .pam).png"
done
python3 demo/gallery.py out build/demo/book.log
exit $status
