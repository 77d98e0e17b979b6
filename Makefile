# softgl — build, test, demo. See README.md.
#
#   make         build the library and lay out build/lib
#   make headless  the X client stand-ins for running X programs without a
#                display (build/headless, headless/README.md)
#   make test    all tests (Rust unit tests, header/export checks, C tests)
#   make demo    render the demo scenes into out/
#   make piglit  piglit's GL 1.x tests against softgl on Xvfb
#   make bench   benchmark against Mesa into out/bench/ (BENCH_ARGS=--quick for a short run)
#   make coverage  regenerate the README's coverage table

CARGO ?= cargo
CC ?= cc
LIB := build/lib
SO := target/release/libsoftgl.so

.PHONY: headless piglit bench all lib test rust-test c-test exports-test delphi-test windows windows-test demo coverage coverage-check deps clean

all: lib headless

# One object under every name programs look for (README: "One library,
# several names"): the SONAME is libGL.so.1; the others are symlinks so a
# process that loads two of the names still holds a single softgl.
lib:
	$(CARGO) build --release --workspace
	mkdir -p $(LIB)
	cp -f $(SO) $(LIB)/libGL.so.1.tmp && mv -f $(LIB)/libGL.so.1.tmp $(LIB)/libGL.so.1
	ln -sf libGL.so.1 $(LIB)/libGL.so
	ln -sf libGL.so.1 $(LIB)/libGLU.so.1
	ln -sf libGLU.so.1 $(LIB)/libGLU.so
	ln -sf libGL.so.1 $(LIB)/libOSMesa.so.8
	ln -sf libOSMesa.so.8 $(LIB)/libOSMesa.so
	ln -sf libGL.so.1 $(LIB)/libsoftgl.so

# libX11.so.6, libXext.so.6, libXi.so.6, libXxf86vm.so.1 with no X server
# behind them (headless/build.sh; skipped without the Xlib headers).
headless:
	sh headless/build.sh

# Debian packages the tests use (only when root and missing).
deps:
	@sh tools/install_deps.sh

test: deps lib headless rust-test exports-test coverage-check c-test delphi-test windows-test

rust-test:
	$(CARGO) test --release --workspace

exports-test: lib
	sh tools/check_exports.sh

c-test: lib headless
	bash c_tests/run.sh

# opengl32.dll + glu32.dll cross-built with mingw-w64, 64-bit
# (build/windows) and 32-bit stdcall (build/windows32), and Windows
# programs run against them under Wine (windows/run_test.sh; skipped,
# status 77, where the Rust Windows target or Wine cannot be installed).
windows:
	bash windows/build.sh
	bash windows/build.sh i686

windows-test:
	@bash windows/run_test.sh; rc=$$?; if [ $$rc -eq 77 ]; then echo "SKIP windows-test (no Windows toolchain or Wine here)"; else exit $$rc; fi

# The Free Pascal (Delphi mode) book programs, their images checked
# (delphi_samples/run.sh; installs fp-compiler when root, fails without it).
delphi-test: lib
	bash delphi_samples/run.sh

# The Delphi samples run first so that demo/run.sh's gallery shows them.
demo: lib
	DELPHI_OUT=out/demo/delphi bash delphi_samples/run.sh; st=$$?; sh demo/run.sh && exit $$st

# piglit's GL 1.x group on Xvfb against softgl: out/piglit.summary.txt.
piglit: lib
	bash tools/piglit.sh

# Side by side against Mesa (llvmpipe 1 thread / all cores, softpipe): out/bench/.
bench: deps lib
	sh bench/build.sh
	python3 -c 'import matplotlib' 2>/dev/null || pip install -q matplotlib || echo "no matplotlib: no plots"
	python3 bench/run.py $(BENCH_ARGS)

coverage:
	$(CARGO) run --release --quiet --bin coverage -- README.md

coverage-check:
	$(CARGO) run --release --quiet --bin coverage -- --check README.md

clean:
	rm -rf build out
	$(CARGO) clean
