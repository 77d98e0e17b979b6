#!/bin/sh
# Checks that the shipped headers and the library's exports agree name for
# name, that every GL 1.1 name (opengl32.dll's 336) and the OSMesa API are
# exported, and that the SONAME is libGL.so.1.
set -eu
cd "$(dirname "$0")/.."
LIB=build/lib/libGL.so.1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail=0; pass=0
ok()  { pass=$((pass + 1)); echo "ok   $1"; }
bad() { fail=$((fail + 1)); echo "FAIL $1"; }

grep -hE '^GLAPI .*APIENTRY +[A-Za-z0-9_]+ *\(' include/GL/gl.h include/GL/glu.h include/GL/osmesa.h include/GL/glx.h include/GL/softgl_wgl.h |
  sed -E 's/^GLAPI .*APIENTRY +([A-Za-z0-9_]+) *\(.*/\1/' | sort -u > "$tmp/headers"
nm -D --defined-only "$LIB" | awk '$2 == "T" {print $3}' | sed 's/@.*//' |
  grep -E '^(gl|glu|OSMesa|glX|wgl|softgl)[A-Z]' | sort -u > "$tmp/exports"

if cmp -s "$tmp/headers" "$tmp/exports"; then
  ok "headers and exports agree ($(wc -l < "$tmp/exports") names)"
else
  bad "headers and exports differ:"
  comm -23 "$tmp/headers" "$tmp/exports" | sed 's/^/      declared, not exported: /'
  comm -13 "$tmp/headers" "$tmp/exports" | sed 's/^/      exported, not declared: /'
fi

list=../shared/reference/symbols/gl11-opengl32-336.txt
if [ -f "$list" ]; then
  missing=$(sort -u "$list" | comm -23 - "$tmp/exports" | wc -l)
  [ "$missing" -eq 0 ] && ok "all $(wc -l < "$list") GL 1.1 names exported" || bad "$missing GL 1.1 names missing"
else
  echo "skip GL 1.1 list (../shared not present)"
fi

for f in OSMesaCreateContext OSMesaCreateContextExt OSMesaCreateContextAttribs OSMesaMakeCurrent \
         OSMesaGetCurrentContext OSMesaGetDepthBuffer OSMesaGetColorBuffer OSMesaGetIntegerv \
         OSMesaPixelStore OSMesaGetProcAddress OSMesaDestroyContext; do
  grep -qx "$f" "$tmp/exports" || echo "$f" >> "$tmp/missing_osmesa"
done
[ -s "$tmp/missing_osmesa" ] && bad "OSMesa functions not exported: $(cat "$tmp/missing_osmesa")" || ok "OSMesa API exported"

soname=$(readelf -d "$LIB" | sed -n 's/.*(SONAME).*\[\(.*\)\]/\1/p')
[ "$soname" = libGL.so.1 ] && ok "SONAME is libGL.so.1" || bad "SONAME is '$soname'"
links_ok=1
for n in libGL.so libGLU.so.1 libGLU.so libOSMesa.so.8 libOSMesa.so; do
  [ "$(readlink -f build/lib/$n)" = "$(readlink -f $LIB)" ] || { links_ok=0; echo "      build/lib/$n does not lead to libGL.so.1"; }
done
[ $links_ok = 1 ] && ok "build/lib names lead to one library" || bad "build/lib names"

echo "exports: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
