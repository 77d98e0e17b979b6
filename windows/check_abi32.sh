#!/bin/bash
# The 32-bit Windows ABI of opengl32.dll (windows/build.sh i686):
#  1. every exported gl*, glu* and wgl* function is __stdcall (rustc
#     decorates a stdcall symbol as _name@N, N the bytes the callee pops)
#     and is exported under its undecorated name, as Microsoft's
#     opengl32.dll and glu32.dll export them (Delphi's and Free Pascal's
#     units import by those names);
#  2. for every export that the C headers declare (ours, and <windows.h>
#     for the wgl calls), the C compiler's own decoration of that
#     declaration has the same N: caller and callee agree on the argument
#     bytes, or the stack would be off by the difference after each call.
# Exit 77 when the 32-bit toolchain is not available.
set -u
cd "$(dirname "$0")/.."
bash windows/build.sh i686
rc=$?
[ $rc -eq 0 ] || exit $rc
DLL=${CARGO_TARGET_DIR:-target}/i686-pc-windows-gnu/release/softgl.dll
OUT=build/windows32
MINGW=i686-w64-mingw32
fail=0

# Exported names (the export table of the stripped DLL).
# (The glX* exports, which the shared entry table also gives the DLL, have
# no meaning on Windows and are left out.)
$MINGW-objdump -p "$OUT/opengl32.dll" | awk '/^\t\[ *[0-9]+\] [a-zA-Z_]/ { print $NF }' \
    | grep -E '^(gl|glu|wgl)[A-Z]' | grep -v '^glX' | sort -u >"$OUT/exports.txt"
# rustc's stdcall decorations: "_name@N" -> "name N".
$MINGW-nm "$DLL" | awk '$2 == "T" && $3 ~ /^_(gl|glu|wgl)[A-Z][A-Za-z0-9_]*@[0-9]+$/ {
        s = substr($3, 2); at = index(s, "@"); print substr(s, 1, at - 1), substr(s, at + 1) }' \
    | sort -u >"$OUT/rust_stdcall.txt"
n_exports=$(wc -l <"$OUT/exports.txt")
[ "$n_exports" -ge 500 ] || { echo "check_abi32: only $n_exports gl/glu/wgl exports"; exit 1; }
not_stdcall=$(join -v1 "$OUT/exports.txt" <(cut -d' ' -f1 "$OUT/rust_stdcall.txt"))
if [ -n "$not_stdcall" ]; then
    echo "check_abi32: exported but not __stdcall:"; echo "$not_stdcall" | head -20; fail=1
fi

# The C side: take the address of every export the headers declare and
# read the compiler's decorated reference from the object file.
{
    echo '#include <windows.h>'
    echo '#define GL_GLEXT_PROTOTYPES 1'
    echo '#include <GL/gl.h>'
    echo '#include <GL/glu.h>'
} >"$OUT/abi_decls.c"
$MINGW-gcc -E -I include "$OUT/abi_decls.c" >"$OUT/abi_decls.i" || exit 1
grep -oE '\b(gl|glu|wgl)[A-Z][A-Za-z0-9_]*[[:space:]]*\(' "$OUT/abi_decls.i" | tr -d ' (\t' | sort -u >"$OUT/declared.txt"
join "$OUT/exports.txt" "$OUT/declared.txt" >"$OUT/checked.txt"
{
    cat "$OUT/abi_decls.c"
    echo 'void *const softgl_abi_refs[] = {'
    sed 's/.*/    (void *)\&&,/' "$OUT/checked.txt"
    echo '};'
} >"$OUT/abi_refs.c"
$MINGW-gcc -c -O0 -w -I include -o "$OUT/abi_refs.o" "$OUT/abi_refs.c" || exit 1
# gdi32's private entry points into opengl32 have no header; their
# argument bytes from their documented signatures (HDC, int, UINT and
# pointers are 4 bytes each).
{
    $MINGW-nm "$OUT/abi_refs.o" | awk '$1 == "U" { s = $2; sub(/^__imp_/, "", s); sub(/^_/, "", s);
        at = index(s, "@"); if (at) print substr(s, 1, at - 1), substr(s, at + 1); else print s, "cdecl" }'
    printf '%s\n' "wglChoosePixelFormat 8" "wglDescribePixelFormat 16" "wglGetPixelFormat 4" \
        "wglSetPixelFormat 12" "wglSwapBuffers 4"
} | sort -u >"$OUT/c_stdcall.txt"
mismatch=$(join "$OUT/c_stdcall.txt" "$OUT/rust_stdcall.txt" | awk '$2 != $3')
if [ -n "$mismatch" ]; then
    echo "check_abi32: argument bytes differ (name, C header, softgl):"; echo "$mismatch" | head -20; fail=1
fi
n_checked=$(join "$OUT/c_stdcall.txt" "$OUT/rust_stdcall.txt" | awk '$2 == $3' | wc -l)
[ "$n_checked" -ge 400 ] || { echo "check_abi32: only $n_checked exports compared with a C declaration"; fail=1; }
unchecked=$(join -v1 "$OUT/exports.txt" <(cut -d' ' -f1 "$OUT/c_stdcall.txt"))
if [ -n "$unchecked" ]; then
    echo "check_abi32: exports with no C declaration to compare:"; echo "$unchecked" | head -20; fail=1
fi
echo "check_abi32: $n_exports gl/glu/wgl exports, all __stdcall under undecorated names; $n_checked agree with their C declaration's argument bytes"
exit $fail
