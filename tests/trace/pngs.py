"""Synthetic test images for the comparison tests: a PNG writer (stdlib only) and a
base picture to plant known differences into."""
import struct
import zlib


def write_png(path, w, h, px, alpha=True):
    """px: list of (r, g, b, a) rows top to bottom, w*h tuples in row order."""
    raw = bytearray()
    for y in range(h):
        raw.append(0)
        for x in range(w):
            p = px[y * w + x]
            raw += bytes(p if alpha else p[:3])

    def chunk(kind, data):
        c = struct.pack(">I", len(data)) + kind + data
        return c + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

    hdr = struct.pack(">IIBBBBB", w, h, 8, 6 if alpha else 2, 0, 0, 0)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", hdr) + chunk(b"IDAT", zlib.compress(bytes(raw)))
                + chunk(b"IEND", b""))


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
