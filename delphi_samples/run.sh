#!/usr/bin/env bash
# Build and run the Free Pascal (Delphi mode) sample programs against
# softgl, and check every image they write against its golden.
#
#   delphi_samples/run.sh [FILTER]   only the runs whose name contains FILTER
#
# Each program is compiled with `fpc -Mdelphi`, linked against build/lib
# (softgl as libGL.so / libGLU.so) and run with LD_LIBRARY_PATH=build/lib,
# so Free Pascal's gl/glu units (which dlopen libGL.so.1 / libGLU.so.1)
# load softgl too.  A run passes when the program's own pixel checks pass
# (it prints PASS and exits 0) and each PNG it wrote matches
# delphi_samples/golden/NAME.png under imgcmp (TOL per channel, at most
# MAX_BAD pixels off).
#
# Free Pascal missing: installed with apt when running as root; otherwise
# every run FAILS (no silent skip).
#
# Variables: DELPHI_OUT (images, default out/delphi), DELPHI_BLESS=1 (write
# the goldens instead of comparing: then look at every one of them),
# SOFTGL_IMGCMP (default target/release/imgcmp), FPC (the compiler, fpc),
# TOL (2), MAX_BAD (40),
# TEST_TIMEOUT (60 s).  Ends with "N passed, N failed".
set -u
cd "$(dirname "$0")/.." || exit 2
ROOT=$PWD
FILTER=${1:-}
OUT=${DELPHI_OUT:-out/delphi}
case $OUT in /*) ;; *) OUT=$ROOT/$OUT ;; esac
BUILD=$ROOT/build/delphi
LIB=$ROOT/build/lib
GOLDEN=$ROOT/delphi_samples/golden
TOL=${TOL:-2}
MAX_BAD=${MAX_BAD:-40}
TEST_TIMEOUT=${TEST_TIMEOUT:-60}
IMGCMP=${SOFTGL_IMGCMP:-target/release/imgcmp}
FPC=${FPC:-fpc}
case $IMGCMP in /*) ;; *) IMGCMP=$ROOT/$IMGCMP ;; esac

# name | program (under delphi_samples) | arguments | working directory
RUNS="
tesswind_book|persian/tesswind.dpr|book|.
tesswind_odd|persian/tesswind.dpr|odd|.
tesswind_nonzero|persian/tesswind.dpr|nonzero|.
tesswind_positive|persian/tesswind.dpr|positive|.
tesswind_negative|persian/tesswind.dpr|negative|.
tesswind_abs_geq_two|persian/tesswind.dpr|abs_geq_two|.
tesswind_cycle|persian/tesswind.dpr|cycle|.
reflectdino|persian/reflectdino.dpr||.
decal|krasnov/decal.dpr||.
primitives|textbook/primitives.dpr||.
stipple_bitmap|textbook/stipple_bitmap.dpr||.
text|textbook/text.dpr||.
quadrics|textbook/quadrics.dpr||.
lists|textbook/lists.dpr||.
arrays|textbook/arrays.dpr||.
texture|textbook/texture.dpr||delphi_samples/textbook
lighting|textbook/lighting.dpr||.
fog|textbook/fog.dpr||.
blending|textbook/blending.dpr||.
stencil|textbook/stencil.dpr||.
accum|textbook/accum.dpr||.
clipplanes|textbook/clipplanes.dpr||.
unproject|textbook/unproject.dpr||.
pixels|textbook/pixels.dpr||.
"

passed=0 failed=0
failed_names=()
fail() { echo "FAIL $1${2:+ ($2)}"; failed=$((failed + 1)); failed_names+=("$1"); }

if ! command -v "$FPC" >/dev/null 2>&1; then
    if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
        echo "installing Free Pascal (fp-compiler fp-units-gfx)..."
        export DEBIAN_FRONTEND=noninteractive
        apt-get update -qq >/dev/null
        apt-get install -y -qq --no-install-recommends fp-compiler fp-units-gfx >/dev/null
    fi
fi
if ! command -v "$FPC" >/dev/null 2>&1; then
    n=0
    while IFS='|' read -r name _; do
        [ -z "$name" ] && continue
        if [ -n "$FILTER" ] && [[ $name != *"$FILTER"* ]]; then continue; fi
        fail "$name" "no Free Pascal compiler: install fp-compiler and fp-units-gfx"
        n=$((n + 1))
    done <<<"$RUNS"
    echo "0 passed, $failed failed"
    exit 1
fi
if [ ! -e "$LIB/libGL.so.1" ] || [ ! -e "$LIB/libGLU.so" ]; then
    echo "FAIL: $LIB/libGL.so.1 missing: run make lib first"
    echo "0 passed, 1 failed"
    exit 1
fi
if [ ! -x "$IMGCMP" ]; then
    cargo build --quiet --release --manifest-path tools/imgcmp/Cargo.toml
    [ -x "$IMGCMP" ] || IMGCMP=$ROOT/tools/imgcmp/target/release/imgcmp
fi

mkdir -p "$BUILD" "$OUT"
# a full run starts from no images, so a golden no run produced shows up
[ -n "$FILTER" ] || rm -f "$OUT"/*.png
declare -A built=()

build() { # program.dpr -> 0 when built
    local src=$1 log
    [ -n "${built[$src]:-}" ] && return "${built[$src]}"
    log=$BUILD/$(basename "$src" .dpr).build.log
    "$FPC" -Mdelphi -O1 -vew -Fudelphi_samples/units -Fu"delphi_samples/$(dirname "$src")" \
        -k-L"$LIB" -k-rpath="$LIB" -FU"$BUILD" -FE"$BUILD" "delphi_samples/$src" >"$log" 2>&1
    built[$src]=$?
    [ "${built[$src]}" = 0 ] || cat "$log"
    return "${built[$src]}"
}

while IFS='|' read -r name src args dir; do
    [ -z "$name" ] && continue
    if [ -n "$FILTER" ] && [[ $name != *"$FILTER"* ]]; then continue; fi
    if ! build "$src"; then fail "$name" "does not compile"; continue; fi
    exe=$BUILD/$(basename "$src" .dpr)
    log=$BUILD/$name.log
    # shellcheck disable=SC2086  # args split on purpose
    (cd "$dir" && DELPHI_OUT=$OUT LD_LIBRARY_PATH=$LIB timeout "$TEST_TIMEOUT" "$exe" $args) >"$log" 2>&1
    rc=$?
    cat "$log"
    if [ $rc -ne 0 ]; then
        fail "$name" "exit status $rc"
        continue
    fi
    ok=1
    images=$(sed -n 's|^wrote .*/\([^/]*\)\.png$|\1|p' "$log")
    [ -n "$images" ] || { ok=0; echo "  no image written"; }
    for img in $images; do
        if [ "${DELPHI_BLESS:-}" = 1 ]; then
            mkdir -p "$GOLDEN"
            "$IMGCMP" --to-png "$OUT/$img.png" "$GOLDEN/$img.png" && echo "  blessed $GOLDEN/$img.png (look at it)"
        elif [ ! -f "$GOLDEN/$img.png" ]; then
            echo "  no golden $GOLDEN/$img.png (DELPHI_BLESS=1, then look at it)"
            ok=0
        elif ! "$IMGCMP" "$OUT/$img.png" "$GOLDEN/$img.png" --tol "$TOL" --max-bad "$MAX_BAD"; then
            echo "  $img.png differs from its golden"
            ok=0
        fi
    done
    if [ $ok = 1 ]; then passed=$((passed + 1)); else fail "$name" "images"; fi
