#!/usr/bin/env python3
"""Writes the small test images the image_map / bump_map / uv_mapping reference scenes use.

test16.png: 16x16 RGB, a colour ramp (red across, green down) with a blue diagonal stripe and
            a white border column, so orientation, repetition and interpolation all show.
bump16.png: 16x16 8-bit grey, a bright disc on a dark ground (a bump_map height).
pal8.png:   8x8 palette image of 4 entries (index = (x + y) % 4), for filter/transmit N.
"""
import struct, zlib

def chunk(kind, data):
    c = struct.pack(">I", len(data)) + kind + data
    return c + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)

def png(path, w, h, color_type, rows, palette=None):
    raw = b"".join(b"\x00" + bytes(r) for r in rows)
    out = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, color_type, 0, 0, 0))
    if palette:
        out += chunk(b"PLTE", bytes(sum(palette, [])))
    out += chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b"")
    open(path, "wb").write(out)

rows = []
for y in range(16):
    r = []
    for x in range(16):
        if x == 15:
            r += [255, 255, 255]
        elif abs(x - y) <= 1:
            r += [20, 40, 230]
        else:
            r += [x * 17, y * 17, 40]
    rows.append(r)
png("test16.png", 16, 16, 2, rows)

rows = []
for y in range(16):
    rows.append([230 if (x - 7.5) ** 2 + (y - 7.5) ** 2 < 30 else 30 for x in range(16)])
png("bump16.png", 16, 16, 0, rows)

pal = [[255, 0, 0], [0, 255, 0], [0, 0, 255], [255, 255, 0]]
png("pal8.png", 8, 8, 3, [[(x + y) % 4 for x in range(8)] for y in range(8)], pal)

# The JPEGs are made by Pillow (not the standard library), so they are committed as made:
#   test16.jpg: test16.png at quality 95, no chroma subsampling (Image.save(.., "JPEG",
#               quality=95, subsampling=0));
#   hill.jpg:   32x32 grey stored as RGB, v = 255 (0.5 + 0.5 cos(r / 6)) exp(-r² / 300), r from
#               the centre (15.5, 15.5), quality 90 (a height_field);
#   halves.jpg: 16x8 grey (one component), black left half, white right half, quality 95;
#   red.jpg:    16x16 RGB pure red, quality 95, no chroma subsampling.
