#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""agree.py - how far a collision table is from a reference table.

    agree.py REF.csv OTHER.csv [--rows N] [--limit L] [--errors]

Both files are collision CSVs (hybounce --collisions, or hybounce-ref);
lines starting with '#' are skipped.  For each column the largest error
over the first N rows (default: the rows both have) is printed as
"column error", in the measure the error bars use: t_e and t_s relative
to the collision's t_d, x_c_r relative to x_c_max, W relative to the
larger of |W| and |J_Fc v_i|, every other value relative to its own size.
Read in decimal (28 digits), so that a binary128
reference is compared to its last digits.

--limit L: exit 1 when an error exceeds L.
--max: print only the largest error over every column and row (1 when
the two files have a different number of collisions and --rows is not
given).
--errors: OTHER carries error columns (NAME_err, hybounce --error); for
each estimated value print the ratio estimate / true error (both in the
measure above) and exit 1 when one is below 1/2 or above 100.  Where the
true error is below 1e-13 (500 ulps: double rounding, which neither run
resolves) only an estimate above 100 x 1e-13 is refused.
"""
import sys
from decimal import Decimal, getcontext

getcontext().prec = 40


def read(path):
    rows, head = [], None
    with open(path) as f:
        for line in f:
            line = line.strip()
            if not line or line.startswith("#") or line.startswith(";"):
                continue
            cells = line.split(",")
            if head is None:
                head = cells
                continue
            rows.append({h: c for h, c in zip(head, cells)})
    return head, rows


def num(s):
    try:
        d = Decimal(s)
    except Exception:
        return None
    return None if d.is_nan() else d


def scale(col, row):
    """The size an error in col is measured against."""
    if col in ("t_e", "t_s"):
        return abs(num(row["t_d"]))
    if col == "x_c_r":
        return abs(num(row["x_c_max"]))
    if col == "W":
        return max(abs(num(row["W"])), abs(num(row["J_Fc"]) * num(row["v_i"])))
    return abs(num(row[col]))


def main(argv):
    args = argv[1:]
    nrows = limit = errfile = None
    only_max = False
    files = []
    while args:
        a = args.pop(0)
        if a == "--rows":
            nrows = int(args.pop(0))
        elif a == "--limit":
            limit = Decimal(args.pop(0))
        elif a == "--max":
            only_max = True
        elif a == "--errors":
            errfile = True
        else:
            files.append(a)
    if len(files) != 2:
        sys.stderr.write(__doc__)
        return 2
    h1, ref = read(files[0])
    h2, oth = read(files[1])
    n = min(len(ref), len(oth)) if nrows is None else nrows
    if n > min(len(ref), len(oth)) or n == 0:
        print(f"agree.py: {n} rows asked, the files have {len(ref)} and {len(oth)}")
        return 1
    cols = [c for c in h1 if c != "i" and c in h2]
    worst = Decimal(0)
    bad = tested = 0
    for c in cols:
        e = Decimal(0)
        for r in range(n):
            a, b = num(ref[r][c]), num(oth[r][c])
            if a is None or b is None:
                continue
            s = scale(c, ref[r])
            if s == 0:
                continue
            e = max(e, abs(a - b) / s)
        if not only_max:
            print(f"{c} {float(e):.3g}")
        worst = max(worst, e)
        if errfile and c + "_err" in h2:
            for r in range(n):
                a, b = num(ref[r][c]), num(oth[r][c])
                est = num(oth[r][c + "_err"])
                if a is None or b is None or est is None:
                    continue
                s = scale(c, ref[r])
                if s == 0:
                    continue
                true = abs(a - b) / s
                estr = est / s
                floor = Decimal("1e-13")
                ratio = estr / true if true > 0 else Decimal("Infinity")
                ok = True
                if true > floor:
                    ok = Decimal("0.5") <= ratio <= 100
                    tested += 1
                elif estr > 100 * floor:
                    ok = False
                print(f"  {c}[{r}] true {float(true):.3g} estimate {float(estr):.3g} "
                      f"ratio {float(ratio):.3g}{'' if ok else '  OUTSIDE [0.5, 100]'}")
                if not ok:
                    bad += 1
    if limit is not None and worst > limit:
        print(f"agree.py: largest error {float(worst):.3g} exceeds {float(limit):.3g}")
        return 1
    if only_max:
        print(f"{float(worst if nrows is not None or len(ref) == len(oth) else 1):.3g}")
    if errfile:
        print(f"agree.py: {tested} estimates of a true error above 1e-13, {bad} outside")
    if bad:
        print(f"agree.py: {bad} estimates outside [0.5, 100] x the true error")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
