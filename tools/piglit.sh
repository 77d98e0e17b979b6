#!/bin/bash
# Runs piglit's GL 1.0-1.5 group against softgl on Xvfb (PIGLIT_PLATFORM=glx,
# libGL.so.1 from build/lib) and summarizes it beside Mesa's baseline.
#
#   tools/piglit.sh [OUT_DIR]          default out/piglit
#   SOFTGL_LIB_DIR=DIR                 the libGL.so.1 to test (default build/lib)
#   GROUP=core|ext|all JOBS=N TIMEOUT=S as ../shared/reference/piglit/run_gl1x.sh
#   PIGLIT_DISPLAY=:N                  use that X server instead of starting Xvfb -noreset
#   ONLY=REGEX                         run only the tests matching REGEX (e.g. '^glx@')
#
# Installs piglit and Xvfb with apt when run as root and they are missing.
# The two tests Mesa itself needs 10+ minutes for are excluded.
set -u
cd "$(dirname "$0")/.."
OUT=${1:-out/piglit}
REF=../shared/reference/piglit
if ! command -v piglit >/dev/null || ! command -v Xvfb >/dev/null; then
  if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null; then
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq piglit xvfb >/dev/null || { echo "piglit: apt-get failed"; exit 1; }
  else
    echo "piglit: piglit or Xvfb missing (run as root to install)"; exit 1
  fi
fi
[ -x "$REF/run_gl1x.sh" ] || { echo "piglit: $REF/run_gl1x.sh not found"; exit 1; }
rm -rf "$OUT" && mkdir -p "$(dirname "$OUT")"
# Our own Xvfb with -noreset: without it the server resets whenever its last
# client disconnects, and a test connecting during the reset fails with
# "XOpenDisplay failed" (what made 11 tests fail at random in earlier runs).
XPID=
if [ -z "${PIGLIT_DISPLAY:-}" ]; then
  for d in 93 92 91 90; do [ -e /tmp/.X11-unix/X$d ] || break; done
  Xvfb :$d -screen 0 1280x1024x24 -nolisten tcp -noreset >/dev/null 2>&1 &
  XPID=$!
  trap '[ -n "$XPID" ] && kill $XPID' EXIT
  for i in $(seq 50); do [ -e /tmp/.X11-unix/X$d ] && break; sleep 0.1; done
  export DISPLAY=:$d
else
  export DISPLAY=$PIGLIT_DISPLAY
fi
if [ -n "${ONLY:-}" ]; then
  LD_LIBRARY_PATH="${SOFTGL_LIB_DIR:-$PWD/build/lib}${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" PIGLIT_PLATFORM=glx \
    piglit run opengl -p glx -j "${JOBS:-$(nproc)}" --timeout "${TIMEOUT:-60}" -l quiet -o -t "$ONLY" "$OUT" >/dev/null
else
  LD_LIBRARY_PATH="${SOFTGL_LIB_DIR:-$PWD/build/lib}${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" \
    TIMEOUT=${TIMEOUT:-60} "$REF/run_gl1x.sh" "$OUT" -x 'gl-1.0-blend-func|texture-env-combine' >/dev/null
fi
python3 "$REF/summarize.py" "$OUT" --list > "$OUT.summary.txt"
head -12 "$OUT.summary.txt"
echo "(Mesa llvmpipe forced to GL 1.5: $(sed -n 3p $REF/baselines/llvmpipe-gl15override-gl1x-core.summary.txt))"
echo "full list: $OUT.summary.txt"
