# SPDX-License-Identifier: MIT
# SPDX-FileCopyrightText: 2026 the meff authors
"""PNG images compared by geometry, for the tests that put meff's pictures side by side (meff
view's screenshot and meff render's frame; an SVG frame rasterized and the PNG frame)."""
import struct
import zlib

# DrawPalette::dynamicBody (0.90, 0.55, 0.45) half way to white: the fill of dynamic bodies,
# the same colour in every picture meff draws, flat inside each shape.
DYNAMIC_FILL = (242, 198, 185)


def read_png(path):
    """8-bit RGB or RGBA, not interlaced (what meff writes): rows of (r, g, b)."""
    with open(path, "rb") as f:
        data = f.read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and colour in (2, 6) and interlace == 0, path
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        previous = line
    return rows


def mask(rows, colour):
    """The pixels inside a fill: of the fill colour, and so are their four neighbours. An
    anti-aliased edge pixel of meff render's (a mix of outline, fill and background) can happen
    to come out near the fill colour; one in the middle of fill-coloured neighbours cannot."""
    def fill(x, y):
        if not (0 <= y < len(rows) and 0 <= x < len(rows[0])):
            return False
        p = rows[y][x]
        return max(abs(p[i] - colour[i]) for i in range(3)) <= 6
    return {(x, y) for y in range(len(rows)) for x in range(len(rows[0]))
            if fill(x, y) and fill(x - 1, y) and fill(x + 1, y) and fill(x, y - 1) and fill(x, y + 1)}


def far(points, other):
    """The points of `points` farther than one pixel (8-neighbourhood) from every point of
    `other`."""
    return [p for p in points
            if not any((p[0] + dx, p[1] + dy) in other for dx in (-1, 0, 1) for dy in (-1, 0, 1))]


def stray_fill_pixels(first, second, colour):
    """The inside-fill pixels of either image more than one pixel from the other's, and the
    two masks' sizes."""
    a, b = mask(first, colour), mask(second, colour)
    return far(a, b) + far(b, a), len(a), len(b)
