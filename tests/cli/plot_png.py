# SPDX-License-Identifier: GPL-3.0-or-later
"""plot_png.py - reads a PNG of `hybounce plot` as a reader would
(tests/cli/plot.sh): decodes it with zlib alone and prints what it sees.

    python3 plot_png.py info FILE.png
        size W H           the image
        ink N              pixels that are not white
        panels N           frames (black rectangles) found
        frame L R T B      each frame, in pixels (rows from the top)
        legend N           pixels that are not white above the first frame
        legend_style K N   pixels there nearest colour K of the palette
                           (black, grey and white left out), where N >= 5
        legend_shade N     pixels of the contact shade there
    python3 plot_png.py bar FILE.png
        (a heat map: the first frame is the map, its colour legend the
        coloured strip right of it)
        bar_bottom R G B / bar_top R G B
                           the legend's colours at its ends
        bar_rising 1|0     its grey level (0.299 R + 0.587 G + 0.114 B)
                           rises from bottom to top (to within 3)
        bar_grey_span N    top's grey level less bottom's
        map_top N / map_bottom N
                           pixels in the map within 12 of those colours
    python3 plot_png.py shade FILE.png COLLISIONS.csv T_END
        hit N / miss N     collisions whose middle (t_e + t_s) / 2 lies on
                           a shaded pixel column (in one of the frames; the
                           t axis is the first frame's, 0 to T_END)
        flight_clear N / flight_shaded N
                           flights (t_s to the next t_e, at least 6 pixels
                           wide) whose middle column is not shaded / is
"""
import struct
import sys
import zlib

SHADE = (217, 217, 217)   # plot_shade_rgb 0.85
# the palette's colours, in the order of src/cli/plot_model.c (Okabe-Ito)
PALETTE = [(0, 114, 178), (213, 94, 0), (0, 158, 115), (204, 121, 167),
           (230, 159, 0), (86, 180, 233), (0, 0, 0), (240, 228, 66)]


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise SystemExit("not a PNG: " + path)
    pos, idat, w = 8, b"", 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, ctype = struct.unpack(">IIBB", body[:10])
            if depth != 8 or ctype not in (2, 6):
                raise SystemExit("unexpected PNG type %d/%d" % (depth, ctype))
            bpp = 3 if ctype == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw = zlib.decompress(idat)
    stride = w * bpp
    rows, prev, i = [], bytearray(stride), 0
    for _ in range(h):
        f = raw[i]
        line = bytearray(raw[i + 1:i + 1 + stride])
        i += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b = prev[x]
            c = prev[x - bpp] if x >= bpp else 0
            if f == 1:
                line[x] = (line[x] + a) & 255
            elif f == 2:
                line[x] = (line[x] + b) & 255
            elif f == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pr = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                line[x] = (line[x] + pr) & 255
        rows.append([tuple(line[k:k + 3]) for k in range(0, stride, bpp)])
        prev = line
    return w, h, rows


def dark(p):
    return p[0] + p[1] + p[2] < 3 * 160 and max(p) - min(p) < 40


def frames(w, h, rows):
    """Black rectangles: rows with a long dark run are edges; an edge's
    runs at the same columns on two row groups make a frame."""
    edges = []   # (row, [(l, r), ...])
    for y in range(h):
        runs, x = [], 0
        r = rows[y]
        while x < w:
            if dark(r[x]):
                s = x
                while x < w and dark(r[x]):
                    x += 1
                if x - s >= w // 6:
                    runs.append((s, x - 1))
            x += 1
        if runs:
            edges.append((y, runs))
    # group consecutive rows, keep the first row's runs
    groups = []
    for y, runs in edges:
        if groups and y - groups[-1][1] <= 1:
            groups[-1][1] = y
        else:
            groups.append([y, y, runs])
    out = []
    used = set()
    for gi, (y0, y1, runs) in enumerate(groups):
        for (l, r) in runs:
            if (gi, l) in used:
                continue
            # the next group with a run at the same columns closes it
            for gj in range(gi + 1, len(groups)):
                m = [(l2, r2) for (l2, r2) in groups[gj][2]
                     if abs(l2 - l) <= 2 and abs(r2 - r) <= 2]
                if m:
                    used.add((gj, m[0][0]))
                    out.append((l, r, y0, groups[gj][1]))
                    break
    out.sort(key=lambda f: (f[2], f[0]))
    return out


