#!/usr/bin/env python3
"""Writes the small PNG images that the image_map / uv_mapping / bump_map scenes of scenes/ read.

Every image is computed here from simple formulas (no third-party data), with Python's zlib only, so running
this script again reproduces the committed files byte for byte:  python3 scripts/make_texture_images.py
The images cover the PNG layouts povtrace reads for image maps: 8- and 16-bit RGB, RGBA, grey, palette with a
tRNS chunk, and the gamma chunks (none, gAMA, sRGB) that decide how POV-Ray decodes them.
"""
import os
import struct
import zlib

SCENES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scenes")


def chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


def write_png(name, width, height, colour_type, bit_depth, rows, palette=None, trns=None, gamma=None, srgb=False):
    """rows: one list of samples per row (already in the file's channel order and bit depth)."""
    raw = bytearray()
    for row in rows:
        raw.append(0)  # filter type None
        if bit_depth == 16:
            for s in row:
                raw += struct.pack(">H", s)
        elif bit_depth == 8:
            raw += bytes(row)
        else:  # packed sub-byte samples (palette or grey), most significant bits first
            per_byte = 8 // bit_depth
            for i in range(0, len(row), per_byte):
                b = 0
                for j in range(per_byte):
                    s = row[i + j] if i + j < len(row) else 0
                    b |= s << (8 - bit_depth * (j + 1))
                raw.append(b)
    out = b"\x89PNG\r\n\x1a\n"
    out += chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, bit_depth, colour_type, 0, 0, 0))
    if srgb:
        out += chunk(b"sRGB", bytes([0]))
    if gamma is not None:
        out += chunk(b"gAMA", struct.pack(">I", int(round(gamma * 100000))))
    if palette is not None:
        out += chunk(b"PLTE", bytes(c for entry in palette for c in entry))
    if trns is not None:
        out += chunk(b"tRNS", bytes(trns))
    out += chunk(b"IDAT", zlib.compress(bytes(raw), 9))
    out += chunk(b"IEND", b"")
    with open(os.path.join(SCENES, name), "wb") as f:
        f.write(out)


def rgb_test_card(width, height, scale):
    """A colourful card: red rises to the right, green upwards, blue in a diagonal stripe; a white top-left
    corner pixel and a black bottom-right one mark the orientation."""
    rows = []
    for y in range(height):
        row = []
        for x in range(width):
            r = (x * (scale - 1)) // (width - 1)
            g = ((height - 1 - y) * (scale - 1)) // (height - 1)
            b = (scale - 1) if (x + y) % 3 == 0 else (scale - 1) // 4
            if (x, y) == (0, 0):
                r = g = b = scale - 1
            if (x, y) == (width - 1, height - 1):
                r = g = b = 0
            row += [r, g, b]
        rows.append(row)
    return rows


def main():
    # 8 x 6 RGB, no gamma chunk: POV-Ray 3.7 takes it as sRGB.
    write_png("tex_rgb.png", 8, 6, 2, 8, rgb_test_card(8, 6, 256))
    # The same card with a gAMA chunk of 1.0 (linear values) and as 16-bit with an sRGB chunk.
    write_png("tex_linear.png", 8, 6, 2, 8, rgb_test_card(8, 6, 256), gamma=1.0)
    write_png("tex_rgb16.png", 8, 6, 2, 16, rgb_test_card(8, 6, 65536), srgb=True)
    # 6 x 6 RGBA: a colour gradient whose alpha runs 0 .. 255 from left to right, opaque in the top row.
    rows = []
    for y in range(6):
        row = []
        for x in range(6):
            alpha = 255 if y == 0 else (x * 255) // 5
            row += [40 * x + 30, 200 - 30 * y, 128, alpha]
        rows.append(row)
    write_png("tex_rgba.png", 6, 6, 6, 8, rows)
    # 8 x 4 palette image (4 bits per index) whose tRNS chunk makes entry 2 half and entry 3 fully transparent.
    palette = [(255, 40, 40), (40, 220, 40), (60, 60, 255), (250, 250, 60), (240, 240, 240), (20, 20, 20)]
    rows = [[(x + 2 * y) % len(palette) for x in range(8)] for y in range(4)]
    write_png("tex_palette.png", 8, 4, 3, 4, rows, palette=palette, trns=[255, 255, 128, 0])
    # 8 x 8 greys: an 8-bit ramp and a 16-bit one (bump_map and grey image maps).
    rows = [[((x * 8 + y) * 255) // 63 for x in range(8)] for y in range(8)]
    write_png("tex_grey.png", 8, 8, 0, 8, rows)
    rows = [[(((x - 3.5) ** 2 + (y - 3.5) ** 2) * 65535) // 25 if (x - 3.5) ** 2 + (y - 3.5) ** 2 < 25 else 65535
             for x in range(8)] for y in range(8)]
    write_png("tex_grey16.png", 8, 8, 0, 16, [[int(v) for v in r] for r in rows])
    # 24 x 18 palette image (8 bits per index) for a height field: POV-Ray takes the index as the height, so the
    # palette's colours run against the indices (index 0 white, 255 black) and only the indices form the hill.
    palette = [(255 - i, (i * 7) % 256, i) for i in range(256)]
    rows = [[min(255, int(255 * max(0.0, 1.0 - ((x - 11.5) ** 2 + (y - 8.5) ** 2) / 110.0) + 20 * ((x + y) % 3)))
             for x in range(24)] for y in range(18)]
    write_png("height_field_palette.png", 24, 18, 3, 8, rows, palette=palette)


if __name__ == "__main__":
    main()