done <<<"$RUNS"

# every golden must have been produced by some run (unless filtered)
if [ -z "$FILTER" ] && [ "${DELPHI_BLESS:-}" != 1 ]; then
    for g in "$GOLDEN"/*.png; do
        case $g in *.actual.png) continue ;; esac
        [ -f "$OUT/$(basename "$g")" ] || fail "$(basename "$g" .png)" "golden with no image from this run"
        grep -q "^$(basename "$g" .png)	" delphi_samples/gallery.tsv || fail "$(basename "$g" .png)" "not described in delphi_samples/gallery.tsv"
    done
fi

# a page for the images: delphi_samples/gallery.tsv gives each one's book,
# program and what it exercises
if [ -z "$FILTER" ]; then
    awk -F'\t' 'function esc(s) { gsub(/&/, "\\&amp;", s); gsub(/</, "\\&lt;", s); gsub(/>/, "\\&gt;", s); return s }
        BEGIN { print "<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>softgl: the Delphi programs</title></head><body>";
                print "<h1>The books&apos; Delphi programs under Free Pascal, on softgl</h1>";
                print "<p>Built and checked by <code>delphi_samples/run.sh</code>; see <code>docs/delphi.md</code>.</p>";
                print "<table border=\"1\" cellpadding=\"4\"><tr><th>image</th><th>book</th><th>program</th><th>what it shows</th></tr>" }
        /^#/ { next }
        { printf "<tr><td><img src=\"%s.png\" alt=\"%s\"><br>%s</td><td>%s</td><td>%s</td><td>%s</td></tr>\n", $1, $1, $1, esc($2), esc($3), esc($4) }
        END { print "</table></body></html>" }' delphi_samples/gallery.tsv >"$OUT/index.html"
fi

if [ $failed -gt 0 ]; then echo "failed: ${failed_names[*]}"; fi
echo "$passed passed, $failed failed"
[ $failed -eq 0 ]
