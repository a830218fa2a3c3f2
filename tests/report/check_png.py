#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Checks that a PNG screenshot is not blank, with the standard library only.

Usage: check_png.py FILE.png WIDTH
Decodes the chunks, inflates the image data and counts scanlines whose filtered bytes take more than
four distinct values: a uniform row, whatever PNG filter the encoder chose, filters to at most a few
(zero differences plus the first pixel). A page with plots and tables has many such "inked" rows; a
blank or failed render has none.
"""
import struct
import sys
import zlib


def main(path, width):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"FAIL: {path} is not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    w, h, depth, colour = header[:4]
    if w != width:
        sys.exit(f"FAIL: {path} is {w} px wide, expected {width}")
    channels = {0: 1, 2: 3, 4: 2, 6: 4}.get(colour, 1)
    stride = 1 + w * channels * depth // 8
    raw = zlib.decompress(idat)
    inked = sum(1 for r in range(h) if len(set(raw[r * stride + 1:(r + 1) * stride])) > 4)
    if inked < 0.05 * h:
        sys.exit(f"FAIL: {path} looks blank ({inked} of {h} rows hold more than flat colour)")
    print(f"{path}: {w}x{h}, {inked} of {h} rows inked")


if __name__ == "__main__":
    main(sys.argv[1], int(sys.argv[2]))
