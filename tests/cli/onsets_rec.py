#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
# onsets_rec.py - a recording of a bouncing sequence whose truth is known,
# for tests/cli/onsets.sh: reads hybounce's --collisions CSV (t_e, v_i) on
# stdin, writes raw 32-bit float samples (sox converts them to the formats
# tested) and the true onset times, one per line.
#
#   onsets_rec.py OUT.f32 TRUTH.txt [key=value ...]
#
# keys: sr (Hz), ch (channels), pre, post (s of digital silence), snr (dB of
# pink noise below the first impact's peak; none: no noise), reverb (s,
# RT60; 0 none), ring (s: a long-ringing low mode), knock (s, a handling
# knock at that time after the first impact, repeatable as knock2), blip
# (a faint blip, s before the first impact), gap (shortest interval kept,
# s), even (N clicks at even intervals instead: no bouncing sequence),
# geom=T0,e (instead: intervals from T0 s shrinking by e down to gap),
# damp (a factor on the modes' decay times), seed.  Each impact: three damped modes, its loudness from its speed.
import sys
import numpy as np


def main():
    out, truth = sys.argv[1], sys.argv[2]
    kv = dict(a.split('=', 1) for a in sys.argv[3:])
    sr = int(kv.get('sr', 44100))
    ch = int(kv.get('ch', 1))
    pre = float(kv.get('pre', 0.2))
    post = float(kv.get('post', 0.3))
    gap = float(kv.get('gap', 0.003))
    rng = np.random.default_rng(int(kv.get('seed', 1)))
    rows = [ln.split(',') for ln in sys.stdin.read().split('\n')[1:] if ln]
    te = [float(r[1]) for r in rows]
    vi = [abs(float(r[5])) for r in rows]
    t, v = [te[0]], [vi[0]]
    for a, b in zip(te[1:], vi[1:]):
        if a - t[-1] < gap:
            break
        t.append(a)
        v.append(b)
    if 'geom' in kv:  # intervals from T0 shrinking by e, down to gap
        T0, e = (float(a) for a in kv['geom'].split(','))
        t, v, T = [0.0], [1.0], T0
        while T >= gap:
            t.append(t[-1] + T)
            v.append(v[-1] * e)
            T *= e
    if 'even' in kv:  # no bouncing: clicks at even intervals, all as loud
        t, v = [0.25 * i for i in range(int(kv['even']))], [1.0] * int(kv['even'])
    t = np.array(t) - t[0] + pre
    n = int((t[-1] + post + 0.05 + float(kv.get('ring', 0))) * sr)
    x = np.zeros(n)
    d = float(kv.get('damp', 1))  # scales the modes' decay times
    modes = [(2300.0, 0.004 * d, 0.5), (3900.0, 0.002 * d, 0.3), (6100.0, 0.001 * d, 0.2)]
    if 'ring' in kv:
        modes.append((900.0, float(kv['ring']), 0.05))
    for ti, vv in zip(t, v):
        amp = 0.9 * (vv / v[0]) ** 1.2
        i0 = int(np.ceil(ti * sr))
        tt = np.arange(i0, min(n, i0 + int(0.5 * sr))) / sr - ti
        click = sum(a * np.sin(2 * np.pi * f * tt) * np.exp(-tt / tau) for f, tau, a in modes)
        x[i0:i0 + len(tt)] += amp * click / 0.62
    for k in ('knock', 'knock2'):
        if k in kv:
            tk = t[0] + float(kv[k])
            i0 = int(tk * sr)
            tt = np.arange(0, int(0.08 * sr)) / sr
            x[i0:i0 + len(tt)] += 0.6 * np.sin(2 * np.pi * 180 * tt) * np.exp(-tt / 0.015)
    if 'blip' in kv:
        i0 = int((t[0] - float(kv['blip'])) * sr)
        x[i0:i0 + 20] += 0.01 * np.sin(np.arange(20) * 0.7)
    rt = float(kv.get('reverb', 0))
    if rt > 0:
        m = int(rt * sr)
        ir = rng.standard_normal(m) * np.exp(-6.9 * np.arange(m) / m) * 0.006
        x = x + np.convolve(x, ir)[:n]
    xc, nrms = x.copy(), 0.0
    if 'snr' in kv:
        w = np.fft.rfft(rng.standard_normal(n))
        f = np.arange(len(w)) + 1.0
        p = np.fft.irfft(w / np.sqrt(f), n)
        p *= (0.9 / 10 ** (float(kv['snr']) / 20)) / np.sqrt(np.mean(p ** 2))
        s0, s1 = int(pre * 0.5 * sr), int((t[-1] + post * 0.5) * sr)
        x[s0:s1] += p[s0:s1]
        nrms = float(np.sqrt(np.mean(p ** 2)))
    y = np.stack([x * (1.0 - 0.2 * c) for c in range(ch)], axis=1)
    y = np.clip(y, -0.999, 0.999).astype('<f4')
    y.tofile(out)
    # each click's SNR: its peak over the rms of all else sounding as it
    # starts: the noise, and the ring and reverberation of the clicks before
    # (their rms over the 1 ms before it)
    with open(truth, 'w') as fh:
        for ti, vv in zip(t, v):
            i0 = int(np.ceil(ti * sr))
            before = xc[max(0, i0 - sr // 1000):i0]
            pk = np.max(np.abs(xc[i0:i0 + sr // 500] - xc[i0 - 1] * 0))
            rms = np.sqrt(np.mean(before ** 2) + nrms ** 2) if len(before) else nrms
            snr = 'inf' if rms == 0 else '%.2f' % (20 * np.log10(pk / rms))
            fh.write('%.7f %s\n' % (ti, snr))


main()