def near(p, q, tol=4):
    return all(abs(a - b) <= tol for a, b in zip(p, q))


def is_shade(p):
    return p[0] == p[1] == p[2] and 190 <= p[0] <= 245


def info(path):
    w, h, rows = read_png(path)
    ink = sum(1 for r in rows for p in r if p != (255, 255, 255))
    fr = frames(w, h, rows)
    print("size %d %d" % (w, h))
    print("ink %d" % ink)
    print("panels %d" % len(fr))
    for f in fr:
        print("frame %d %d %d %d" % f)
    top = min(f[2] for f in fr) if fr else h
    # above the first frame, less its top tick label's upper half
    lim = max(0, top - max(4, h // 60))
    leg = [p for r in rows[:lim] for p in r if p != (255, 255, 255)]
    print("legend %d" % len(leg))
    counts = [0] * len(PALETTE)
    for p in leg:
        if max(p) - min(p) > 60:    # a colour, not black, grey or white
            d = [sum((a - b) ** 2 for a, b in zip(p, q)) for q in PALETTE]
            counts[d.index(min(d))] += 1
    for k, n in enumerate(counts):
        if n >= 5:
            print("legend_style %d %d" % (k, n))
    print("legend_shade %d" % sum(1 for p in leg if p == SHADE))


def shade(path, csv, t_end):
    w, h, rows = read_png(path)
    fr = frames(w, h, rows)
    l, r, t, b = fr[0]

    def col(tt):
        return l + tt / t_end * (r - l)

    def shaded(x):
        for dx in (-1, 0, 1):
            xx = int(round(x)) + dx
            # the middle rows of each frame (clear of its inward ticks):
            # the shade, or its antialiased edge, is a light grey
            for (fl, fr_, ft, fb) in fr:
                m = (fb - ft) // 5
                if fl < xx < fr_ and any(is_shade(rows[y][xx])
                                        for y in range(ft + m, fb - m)):
                    return True
        return False

    coll = []
    for line in open(csv):
        if line[0].isdigit():
            f = line.split(",")
            coll.append((float(f[1]), float(f[2])))
    hit = sum(1 for te, ts in coll if shaded(col((te + ts) / 2)))
    print("hit %d" % hit)
    print("miss %d" % (len(coll) - hit))
    clear = dirty = 0
    for (te, ts), (te2, _) in zip(coll, coll[1:]):
        if col(te2) - col(ts) >= 6:
            if shaded(col((ts + te2) / 2)):
                dirty += 1
            else:
                clear += 1
    print("flight_clear %d" % clear)
    print("flight_shaded %d" % dirty)


def grey(p):
    return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]


def bar(path):
    w, h, rows = read_png(path)
    fr = frames(w, h, rows)
    l, r, t, b = fr[0]
    mid = (t + b) // 2
    x = r + 2
    while x < w and max(rows[mid][x]) - min(rows[mid][x]) <= 40:
        x += 1
    x0 = x
    while x < w and max(rows[mid][x]) - min(rows[mid][x]) > 40:
        x += 1
    xc = (x0 + x) // 2
    col = [rows[y][xc] for y in range(b - 3, t + 3, -1)]   # bottom to top
    lo, hi = col[0], col[-1]
    print("bar_bottom %d %d %d" % lo)
    print("bar_top %d %d %d" % hi)
    g = [grey(p) for p in col]
    print("bar_rising %d" % all(g[k + 1] >= g[k] - 3 for k in range(len(g) - 1)))
    print("bar_grey_span %d" % (g[-1] - g[0]))
    inside = [rows[y][xx] for y in range(t + 2, b - 1) for xx in range(l + 2, r - 1)]
    print("map_top %d" % sum(1 for p in inside if near(p, hi, 12)))
    print("map_bottom %d" % sum(1 for p in inside if near(p, lo, 12)))


if __name__ == "__main__":
    if sys.argv[1] == "info":
        info(sys.argv[2])
    elif sys.argv[1] == "bar":
        bar(sys.argv[2])
    else:
        shade(sys.argv[2], sys.argv[3], float(sys.argv[4]))
