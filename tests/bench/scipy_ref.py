#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""scipy_ref.py - the paper's own method, re-implemented for a side-by-side
benchmark (make bench-scipy; tests/bench/scipy.sh).

The paper (section Simulation, Background) integrates "each flow interval
by the routine solve_ivp of SciPy with the method DOP853, the relative
tolerance 1e-11, the absolute tolerance 1e-14, and the step size bounded
above. A jump is taken when the indicator of the flow set changes sign
within a step; the state at the located event is first advanced along the
flow, by the least interval that a derivative-free search finds, into the
jump set with a small margin."  Its code is not available here, so this is
that method written as a careful researcher would write it in plain
NumPy/SciPy:

  * the model of the paper's section Model, literally: the state of H_r is
    (x, v, x_c, z_c) and that of H_f (x, v, x_m, v_m, x_c, z_c), q_c a
    parameter of the right-hand side; f, C, D and g of eqs. Hr_f .. H_D;
    the laws SHCCL, BWSHCCL (ex. bwshc) and BWMCL (ex. bwm) continued
    beyond x_c = 0 by their own formulas (rule R1, extension = adhesive);
    k from Hertz theory by eq. k_hertz; the loads of the second study
    (eqs. ramp .. u_2) and gravity;
  * every flow interval is one solve_ivp(method='DOP853', rtol=1e-11,
    atol=1e-14, max_step=H_MAX) call on a plain Python right-hand side; the
    kinks of |v|, |Psi_2|, |z| and |x_c| are integrated through, as SciPy
    does (the step control rejects and shrinks);
  * leaving the flow set is a terminal event on its indicator: max(x, v)
    falling through 0 in flight, min(Phi, v) rising through 0 in contact;
    SciPy locates it by brentq on the step's dense output;
  * the located state is advanced along the flow (one DOP853 step of the
    trial length) by the least interval of a doubling search (0, 1, 2, 4
    ... ulps of t) that puts it strictly inside the jump set D; then g;
  * the extrema x_c^max and F_c^max of a contact are the largest |x_c| and
    -Phi over the accepted steps and over non-terminal events at v = 0 and
    dPhi/dt = 0 (located by SciPy as above).

The step bound: the paper gives none (only "bounded above"); hybounce's
counterpart run.h_max is 0 (none) in every paper preset.  H_MAX = 1 ms is
used: it never binds inside a contact at these tolerances (contact steps
are microseconds) and bounds the flights, where DOP853 on a parabola would
otherwise take steps as long as the flight.  --max-step changes it.

Usage:
  scipy_ref.py [--runs N] [--max-step S] [--csv FILE] [--against HB.csv]
               [--trace HBTRACE.csv] [--json FILE] PRESET
