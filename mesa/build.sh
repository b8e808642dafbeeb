#!/bin/sh
# Builds the pinned, patched Mesa with the fixpipe driver into $FIXPIPE_WORK/prefix.
# Quick no-op when nothing changed; reconfigures when the options, the patches or the
# Mesa pin change. The one heavy build of the machine: holds /tmp/fixpipe-build.lock.
#
#   FIXPIPE_WORK             work dir (default: <repo>/.fixpipe)
#   FIXPIPE_GALLIUM_DRIVERS  default swrast,fixpipe ("swrast" alone warms ccache before
#                            the driver exists)
#   FIXPIPE_MESA_BUILDTYPE   default release
#   FIXPIPE_SANITIZE         e.g. address,undefined: a second build (mesa-build-asan, installed
#                            in prefix-asan) whose fixpipe sources (driver and model) are
#                            compiled with -fsanitize=...; Mesa's own stay as they are, so
#                            ccache serves them from the first build (./fixpipe run --sanitize)
set -eu
REPO=$(cd "$(dirname "$0")/.." && pwd)
WORK=${FIXPIPE_WORK:-$REPO/.fixpipe}
SANITIZE=${FIXPIPE_SANITIZE:-}
TAG=${SANITIZE:+-asan}
BUILD=$WORK/mesa-build$TAG
PREFIX=$WORK/prefix$TAG
DRIVERS=${FIXPIPE_GALLIUM_DRIVERS:-swrast,fixpipe}
BUILDTYPE=${FIXPIPE_MESA_BUILDTYPE:-release}

# mako comes from Debian's python3-mako; a python earlier in PATH (a venv) would lack it.
PATH=/usr/bin:/bin:$PATH
# Hits across clones at different paths (CI uses a fresh clone).
CCACHE_NOHASHDIR=1
export PATH CCACHE_NOHASHDIR

exec 9>/tmp/fixpipe-build.lock
if ! flock -n 9; then
    echo "fixpipe: waiting for another Mesa build (/tmp/fixpipe-build.lock)" >&2
    flock 9
fi

sh "$REPO/mesa/fetch.sh"
SRC=$WORK/mesa-src
case ",$DRIVERS," in
*,fixpipe,*)
    if [ ! -f "$SRC/src/gallium/drivers/fixpipe/meson.build" ]; then
        echo "fixpipe: no driver build file at $(readlink "$SRC/src/gallium/drivers/fixpipe")/meson.build" >&2
        echo "fixpipe: (FIXPIPE_GALLIUM_DRIVERS=swrast builds Mesa without it)" >&2
        exit 1
    fi ;;
esac

# Only what the launcher runs: GLX/EGL/GLES2/OSMesa on the software rasterizers, with
# Debian's LLVM 15 (the one its own llvmpipe uses) for gallivm: draw's compiled vertex
# shaders, fixpipe's compiled fragment shaders, and llvmpipe from the same tree. The native
# file names llvm-config-15 (through mesa/llvm-config): /usr/bin/llvm-config may be another
# LLVM that meson would take. LLVM is linked statically: every GL process loads the driver,
# and loading libLLVM-15.so (its relocations and symbol look-ups) made piglit's thousands of
# short processes slower than without LLVM.
# Statically linked, the driver has 110,000 relative relocations: packed (DT_RELR, glibc 2.36)
# their table shrinks from 2.6 MB, read by every process that loads the driver, to kilobytes.
# mesa/llvm-ctors.ld keeps LLVM's static constructors out of .init_array: gallivm runs them
# at the first compiled shader (mesa/patches/0006), not the loader in every process.
NATIVE=$WORK/llvm$TAG.ini
LINK_ARGS=-Wl,-z,pack-relative-relocs,-T,$REPO/mesa/llvm-ctors.ld
OPTIONS="--prefix=$PREFIX --libdir=lib --buildtype=$BUILDTYPE -Db_ndebug=true
 --native-file=$NATIVE -Dllvm=enabled -Dshared-llvm=disabled -Dshader-cache=enabled
 -Dc_link_args=$LINK_ARGS -Dcpp_link_args=$LINK_ARGS
 -Dplatforms=x11 -Dgallium-drivers=$DRIVERS -Dvulkan-drivers=
 -Dglx=dri -Dosmesa=true -Degl=enabled -Dgles1=disabled -Dgles2=enabled
 -Dglvnd=false -Dgbm=disabled -Dshared-glapi=enabled
 -Dgallium-vdpau=disabled -Dgallium-va=disabled -Dgallium-xa=disabled
 -Dgallium-omx=disabled -Dgallium-opencl=disabled -Dgallium-nine=false
 -Dbuild-tests=false -Dvalgrind=disabled -Dlibunwind=disabled -Dlmsensors=disabled"
