#!/bin/sh
# Puts the pinned, checksum-verified, patched Mesa source at $FIXPIPE_WORK/mesa-src
# with src/gallium/drivers/fixpipe linked to this repository's src/.
# Quick when it is already there.
# FIXPIPE_DRIVER_SRC points the link elsewhere (a throw-away driver, for testing the patches).
set -eu
REPO=$(cd "$(dirname "$0")/.." && pwd)
. "$REPO/mesa/pin"
WORK=${FIXPIPE_WORK:-$REPO/.fixpipe}
DRIVER_SRC=${FIXPIPE_DRIVER_SRC:-$REPO/src}
SRC=$WORK/mesa-src
DL=$WORK/download
mkdir -p "$DL"

stamp="$MESA_SHA256 $(cat "$REPO"/mesa/patches/*.patch | sha256sum | cut -d' ' -f1)"
if [ -f "$SRC/.fixpipe-stamp" ] && [ "$(cat "$SRC/.fixpipe-stamp")" = "$stamp" ]; then
    ln -sfn "$DRIVER_SRC" "$SRC/src/gallium/drivers/fixpipe"
    exit 0
fi

if [ ! -f "$DL/$MESA_ORIG" ] || \
   ! echo "$MESA_SHA256  $DL/$MESA_ORIG" | sha256sum -c --status; then
    echo "fixpipe: fetching Debian source package mesa=$MESA_DEB_VERSION" >&2
    (cd "$DL" && apt-get source --download-only "mesa=$MESA_DEB_VERSION" >/dev/null 2>&1) || {
        echo "fixpipe: 'apt-get source mesa=$MESA_DEB_VERSION' failed (is there a deb-src entry? run tools/install-deps.sh)" >&2
        exit 1
    }
fi
if ! echo "$MESA_SHA256  $DL/$MESA_ORIG" | sha256sum -c --status; then
    echo "fixpipe: $DL/$MESA_ORIG does not match the pinned sha256 $MESA_SHA256" >&2
    exit 1
fi

rm -rf "$SRC" "$SRC.tmp"
mkdir -p "$SRC.tmp"
tar -xzf "$DL/$MESA_ORIG" -C "$SRC.tmp" --strip-components=1
for p in "$REPO"/mesa/patches/*.patch; do
    patch -d "$SRC.tmp" -p1 --quiet --forward < "$p" || {
        echo "fixpipe: $p does not apply to Mesa $MESA_VERSION" >&2
        exit 1
    }
done
ln -sfn "$DRIVER_SRC" "$SRC.tmp/src/gallium/drivers/fixpipe"
echo "$stamp" > "$SRC.tmp/.fixpipe-stamp"
mv "$SRC.tmp" "$SRC"
