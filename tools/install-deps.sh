#!/bin/sh
# Installs the Debian packages fixpipe needs to build Mesa and to run the
# reference programs (and Slurm, whose one-node cluster the tests start: tests/slurm).
# Quick when everything is already there.
set -eu

PKGS="meson ninja-build python3-mako bison flex pkg-config ccache gcc g++ make
 libdrm-dev libx11-dev libxext-dev libxfixes-dev libxcb-glx0-dev libxcb-shm0-dev
 libx11-xcb-dev libxcb-dri2-0-dev libxcb-dri3-dev libxcb-present-dev libxcb-sync-dev
 libxcb-randr0-dev libxcb-xfixes0-dev libxshmfence-dev libxxf86vm-dev libxrandr-dev
 zlib1g-dev libexpat1-dev libpng-dev libegl-dev libgles-dev
 libgl1-mesa-dri libegl-mesa0 mesa-utils mesa-utils-bin glmark2-es2-x11 piglit
 apitrace apitrace-tracers xvfb xauth dpkg-dev python3 waffle-utils
 llvm-15-dev libelf-dev gdb clang python3-matplotlib python3-pil python3-numpy x11-apps
 chromium slurm-wlm munge"

SUDO=""
[ "$(id -u)" = 0 ] || SUDO=sudo

# A deb-src entry for the suites already configured, so `apt-get source mesa` (mesa/fetch.sh)
# works; checked on its own, since the packages may be there without it.
updated=""
if ! grep -rqs '^Types:.*deb-src' /etc/apt/sources.list.d/ && \
   ! grep -qs '^deb-src' /etc/apt/sources.list; then
    if [ -f /etc/apt/sources.list.d/debian.sources ]; then
        $SUDO sed 's/^Types: deb$/Types: deb-src/' /etc/apt/sources.list.d/debian.sources \
            | $SUDO tee /etc/apt/sources.list.d/fixpipe-deb-src.sources >/dev/null
    else
        grep '^deb ' /etc/apt/sources.list | sed 's/^deb /deb-src /' \
            | $SUDO tee /etc/apt/sources.list.d/fixpipe-deb-src.list >/dev/null
    fi
    $SUDO apt-get update -qq
    updated=1
fi

missing=""
for p in $PKGS; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" \
        || missing="$missing $p"
done
[ -z "$missing" ] && exit 0

echo "fixpipe: installing:$missing" >&2
[ -n "$updated" ] || $SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $missing