prints the collision table (as hybounce --batch --collisions writes it) on
standard output; --runs N times the simulation (integration, events and
jumps only: no import, no preset parsing) N times and reports the median;
--against compares every collision with hybounce's CSV.
"""

import configparser
import json
import math
import re
import statistics
import sys
import time

import numpy as np
from scipy.integrate import DOP853, solve_ivp

RTOL = 1e-11
ATOL = 1e-14
H_MAX = 1e-3

# ---------------------------------------------------------------------------
# Presets: INI files whose values carry SI-prefixed units.

PREFIX = {"G": 1e9, "M": 1e6, "k": 1e3, "": 1.0, "m": 1e-3, "u": 1e-6,
          "\u00b5": 1e-6, "n": 1e-9, "p": 1e-12, "f": 1e-15}
BASE = ("Pa", "m", "s", "N", "J", "g")


def quantity(text):
    """'200 GPa' -> 2e11, '20 mm' -> 0.02, '7800 kg/m^3' -> 7800, 'inf'."""
    text = text.strip()
    m = re.match(r"^([-+]?(?:inf|nan|[0-9.]+(?:[eE][-+]?[0-9]+)?))\s*(.*)$", text)
    if m is None:
        raise ValueError("not a quantity: %r" % text)
    value, unit = float(m.group(1)), m.group(2).strip()
    if not unit:
        return value
    first = re.split(r"[ /^]", unit)[0]
    if first == "kg":
        return value
    for base in BASE:
        if first.endswith(base) and first[:-len(base)] in PREFIX:
            if base == "g":
                return value * PREFIX[first[:-1]] * 1e-3
            return value * PREFIX[first[:-len(base)]]
    raise ValueError("unknown unit in %r" % text)


class Model:
    """The scene of a preset: parameters, derived constants, loads, law."""

    def __init__(self, path):
        ini = configparser.ConfigParser(inline_comment_prefixes=(";", "#"),
                                        comment_prefixes=(";", "#"))
        ini.optionxform = str
        with open(path, encoding="utf-8") as f:
            ini.read_file(f)

        def get(sec, key, default=None):
            if ini.has_option(sec, key):
                return quantity(ini.get(sec, key))
            if default is None:
                raise KeyError("%s: [%s] %s is missing" % (path, sec, key))
            return default

        self.law = ini.get("scene", "law").strip()
        if self.law not in ("shccl", "bwshccl", "bwmcl"):
            raise ValueError("%s: law %s is not one of the paper's" % (path, self.law))
        ext = ini.get("scene", "extension", fallback="adhesive").strip()
        if ext != "adhesive":
            raise ValueError("%s: only extension = adhesive (the presets') is written here" % path)

        # Bodies: m_i = 4/3 pi R^3 rho; R2 = inf without rho is a fixed obstacle.
        E1, nu1, rho1, R1 = (get("body1", k) for k in ("E", "nu", "rho", "R"))
        E2, nu2, R2 = (get("body2", k) for k in ("E", "nu", "R"))
        self.m1 = 4.0 / 3.0 * math.pi * R1 ** 3 * rho1
        self.full = math.isfinite(R2)
        if self.full:
            self.m2 = 4.0 / 3.0 * math.pi * R2 ** 3 * get("body2", "rho")
            self.m = self.m1 * self.m2 / (self.m1 + self.m2)
            self.eta = self.m1 / (self.m1 + self.m2)
        else:
            self.m2 = math.inf
            self.m = self.m1
            self.eta = 0.0
        Estar = 1.0 / ((1 - nu1 ** 2) / E1 + (1 - nu2 ** 2) / E2)
        Re = 1.0 / (1.0 / R1 + 1.0 / R2)
        self.kH = 4.0 / 3.0 * Estar * math.sqrt(Re)

        self.p = get("law", "p")
        self.c = get("law", "c")
        if self.law == "shccl":
            self.k = self.kH
        else:
            self.A = get("law", "A")
            self.alpha = get("law", "alpha")
            self.beta = get("law", "beta")
            self.gamma = get("law", "gamma")
            self.n = get("law", "n")
            # eq. k_hertz
            self.k = self.kH / (self.alpha + (1 - self.alpha) * self.A ** self.p)

        self.g = get("loads", "g", 0.0)
        self.F1 = get("loads", "F1", 0.0)
        self.F2 = get("loads", "F2", 0.0)
        self.ramp = ini.get("loads", "ramp", fallback="no").strip() in ("yes", "1", "true", "on")
        if self.ramp:
            self.Fe0 = get("loads", "F_e0")
            self.Te = get("loads", "T_e")
            self.Ts = get("loads", "T_s")

        self.x0 = get("initial", "x0")
        self.v0 = get("initial", "v0", 0.0)
        self.xm0 = get("initial", "x_m0", 0.0)
        self.vm0 = get("initial", "v_m0", 0.0)
        self.T = get("run", "T")

        # State layout: H_f (x, v, x_m, v_m, x_c, z), H_r (x, v, x_c, z).
        self.nz = {"shccl": 0, "bwshccl": 1, "bwmcl": 2}[self.law]
        self.ic = 4 if self.full else 2
        self.size = self.ic + 1 + self.nz

    # --- loads (eqs. ramp, ramp_d, a_of_t, u_1, u_2, u) -----------------

    def loads(self, t):
        """F_e1, F_e2 at t."""
        Fe1 = self.F1 - self.m1 * self.g
        Fe2 = self.F2 - self.m2 * self.g if self.full else 0.0
        if self.ramp:
            w = t / self.Te
            S = 0.0 if w < 0 else 1.0 if w > 1 else 0.5 * (1 - math.cos(math.pi * w))
            w = t / self.Ts
            Sd = 0.5 * math.pi * math.sin(math.pi * w) if 0 <= w <= 1 else 0.0
            a = self.vm0 / self.Ts * Sd
            draw = self.Fe0 * (1 + S)
            Fe1 -= draw + self.m1 * a
            if self.full:
                Fe2 += draw - self.m2 * a
        return Fe1, Fe2

    def Fer(self, t):
        Fe1, Fe2 = self.loads(t)
        if self.full:
            return (self.m2 * Fe1 - self.m1 * Fe2) / (self.m1 + self.m2)
        return Fe1

    # --- the contact law: Phi, Psi and dPhi/dt -----------------------------

    def phi(self, xc, z, v):
        """Phi(x_c, z_c, v); works on scalars and on NumPy arrays."""
        k, p = self.k, self.p
        if self.law == "shccl":
            return k * xc * abs(xc) ** (p - 1) + self.c * abs(xc) ** p * v
        if self.law == "bwshccl":
            a = self.alpha
            return (a * k * xc * abs(xc) ** (p - 1)
                    + (1 - a) * k * z[0] * abs(z[0]) ** (p - 1)
                    + self.c * abs(xc) ** p * v)
        a = self.alpha   # bwmcl: z = (z_c1, z_c2)
        return a * k * z[1] * abs(z[1]) ** (p - 1) + (1 - a) * k * z[0] * abs(z[0]) ** (p - 1)

    def psi(self, xc, z, v):
        """dz_c/dt = Psi(x_c, z_c, v) as a list."""
        A, beta, gamma, n = self.A, self.beta, self.gamma, self.n
        if self.law == "bwshccl":
            z1 = z[0]
            return [A * v - beta * z1 * abs(z1) ** (n - 1) * abs(v) - gamma * abs(z1) ** n * v]
        z1 = z[0]
        psi2 = v - self.phi(xc, z, v) / self.c
        psi1 = A * psi2 - beta * z1 * abs(z1) ** (n - 1) * abs(psi2) - gamma * abs(z1) ** n * psi2
        return [psi1, psi2]

    def dphi_dt(self, xc, z, v, dv, dz):
        """dPhi/dt along the flow (dx_c/dt = v, dv/dt = dv, dz/dt = dz)."""
        k, p = self.k, self.p
        if self.law == "bwmcl":
            a = self.alpha
            return (a * k * p * abs(z[1]) ** (p - 1) * dz[1]
                    + (1 - a) * k * p * abs(z[0]) ** (p - 1) * dz[0])
        ke = k if self.law == "shccl" else self.alpha * k
        r = (ke * p * abs(xc) ** (p - 1) * v
             + self.c * p * math.copysign(abs(xc) ** (p - 1), xc) * v * v
             + self.c * abs(xc) ** p * dv)
        if self.law == "bwshccl":
            r += (1 - self.alpha) * k * p * abs(z[0]) ** (p - 1) * dz[0]
        return r

    # --- the hybrid system ----------------------------------------------

    def rhs(self, t, y, q):
        """f of eq. Hr_f (reduced) or H_f (full), q_c given."""
        v = y[1]
        ic = self.ic
        if self.full:
            Fe1, Fe2 = self.loads(t)
            Fer = (self.m2 * Fe1 - self.m1 * Fe2) / (self.m1 + self.m2)
            head = [v, 0.0, y[3], (Fe1 + Fe2) / (self.m1 + self.m2)]
        else:
            Fer = self.loads(t)[0]
            head = [v, 0.0]
        if q:
            xc, z = y[ic], y[ic + 1:]
            head[1] = (-self.phi(xc, z, v) + Fer) / self.m
            return head + [v] + (self.psi(xc, z, v) if self.nz else [])
        head[1] = Fer / self.m
        return head + [0.0] * (1 + self.nz)

    def indicator(self, y, q):
        """>= 0 in C, < 0 strictly outside it (then y is in D)."""
        if q:
            return -min(self.phi(y[self.ic], y[self.ic + 1:], y[1]), y[1])
        return max(y[0], y[1])

    def in_D(self, y, q):
        """Strictly inside the jump set D (eq. H_D): the small margin."""
        if q:
            return self.phi(y[self.ic], y[self.ic + 1:], y[1]) > 0 and y[1] > 0
        return y[0] < 0 and y[1] < 0


def simulate(model, h_max=H_MAX):
    """The paper's method over [0, T]: returns (collisions, end, stats)."""
    mo = model
    ic = mo.ic

    def leave_flight(t, y, q):
        return max(y[0], y[1])
    leave_flight.terminal = True
    leave_flight.direction = -1

    def leave_contact(t, y, q):
        return min(mo.phi(y[ic], y[ic + 1:], y[1]), y[1])
    leave_contact.terminal = True
    leave_contact.direction = 1

    def xc_extremum(t, y, q):          # v = 0: |x_c| greatest
        return y[1]
    xc_extremum.direction = 1

    def fc_extremum(t, y, q):          # dPhi/dt = 0: -Phi greatest
        f = mo.rhs(t, y, q)
        return mo.dphi_dt(y[ic], y[ic + 1:], y[1], f[1], f[ic + 1:])
    fc_extremum.direction = 1

    y = np.zeros(mo.size)
    y[0], y[1] = mo.x0, mo.v0
    if mo.full:
        y[2], y[3] = mo.xm0, mo.vm0
    t, q, j = 0.0, 0, 0
    collisions = []
    stats = {"nfev": 0, "steps": 0, "intervals": 0, "advance_trials": 0, "advance_nfev": 0}
    te = vi = 0.0
    xcmax = fcmax = 0.0
    while t < mo.T:
        events = [leave_contact, xc_extremum, fc_extremum] if q else [leave_flight]
        sol = solve_ivp(mo.rhs, (t, mo.T), y, method="DOP853", rtol=RTOL, atol=ATOL,
                        max_step=h_max, events=events, args=(q,))
        if sol.status < 0:
            raise RuntimeError("solve_ivp failed at t = %.12g: %s" % (t, sol.message))
        stats["nfev"] += sol.nfev
        stats["steps"] += sol.t.size - 1
        stats["intervals"] += 1
        if q:
            Y = sol.y
            xcmax = max(xcmax, float(np.max(np.abs(Y[ic]))))
            fcmax = max(fcmax, float(np.max(-mo.phi(Y[ic], Y[ic + 1:], Y[1]))))
            for ye in list(sol.y_events[1]) + list(sol.y_events[2]):
                xcmax = max(xcmax, abs(ye[ic]))
                fcmax = max(fcmax, -mo.phi(ye[ic], ye[ic + 1:], ye[1]))
        if sol.status != 1:            # the horizon
            t, y = sol.t[-1], sol.y[:, -1]
            break
        # The event: advance along the flow into D, by the least interval of
        # a doubling search, each trial one DOP853 step of that length.
        tev, yev = sol.t_events[0][0], sol.y_events[0][0]
        dt, ynew = 0.0, yev
        while not mo.in_D(ynew, q):
            dt = math.ulp(tev) if dt == 0.0 else 2 * dt
            step = DOP853(lambda s, u: mo.rhs(s, u, q), tev, yev, tev + dt,
                          rtol=RTOL, atol=ATOL, first_step=dt)
            while step.status == "running":
                step.step()
            stats["nfev"] += step.nfev
            stats["advance_nfev"] += step.nfev
            stats["advance_trials"] += 1
            ynew = step.y
            if dt > 1e-6 * max(1.0, abs(tev)):
                raise RuntimeError("no state in D within 1e-6 s of the event at t = %.17g" % tev)
        t, y = tev + dt, ynew.copy()
        if q:
            xcmax = max(xcmax, abs(y[ic]))
            fcmax = max(fcmax, -mo.phi(y[ic], y[ic + 1:], y[1]))
            collisions.append((te, t, vi, -y[1] / vi, xcmax, fcmax))
        # g: x, v (x_m, v_m) unchanged, x_c = z_c = 0, q_c = 1 - q_c.
        y[ic:] = 0.0
        q = 1 - q
        j += 1
        if q:
            te, vi = t, y[1]
            xcmax = fcmax = 0.0
    end = {"t": t, "j": j, "q": q, "y": list(map(float, y))}
    if q:
        end["in_progress"] = (te, vi, xcmax, fcmax)
    return collisions, end, stats


