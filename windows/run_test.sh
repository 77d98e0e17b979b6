#!/bin/bash
# Builds opengl32.dll and glu32.dll (windows/build.sh) and runs
# windows/wgl_window.c and windows/glu_callbacks.c against them under Wine
# on a private Xvfb; then builds the 32-bit DLLs and checks their stdcall
# ABI against the headers (windows/check_abi32.sh), and runs both programs
# as 32-bit programs too where a 32-bit Wine is installed (Debian:
# wine32:i386). Installs wine64 when missing (as root). Exit 77 (skipped)
# when the Windows toolchain or Wine is not available.
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
programs() { # $1 = mingw prefix, $2 = output directory
    $1-gcc -O1 -Wall -I include -o "$2/wgl_window.exe" windows/wgl_window.c -lopengl32 -lglu32 -lgdi32 -luser32 || return 1
    $1-gcc -O1 -Wall -I include -o "$2/glu_callbacks.exe" windows/glu_callbacks.c -lglu32 -lopengl32 || return 1
    # Wine 8 has no bcryptprimitives.dll (see the stub's comment).
    $1-gcc -shared -O1 -s -o "$2/bcryptprimitives.dll" windows/bcryptprimitives_stub.c -ladvapi32 || return 1
}
programs x86_64-w64-mingw32 "$OUT" || exit 1
export WINEPREFIX=${WINEPREFIX:-/tmp/softgl-wineprefix}
export WINEDEBUG=-all
# Native (softgl's) opengl32 and glu32 from the program's directory.
export WINEDLLOVERRIDES="opengl32,glu32,bcryptprimitives=n;mscoree,mshtml="
Xvfb :93 -screen 0 640x480x24 -nolisten tcp >/dev/null 2>&1 &
XPID=$!
trap 'kill $XPID 2>/dev/null' EXIT
sleep 1
run() { # $1 = wine, $2 = directory, $3 = program, $4 = its success line
    (cd "$2" && DISPLAY=:93 timeout 300 "$1" ./$3.exe) 2>&1 | tr -d '\r' | tee "$2/$3.log"
    grep -q "^$4" "$2/$3.log" || { echo "windows/run_test.sh: $2/$3.exe failed"; fail=1; }
}
fail=0
run "$WINE" "$OUT" wgl_window "WGL WINDOW OK"
run "$WINE" "$OUT" glu_callbacks "GLU CALLBACKS OK"

# 32-bit: the DLLs and their ABI; the programs where Wine can run them.
bash windows/check_abi32.sh
rc=$?
if [ $rc -eq 77 ]; then
    echo "windows/run_test.sh: 32-bit skipped (no i686 toolchain)"
elif [ $rc -ne 0 ]; then
    fail=1
elif [ -x /usr/lib/wine/wine ] || [ -x /usr/lib/i386-linux-gnu/wine/wine ]; then
    WINE32=$(ls /usr/lib/wine/wine /usr/lib/i386-linux-gnu/wine/wine 2>/dev/null | head -1)
    programs i686-w64-mingw32 build/windows32 || exit 1
    WINEPREFIX=${WINEPREFIX}32
    export WINEPREFIX
    run "$WINE32" build/windows32 wgl_window "WGL WINDOW OK"
    run "$WINE32" build/windows32 glu_callbacks "GLU CALLBACKS OK"
else
    echo "windows/run_test.sh: 32-bit programs not run: no 32-bit Wine here (Debian: dpkg --add-architecture i386; apt-get install wine32:i386)"
fi
exit $fail
