#!/usr/bin/env python3
"""Writes the density files of pattern_density_file.pov (DF3: three big-endian 16-bit sizes x, y, z, then the
voxels, big-endian, x fastest, then y, then z; POV-Ray tells the voxel width from the file's length).

- pattern_density_file_8.df3: 5x6x7 voxels of 8 bits, a hashed pattern (neighbouring voxels differ a lot, so the
  three interpolations look very different; the tricubic overshoots above 1 and below 0). The sizes are not powers
  of two: POV-Ray's tricubic lookup wraps below the first voxel to (2^64 - 1) % size, not to size - 1.
- pattern_density_file_16.df3: 6x5x4 voxels of 16 bits, a smooth wave whose low bytes matter (values that are not
  multiples of 257), with one cold and one hot voxel.
"""
import math
import os
import struct

here = os.path.dirname(os.path.abspath(__file__))


def write(name, sizes, width, value):
    sx, sy, sz = sizes
    fmt = {1: "B", 2: "H"}[width]
    voxels = [value(x, y, z) for z in range(sz) for y in range(sy) for x in range(sx)]
    with open(os.path.join(here, name), "wb") as f:
        f.write(struct.pack(">HHH", sx, sy, sz))
        f.write(struct.pack(">%d%s" % (len(voxels), fmt), *voxels))


def hashed(x, y, z):
    return (37 * x + 53 * y + 71 * z + 13 * x * y * z + 7 * x * x) % 256


def wave(x, y, z):
    if (x, y, z) == (1, 3, 2):
        return 0
    if (x, y, z) == (4, 1, 1):
        return 65535
    v = 0.5 + 0.45 * math.sin(1.3 * x + 0.7 * y) * math.cos(1.1 * z + 0.4)
    return int(round(v * 65535))


write("pattern_density_file_8.df3", (5, 6, 7), 1, hashed)
write("pattern_density_file_16.df3", (6, 5, 4), 2, wave)
