#!/usr/bin/env python3
"""Writes media_df3.df3, the density file of media_df3.pov: 8x8x8 voxels, 8 bits each.

DF3 layout (POV-Ray): three big-endian 16-bit sizes (x, y, z), then the voxels, x fastest, then y, then z.
The content is asymmetric so that axis or orientation mistakes show: a ramp rising along x, a ring of dense voxels
in the middle z layers, one bright voxel in a corner and a hollow (zero) column along z.
"""
import os
import struct

N = 8
here = os.path.dirname(os.path.abspath(__file__))
data = bytearray()
for z in range(N):
    for y in range(N):
        for x in range(N):
            v = 20 + 20 * x                                   # ramp along x: 20 … 160
            r2 = (x - 3.5) ** 2 + (y - 3.5) ** 2
            if 3 <= z <= 4 and 4 <= r2 <= 9:
                v = 255                                        # a dense ring around the z axis
            if (x, y) in ((5, 2), (5, 3)):
                v = 0                                          # an empty column along z
            if (x, y, z) == (0, 7, 0):
                v = 255                                        # one bright corner voxel
            data.append(min(v, 255))
with open(os.path.join(here, "media_df3.df3"), "wb") as f:
    f.write(struct.pack(">HHH", N, N, N) + bytes(data))
