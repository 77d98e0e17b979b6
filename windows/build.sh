#!/bin/bash
# Builds softgl for Windows with mingw-w64: `windows/build.sh` (or
# `x86_64`) for 64-bit Windows into build/windows, `windows/build.sh i686`
# for 32-bit Windows (stdcall entry points, undecorated export names, as
# Microsoft's opengl32.dll has them) into build/windows32:
# opengl32.dll (softgl itself: gl*, glu*, wgl*) and glu32.dll (a DLL of
# forwarders only: each glu* export forwards to opengl32.dll's, so a
# process holds one softgl, as the libGLU.so.1 symlink does on Linux).
# Installs the Rust target and mingw-w64 when missing (rustup; apt as root).
# Exit status 77: the toolchain is not available here.
set -u
cd "$(dirname "$0")/.."
ARCH=${1:-x86_64}
case "$ARCH" in
    x86_64) OUT=build/windows; MINGW=x86_64-w64-mingw32; PKG=gcc-mingw-w64-x86-64-win32 ;;
    i686) OUT=build/windows32; MINGW=i686-w64-mingw32; PKG=gcc-mingw-w64-i686-win32 ;;
    *) echo "windows/build.sh: ARCH is x86_64 or i686, not $ARCH"; exit 2 ;;
esac
TARGET=$ARCH-pc-windows-gnu
CARGO=${CARGO:-cargo}
if ! command -v $MINGW-gcc >/dev/null 2>&1; then
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
        DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $PKG >/dev/null 2>&1
    fi
fi
command -v $MINGW-gcc >/dev/null 2>&1 || { echo "windows/build.sh: no mingw-w64 ($MINGW-gcc)"; exit 77; }
if ! rustup target list --installed 2>/dev/null | grep -qx "$TARGET"; then
    rustup target add "$TARGET" >/dev/null 2>&1 || { echo "windows/build.sh: cannot install the Rust target $TARGET"; exit 77; }
fi
$CARGO build --release --lib --target "$TARGET" || exit 1
mkdir -p "$OUT"
$MINGW-strip -o "$OUT/opengl32.dll" "${CARGO_TARGET_DIR:-target}/$TARGET/release/softgl.dll" || exit 1
# glu32.dll: "name = opengl32.name" makes each export a forwarder.
{
    echo "LIBRARY glu32.dll"
    echo "EXPORTS"
    $MINGW-objdump -p "$OUT/opengl32.dll" | awk '$NF ~ /^glu[A-Z]/ { print "    " $NF " = opengl32." $NF }' | sort -u
} >"$OUT/glu32.def"
n=$(grep -c " = opengl32\." "$OUT/glu32.def")
[ "$n" -ge 50 ] || { echo "windows/build.sh: only $n glu exports found"; exit 1; }
printf 'int glu32_forwarders_only;\n' >"$OUT/glu32_empty.c"
$MINGW-gcc -shared -s -o "$OUT/glu32.dll" "$OUT/glu32_empty.c" "$OUT/glu32.def" || exit 1
echo "built $OUT/opengl32.dll and $OUT/glu32.dll ($n forwarders)"
