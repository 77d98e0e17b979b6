#!/bin/sh
# Installs the Debian packages the tests and demo use, when running as root
# and they are missing: a C compiler, pkg-config, and Mesa's OSMesa and GLU
# (the LD_PRELOAD test builds a program against Mesa and runs it on softgl),
# and for the GLX test Xvfb, the Xlib and Xext headers (also for the
# headless X libraries), x11-utils and mesa-utils
# (glxgears), freeglut and waffle-utils (a GLUT program, wflinfo), and
# Free Pascal with its gl/glu units for delphi_samples/.
set -eu
need=""
command -v cc >/dev/null 2>&1 || need="$need gcc libc6-dev"
command -v pkg-config >/dev/null 2>&1 || need="$need pkg-config"
[ -f /usr/include/GL/osmesa.h ] || need="$need libosmesa6-dev"
[ -f /usr/include/GL/glu.h ] || need="$need libglu1-mesa-dev"
command -v Xvfb >/dev/null 2>&1 || need="$need xvfb"
[ -f /usr/include/X11/Xlib.h ] || need="$need libx11-dev"
[ -f /usr/include/X11/extensions/XShm.h ] || need="$need libxext-dev"
command -v xdpyinfo >/dev/null 2>&1 || need="$need x11-utils"
command -v glxgears >/dev/null 2>&1 || need="$need mesa-utils"
[ -f /usr/include/GL/freeglut.h ] || need="$need freeglut3-dev"
command -v wflinfo >/dev/null 2>&1 || need="$need waffle-utils"
command -v fpc >/dev/null 2>&1 || need="$need fp-compiler fp-units-gfx"
[ -z "$need" ] && exit 0
if [ "$(id -u)" != 0 ] || ! command -v apt-get >/dev/null 2>&1; then
  echo "install_deps: missing$need (not root or no apt-get: tests that need them will be skipped)"
  exit 0
fi
echo "install_deps: installing$need"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq >/dev/null
apt-get install -y -qq --no-install-recommends $need >/dev/null
