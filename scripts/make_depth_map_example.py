#!/usr/bin/env python3
"""Writes scenes/depth-map-dome.pgm, the example depth map of the depth_map scenes: a smooth dome
(a Gaussian bump, nearest at the centre) on a flat background, 48 x 36 pixels, binary 16-bit PGM
(P5, maxval 65535, big-endian). Gray 0 = depth_near_m, 65535 = depth_far_m (set per scene).
Run from the repository root: python3 scripts/make_depth_map_example.py"""
import math
import struct

W, H, MAXVAL = 48, 36, 65535
SIGMA = 0.28  # bump width as a fraction of the image width


def gray(x, y):
    u = (x + 0.5) / W - 0.5
    v = ((y + 0.5) / H - 0.5) * H / W
    bump = math.exp(-(u * u + v * v) / (2 * SIGMA * SIGMA))
    return round(MAXVAL * (1.0 - bump))


with open("scenes/depth-map-dome.pgm", "wb") as f:
    f.write(b"P5\n# rangesim example depth map: smooth dome, gray 0 = near, 65535 = far\n%d %d\n%d\n" % (W, H, MAXVAL))
    f.write(b"".join(struct.pack(">H", gray(x, y)) for y in range(H) for x in range(W)))