# shellcheck disable=SC2086,SC2116  # one line of words
sed "s#@REPO@#$REPO#g" "$REPO/mesa/llvm.ini" > "$NATIVE"
# src/meson.build reads it with meson.get_external_property(): Mesa has no option of ours
[ -z "$SANITIZE" ] || printf "[properties]\nfixpipe_sanitize = '%s'\n" "$SANITIZE" >> "$NATIVE"
stamp="$(cat "$SRC/.fixpipe-stamp") $(echo $OPTIONS) $(cat "$NATIVE" "$REPO/mesa/llvm-config" "$REPO/mesa/llvm-ctors.ld")"

if [ ! -f "$BUILD/.fixpipe-stamp" ] || [ "$(cat "$BUILD/.fixpipe-stamp")" != "$stamp" ]; then
    rm -f "$BUILD/.fixpipe-stamp"
    wipe=""
    [ -f "$BUILD/build.ninja" ] && wipe=--wipe
    echo "fixpipe: configuring Mesa in $BUILD" >&2
    # shellcheck disable=SC2086  # OPTIONS is a word list
    if ! meson setup $wipe "$BUILD" "$SRC" $OPTIONS > "$WORK/mesa-configure$TAG.log" 2>&1; then
        tail -n 30 "$WORK/mesa-configure$TAG.log" >&2
        echo "fixpipe: Mesa configure failed, full log: $WORK/mesa-configure$TAG.log" >&2
        exit 1
    fi
    echo "$stamp" > "$BUILD/.fixpipe-stamp"
    rm -rf "$PREFIX"
fi

start=$(date +%s)
if [ -t 1 ]; then
    ninja -C "$BUILD" || { echo "fixpipe: Mesa build failed" >&2; exit 1; }
elif ! ninja -C "$BUILD" > "$WORK/mesa-build$TAG.log" 2>&1; then
    # the error messages, without ninja's one-line compiler commands
    grep -A25 -m3 '^FAILED' "$WORK/mesa-build$TAG.log" | grep -Ev '^(ccache )?(cc|gcc|c\+\+|g\+\+) ' >&2 \
        || tail -n 40 "$WORK/mesa-build$TAG.log" >&2
    echo "fixpipe: Mesa build failed, full log: $WORK/mesa-build$TAG.log" >&2
    exit 1
fi
if ! meson install -C "$BUILD" --no-rebuild --only-changed --quiet > "$WORK/mesa-install$TAG.log" 2>&1; then
    tail -n 20 "$WORK/mesa-install$TAG.log" >&2
    echo "fixpipe: Mesa install failed, full log: $WORK/mesa-install$TAG.log" >&2
    exit 1
fi
# `./fixpipe run --driver llvmpipe` keeps Debian's Mesa but has no libOSMesa there:
# a directory with ours alone (its llvmpipe is Debian's, same version and LLVM).
if [ -z "$SANITIZE" ]; then
    mkdir -p "$WORK/osmesa-only"
    ln -sfn "$PREFIX/lib/libOSMesa.so.8" "$WORK/osmesa-only/libOSMesa.so.8"
fi
# (ninja always re-runs git_sha1.h and the devenv links: cheap, and nothing follows from them)
echo "fixpipe: Mesa ($DRIVERS${SANITIZE:+, fixpipe with -fsanitize=$SANITIZE}) ready in $(( $(date +%s) - start )) s:" \
     "libs in $PREFIX/lib, DRI driver in $PREFIX/lib/dri" >&2
