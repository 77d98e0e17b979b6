#!/usr/bin/env bash
# Cross-check the book ports against Mesa: build each c_tests/book/t_book_*.c
# against Mesa's OSMesa and GLU (softpipe; the ports fall back from the wgl
# shim to OSMesa there), run them with their pixel checks, and print the
# RMSE (per channel, 0-255) of every image against softgl's render of it in
# $SOFTGL_TEST_OUT/book (run `bash c_tests/run.sh t_book_` first).
#
#   c_tests/book/crosscheck.sh [FILTER]
set -u
cd "$(dirname "$0")/../.." || exit 2
OUT=${SOFTGL_TEST_OUT:-out/c_tests}
MESA_OUT=out/book-mesa
mkdir -p build/book-mesa "$MESA_OUT"
status=0
for src in c_tests/book/t_book_*"${1:-}"*.c; do
    name=$(basename "$src" .c)
    if ! cc -std=c99 -O1 -I/usr/include -I c_tests -o "build/book-mesa/$name" "$src" c_tests/harness.c \
        -lOSMesa -lGLU -lm 2>"build/book-mesa/$name.build.log"; then
        echo "FAIL $name (does not build against Mesa)"; status=1; continue
    fi
    GALLIUM_DRIVER=softpipe BOOK_NO_GOLDEN=1 SOFTGL_TEST_OUT=$MESA_OUT "build/book-mesa/$name" \
        >"build/book-mesa/$name.log" 2>&1
    rc=$?
    tail -1 "build/book-mesa/$name.log"
    [ $rc -eq 0 ] || [ $rc -eq 77 ] || status=1
done
python3 - "$OUT/book" "$MESA_OUT/book" <<'PY'
import glob, math, os, sys
def load(p):
    d = open(p, 'rb').read(); i = d.index(b'ENDHDR\n') + 7
    h = dict(l.split(b' ', 1) for l in d[:i].split(b'\n')[1:-2])
    return int(h[b'WIDTH']), int(h[b'HEIGHT']), d[i:]
print('| image | RMSE | pixels off by more than 2 |')
print('| --- | --- | --- |')
for a in sorted(glob.glob(sys.argv[1] + '/*.pam')):
    b = os.path.join(sys.argv[2], os.path.basename(a))
    n = os.path.basename(a)[:-4]
    if not os.path.exists(b):
        print('| %s | (no Mesa image) | |' % n); continue
    w, h, pa = load(a); w2, h2, pb = load(b)
    if (w, h) != (w2, h2):
        print('| %s | size differs | |' % n); continue
    s = 0; bad = 0
    for i in range(0, len(pa), 4):
        d = [abs(pa[i + k] - pb[i + k]) for k in range(3)]
        bad += max(d) > 2
        s += sum(x * x for x in d)
    print('| %s | %.2f | %d (%.2f%%) |' % (n, math.sqrt(s / (w * h * 3)), bad, 100.0 * bad / (w * h)))
PY
exit $status