COLUMNS = ("i", "t_e", "t_s", "t_d", "v_i", "e", "x_c_max", "F_c_max")


def read_hybounce_csv(path):
    """Rows of hybounce --collisions CSV as dicts of floats."""
    with open(path, encoding="utf-8") as f:
        head = f.readline().strip().split(",")
        return [dict(zip(head, map(float, line.split(",")))) for line in f if line.strip()]


def compare(cols, hb):
    """Largest relative differences, per observable, over the collisions."""
    out = {"n_scipy": len(cols), "n_hybounce": len(hb)}
    keys = {"t_e": 0, "t_s": 1, "e": 3, "x_c_max": 4, "F_c_max": 5}
    for name, k in keys.items():
        d = [abs(c[k] - r[name]) / abs(r[name]) for c, r in zip(cols, hb)]
        out[name] = max(d) if d else float("nan")
    # event times also against the contact's duration t_d, as make bench does
    d = [max(abs(c[0] - r["t_e"]), abs(c[1] - r["t_s"])) / r["t_d"] for c, r in zip(cols, hb)]
    out["t_over_td"] = max(d) if d else float("nan")
    return out


def main(argv):
    global RTOL, ATOL
    runs, h_max, csv, against, trace, jout = 0, H_MAX, None, None, None, None
    args = list(argv[1:])
    path = None
    while args:
        a = args.pop(0)
        if a == "--runs":
            runs = int(args.pop(0))
        elif a == "--rtol":
            RTOL = float(args.pop(0))
        elif a == "--atol":
            ATOL = float(args.pop(0))
        elif a == "--max-step":
            h_max = float(args.pop(0))
        elif a == "--csv":
            csv = args.pop(0)
        elif a == "--against":
            against = args.pop(0)
        elif a == "--trace":
            trace = args.pop(0)
        elif a == "--json":
            jout = args.pop(0)
        elif a.startswith("-"):
            sys.exit("scipy_ref.py: unknown option %s (see the head of the file)" % a)
        else:
            path = a
    if path is None:
        sys.exit("usage: scipy_ref.py [--runs N] [--max-step S] [--csv FILE] "
                 "[--against HB.csv] [--trace HBTRACE.csv] [--json FILE] PRESET")

    model = Model(path)
    cols, end, stats = simulate(model, h_max)
    result = {"preset": path, "law": model.law, "system": "full" if model.full else "reduced",
              "k": model.k, "m": model.m, "h_max": h_max, "collisions": len(cols),
              "end": end, "stats": stats}

    print("# %s: %s, %s system, k = %.6g N m^-p, m = %.6g kg; DOP853 rtol %g atol %g, "
          "max_step %g s" % (path, model.law, result["system"], model.k, model.m,
                             RTOL, ATOL, h_max))
    print("# %d flow intervals, %d steps, %d rhs evaluations (%d in %d trials advancing into D)"
          % (stats["intervals"], stats["steps"], stats["nfev"], stats["advance_nfev"],
             stats["advance_trials"]))
    lines = [",".join(COLUMNS)]
    for i, (te, ts, vi, e, xm, fm) in enumerate(cols):
        lines.append("%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g"
                     % (i, te, ts, ts - te, vi, e, xm, fm))
    print("\n".join(lines))
    if csv:
        with open(csv, "w", encoding="utf-8") as f:
            f.write("\n".join(lines) + "\n")
    if "in_progress" in end:
        te, vi, xm, fm = end["in_progress"]
        print("# contact in progress at T: t_e = %.17g, v_i = %.17g, x_c^max = %.17g, "
              "F_c^max = %.17g" % (te, vi, xm, fm))
    print("# end state: t = %.17g, j = %d, q_c = %d, x = %.17g, v = %.17g"
          % (end["t"], end["j"], end["q"], end["y"][0], end["y"][1]))

    if against:
        d = compare(cols, read_hybounce_csv(against))
        result["against"] = d
        print("# against hybounce: %d / %d collisions; largest relative differences: "
              "t_e %.2g, t_s %.2g, e %.2g, x_c^max %.2g, F_c^max %.2g; "
              "event times / t_d %.2g" % (d["n_scipy"], d["n_hybounce"], d["t_e"], d["t_s"],
                                          d["e"], d["x_c_max"], d["F_c_max"], d["t_over_td"]))
    if trace:
        with open(trace, encoding="utf-8") as f:
            head = f.readline().strip().split(",")
            last = None
            for line in f:
                if line.strip():
                    last = line
        r = dict(zip(head, map(float, last.split(","))))
        dx = abs(end["y"][0] - r["x"]) / abs(r["x"])
        dv = abs(end["y"][1] - r["v"]) / abs(r["v"])
        result["end_vs_hybounce"] = {"x": dx, "v": dv, "j_scipy": end["j"], "j_hybounce": r["j"]}
        print("# end state against hybounce: j %d / %d, relative difference x %.2g, v %.2g"
              % (end["j"], r["j"], dx, dv))

    if runs > 0:
        wall, cpu = [], []
        for _ in range(runs):
            w0, c0 = time.perf_counter(), time.process_time()
            simulate(model, h_max)
            wall.append(time.perf_counter() - w0)
            cpu.append(time.process_time() - c0)
        result["wall_s"] = statistics.median(wall)
        result["cpu_s"] = statistics.median(cpu)
        result["runs"] = runs
        print("# simulation time (median of %d): %.2f ms wall, %.2f ms CPU"
              % (runs, 1e3 * result["wall_s"], 1e3 * result["cpu_s"]))
    if jout:
        with open(jout, "w", encoding="utf-8") as f:
            json.dump(result, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
