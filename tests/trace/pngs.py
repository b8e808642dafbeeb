"""Synthetic test images for the comparison tests: a PNG writer and a base picture to
plant known differences into; and a reader of 8-bit RGB(A) PNGs, the snapshots
eglretrace writes, for planting differences into real frames.  PNG through Pillow
(Debian: python3-pil), so its importers run under /usr/bin/python3."""
from PIL import Image


def write_png(path, w, h, px, alpha=True):
    """px: list of (r, g, b, a) rows top to bottom, w*h tuples in row order; alpha=False
    drops the fourth value and writes RGB."""
    img = Image.new("RGBA" if alpha else "RGB", (w, h))
    img.putdata(px if alpha else [tuple(p[:3]) for p in px])
    img.save(path, format="PNG")


def base(w, h):
    """Mid-range values everywhere, so +-100 never clips."""
    return [(60 + (x * 3) % 120, 70 + (y * 5) % 110, 90 + ((x + y) * 7) % 80, 255)
            for y in range(h) for x in range(w)]


def plant(px, w, changes):
    """changes: {(x, y): (dr, dg, db, da)} -> a new list."""
    out = list(px)
    for (x, y), d in changes.items():
        p = out[y * w + x]
        out[y * w + x] = tuple(p[c] + d[c] for c in range(4))
        assert all(0 <= v <= 255 for v in out[y * w + x]), "a planted change clips"
    return out


def read_rgb(path):
    """(w, h, bytearray of R, G, B per pixel) of an RGB or RGBA PNG (alpha dropped);
    None for anything else."""
    try:
        with Image.open(path) as img:
            if img.format != "PNG" or img.mode not in ("RGB", "RGBA"):
                return None
            w, h = img.size
            return w, h, bytearray(img.convert("RGB").tobytes())
    except OSError:  # not an image Pillow reads
        return None


def write_rgb(path, w, h, buf):
    """An 8-bit RGB PNG of `buf` (R, G, B per pixel)."""
    Image.frombytes("RGB", (w, h), bytes(buf)).save(path, format="PNG")
