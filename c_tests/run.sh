#!/usr/bin/env bash
# Build and run softgl's C tests: every c_tests/t_*.c and c_tests/book/t_*.c
# (the book ports; compiled against harness.c) and every c_tests/t_*.sh,
# from the repo root.
#
#   c_tests/run.sh [FILTER]      run the tests whose name contains FILTER
#
# Variables (defaults in brackets):
#   CC              C compiler [cc]
#   INCLUDE         include flags [-I include]
#   GL_LIBS         link flags [-L build/lib -Wl,-rpath,$PWD/build/lib -lGL -lGLU]
#   SOFTGL_IMGCMP   image comparer [target/release/imgcmp]
#   SOFTGL_TEST_OUT where tests write images [out/c_tests]
#   SOFTGL_BLESS=1  write goldens instead of comparing (then look at them!)
#   TEST_TIMEOUT    seconds per test [60]
# Against Mesa:  INCLUDE=-I/usr/include GL_LIBS="-lOSMesa -lGLU" c_tests/run.sh
#
# A test passes with exit 0, is skipped with exit 77 (printing "SKIP reason"),
# and fails otherwise.  The last line is "N passed, N failed[, N skipped]".
set -u

cd "$(dirname "$0")/.." || exit 2
ROOT=$PWD

CC=${CC:-cc}
INCLUDE=${INCLUDE:--I include}
GL_LIBS=${GL_LIBS:--L build/lib -Wl,-rpath,$ROOT/build/lib -lGL -lGLU}
SOFTGL_TEST_OUT=${SOFTGL_TEST_OUT:-out/c_tests}
TEST_TIMEOUT=${TEST_TIMEOUT:-60}
BUILD=build/c_tests
FILTER=${1:-}

# Find imgcmp: the workspace build, else the crate's own target dir, else build it.
if [ -z "${SOFTGL_IMGCMP:-}" ]; then
    if [ -x target/release/imgcmp ]; then
        SOFTGL_IMGCMP=target/release/imgcmp
    elif [ -x tools/imgcmp/target/release/imgcmp ]; then
        SOFTGL_IMGCMP=tools/imgcmp/target/release/imgcmp
    else
        echo "building imgcmp..."
        cargo build --quiet --release --manifest-path tools/imgcmp/Cargo.toml
        if [ -x target/release/imgcmp ]; then
            SOFTGL_IMGCMP=target/release/imgcmp
        else
            SOFTGL_IMGCMP=tools/imgcmp/target/release/imgcmp
        fi
    fi
fi
export SOFTGL_IMGCMP SOFTGL_TEST_OUT

mkdir -p "$BUILD" "$SOFTGL_TEST_OUT"

passed=0 failed=0 skipped=0
failed_names=()

record() { # name rc
    case $2 in
        0) passed=$((passed + 1)) ;;
        77) skipped=$((skipped + 1)) ;;
        *) failed=$((failed + 1)); failed_names+=("$1") ;;
    esac
}

run_one() { # name command...
    local name=$1 rc log
    shift
    log=$BUILD/$name.log
    timeout "$TEST_TIMEOUT" "$@" >"$log" 2>&1
    rc=$?
    cat "$log"
    if [ $rc -eq 124 ]; then
        echo "FAIL $name (timed out after ${TEST_TIMEOUT}s)"
    elif [ $rc -ne 0 ] && [ $rc -ne 77 ] && ! grep -q "^FAIL" "$log"; then
        echo "FAIL $name (exit status $rc)"
    elif [ $rc -eq 77 ] && ! grep -q "^SKIP" "$log"; then
        echo "SKIP $name"
    fi
    record "$name" $rc
}

shopt -s nullglob
for src in c_tests/t_*.c c_tests/t_*.sh c_tests/book/t_*.c; do
    file=${src##*/}
    name=${file%.*}
    if [ -n "$FILTER" ] && [[ $name != *"$FILTER"* ]]; then
        continue
    fi
    case $src in
    *.c)
        # shellcheck disable=SC2086  # flags are meant to split
        if ! $CC -std=c99 -O1 -Wall $INCLUDE -I c_tests -o "$BUILD/$name" \
            "$src" c_tests/harness.c $GL_LIBS -lm >"$BUILD/$name.build.log" 2>&1; then
            cat "$BUILD/$name.build.log"
            echo "FAIL $name (does not compile)"
            record "$name" 1
            continue
        fi
        if [ -s "$BUILD/$name.build.log" ]; then cat "$BUILD/$name.build.log"; fi
        run_one "$name" "$BUILD/$name"
        ;;
    *.sh)
        run_one "$name" bash "$src"
        ;;
    esac
done

if [ $failed -gt 0 ]; then
    echo "failed: ${failed_names[*]}"
fi
summary="$passed passed, $failed failed"
if [ $skipped -gt 0 ]; then
    summary="$summary, $skipped skipped"
fi
echo "$summary"
[ $failed -eq 0 ]
