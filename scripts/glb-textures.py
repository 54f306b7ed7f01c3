#!/usr/bin/env python3
"""Pulls the PNG textures out of a glb and lays them side by side, each tiled 2 x 2 (so a
seam would show), into one PNG: glb-textures.py IN.glb OUT.png. Python's standard library
only; reads 8-bit RGB/RGBA non-interlaced PNGs (what corbel writes)."""
import json, struct, sys, zlib


def read_png(data):
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat, w = 8, b"", 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, color = struct.unpack(">IIBB", body[:10])
            assert depth == 8 and color in (2, 6), "only 8-bit RGB/RGBA"
            ch = 3 if color == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw, rows, stride, prev = zlib.decompress(idat), [], w * ch, bytearray(w * ch)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - ch] if i >= ch else 0
            b, c = prev[i], prev[i - ch] if i >= ch else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line[k] for x in range(w) for k in (x * ch, x * ch + 1, x * ch + 2)))
        prev = line
    return w, h, rows


def write_png(path, w, h, rows):
    chunk = lambda k, b: struct.pack(">I", len(b)) + k + b + struct.pack(">I", zlib.crc32(k + b))
    raw = b"".join(b"\x00" + r for r in rows)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


glb = open(sys.argv[1], "rb").read()
jlen = struct.unpack("<I", glb[12:16])[0]
gltf = json.loads(glb[20:20 + jlen])
binary = glb[20 + jlen + 8:]
tiles = []
for im in gltf.get("images", []):
    v = gltf["bufferViews"][im["bufferView"]]
    off = v.get("byteOffset", 0)
    tiles.append((im.get("name", ""), read_png(binary[off:off + v["byteLength"]])))
    print(im.get("name", ""), tiles[-1][1][0], "x", tiles[-1][1][1])
size, gap = max(t[1][0] for t in tiles), 8
W = len(tiles) * (2 * size + gap) - gap
out = []
for y in range(2 * size):
    row = b""
    for i, (_, (w, h, rows)) in enumerate(tiles):
        r = rows[y % h] if y < 2 * h else b"\xff" * 3 * w
        row += (r * 2)[:6 * size].ljust(6 * size, b"\xff") + (b"\xff" * 3 * gap if i + 1 < len(tiles) else b"")
    out.append(row)
write_png(sys.argv[2], W, 2 * size, out)
