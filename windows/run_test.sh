#!/bin/bash
# Builds opengl32.dll and glu32.dll (windows/build.sh) and runs
# windows/wgl_window.c against them under Wine on a private Xvfb.
# Installs wine64 when missing (as root). Exit 77 (skipped) when the
# Windows toolchain or Wine is not available.
set -u
cd "$(dirname "$0")/.."
OUT=build/windows
bash windows/build.sh
rc=$?
[ $rc -eq 0 ] || exit $rc
if ! command -v wine >/dev/null 2>&1 && ! command -v wine64 >/dev/null 2>&1 && [ ! -x /usr/lib/wine/wine64 ]; then
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
        DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends wine64 >/dev/null 2>&1
    fi
fi
WINE=$(command -v wine64 || command -v wine || ls /usr/lib/wine/wine64 2>/dev/null) || { echo "windows/run_test.sh: no wine"; exit 77; }
x86_64-w64-mingw32-gcc -O1 -Wall -I include -o "$OUT/wgl_window.exe" windows/wgl_window.c -lopengl32 -lglu32 -lgdi32 -luser32 || exit 1
# Wine 8 has no bcryptprimitives.dll (see the stub's comment).
x86_64-w64-mingw32-gcc -shared -O1 -s -o "$OUT/bcryptprimitives.dll" windows/bcryptprimitives_stub.c -ladvapi32 || exit 1
export WINEPREFIX=${WINEPREFIX:-/tmp/softgl-wineprefix}
export WINEDEBUG=-all
# Native (softgl's) opengl32 and glu32 from the program's directory.
export WINEDLLOVERRIDES="opengl32,glu32,bcryptprimitives=n;mscoree,mshtml="
Xvfb :93 -screen 0 640x480x24 -nolisten tcp >/dev/null 2>&1 &
XPID=$!
trap 'kill $XPID 2>/dev/null' EXIT
sleep 1
(cd "$OUT" && DISPLAY=:93 timeout 300 "$WINE" ./wgl_window.exe) 2>&1 | tr -d '\r' | tee "$OUT/wgl_window.log"
grep -q "^WGL WINDOW OK" "$OUT/wgl_window.log"
