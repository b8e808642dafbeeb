"""Synthetic test images for the comparison tests: a PNG writer (stdlib only) and a
base picture to plant known differences into; and a reader of 8-bit RGB(A) PNGs, the
snapshots eglretrace writes, for planting differences into real frames."""
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


def read_rgb(path):
    """(w, h, bytearray of R, G, B per pixel) of an 8-bit, non-interlaced RGB or RGBA
    PNG; None for anything else."""
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        return None
    pos, idat, hdr = 8, bytearray(), None
    while pos + 8 <= len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            hdr = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    if not hdr or hdr[2] != 8 or hdr[3] not in (2, 6) or hdr[6] != 0:
        return None
    w, h, bpp = hdr[0], hdr[1], 3 if hdr[3] == 2 else 4
    raw, stride = zlib.decompress(bytes(idat)), w * bpp
    prev, rows, i = bytearray(stride), [], 0
    for _ in range(h):
        ft, line = raw[i], bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b = prev[x]
            c = prev[x - bpp] if x >= bpp else 0
            if ft == 1:
                line[x] = (line[x] + a) & 255
            elif ft == 2:
                line[x] = (line[x] + b) & 255
            elif ft == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif ft == 4:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                pr = a if pa <= pb and pa <= pc else b if pb <= pc else c
                line[x] = (line[x] + pr) & 255
        rows.append(line)
        prev = line
    out = bytearray()
    for line in rows:
        out += line if bpp == 3 else bytes(v for k, v in enumerate(line) if k % 4 != 3)
    return w, h, out


def write_rgb(path, w, h, buf):
    """An 8-bit RGB PNG of `buf` (R, G, B per pixel)."""
    write_png(path, w, h, [tuple(buf[3 * k:3 * k + 3]) for k in range(w * h)], alpha=False)
