/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * solitary.h - the discrete chain's own solitary wave, solved from its
 * equations alone (no time stepping, nothing of the engine), to test the
 * engine's wave against (tests/test_chain.c; README, Chains).
 *
 * Beads of mass m on a line, overlaps d_i = u_(i-1) - u_i, F = k d^p:
 *
 *     d_i'' = (k / m) (d_(i+1)^p - 2 d_i^p + d_(i-1)^p).
 *
 * A travelling wave d_i(t) = D_m phi(i - c t) (c in beads a second,
 * max phi = 1) turns the second difference into a convolution: integrating
 * c^2 phi'' = (k / m) D_m^(p-1) Delta_2[phi^p] twice, with phi -> 0 far
 * away, gives
 *
 *     kappa phi = Lambda * phi^p,   Lambda(s) = max(1 - |s|, 0),
 *     kappa = m c^2 / (k D_m^(p-1))
 *
 * (in Fourier terms -q^2 and Delta_2's -4 sin^2(q/2) differ by the tent's
 * transform sinc^2(q/2)).  So c = sqrt(kappa k D_m^(p-1) / m) beads a
 * second, and with the bead's diameter a and the peak force F_m = k D_m^p,
 * for p = 3/2: V_s = sqrt(kappa) k^(1/3) a m^(-1/2) F_m^(1/6).  Nesterenko's
 * long-wave limit has kappa = 4/5 (V_s = (2 / sqrt 5) ...).
 *
 * The nonlinear eigenproblem psi = Lambda * psi^p is solved by
 * Petviashvili's iteration (psi <- M^(p/(p-1)) Lambda * psi^p, M the ratio
 * <psi, psi> / <psi, Lambda * psi^p>, which makes the fixed point
 * attracting) from Nesterenko's cos^4 profile, on a grid of n_per_bead
 * points a bead over [-half, half] beads; the tent is linear on [-1, 0] and
 * [0, 1], so Simpson's rule on each half is fourth order.  Then
 * phi = psi / psi(0) and kappa = psi(0)^(1-p).  The wave decays faster than
 * exponentially: at 8 beads from its peak it is below 1e-60 of it.
 *
 * Returns kappa, and in *rms the rms width of phi in beads (0 if it fails
 * to converge: then kappa is 0 too).
 */
#ifndef HB_TESTS_SOLITARY_H
#define HB_TESTS_SOLITARY_H

#include <math.h>
#include <stdlib.h>

static double
solitary_kappa(double p, int n_per_bead, int half, double *rms)
{
	int M = n_per_bead + n_per_bead % 2, n = 2 * half * M + 1, c = half * M;
	double h = 1.0 / M, gam = p / (p - 1), kappa = 0;
	double *psi = malloc((size_t)n * sizeof *psi), *g = malloc((size_t)n * sizeof *g);
	double *q = malloc((size_t)n * sizeof *q), *w = malloc((size_t)(2 * M + 1) * sizeof *w);

	*rms = 0;
	if (!psi || !g || !q || !w)
		goto out;
	for (int l = -M; l <= M; l++) { /* Simpson on [-1, 0] and on [0, 1], times the tent */
		int a = abs(l);
		double s = a == M ? 1 : a == 0 ? 2 : a % 2 ? 4 : 2;

		w[l + M] = s * h / 3 * (1 - (double)a / M);
	}
	for (int j = 0; j < n; j++) {
		double z = sqrt(10.0) * (j - c) * h / 5;

		psi[j] = fabs(z) < M_PI / 2 ? pow(cos(z), 4) : 0;
	}
	for (int it = 0; it < 500; it++) {
		double a = 0, b = 0, d = 0, f;

		for (int j = 0; j < n; j++)
			g[j] = pow(fmax(psi[j], 0.0), p);
		for (int j = 0; j < n; j++) {
			int lo = j < M ? -j : -M, hi = j + M >= n ? n - 1 - j : M;
			double s = 0;

			for (int l = lo; l <= hi; l++)
				s += w[l + M] * g[j + l];
			q[j] = s;
		}
		for (int j = 0; j < n; j++) {
			a += psi[j] * psi[j];
			b += psi[j] * q[j];
		}
		f = pow(a / b, gam);
		for (int j = 0; j < n; j++) {
			double v = f * q[j];

			d = fmax(d, fabs(v - psi[j]));
			psi[j] = v;
		}
		if (it > 10 && d <= 1e-14 * psi[c]) {
			double m0 = 0, m2 = 0;

			for (int j = 0; j < n; j++) {
				m0 += psi[j];
				m2 += psi[j] * ((j - c) * h) * ((j - c) * h);
			}
			*rms = sqrt(m2 / m0);
			kappa = pow(psi[c], 1 - p);
			break;
		}
	}
out:
	free(psi);
	free(g);
	free(q);
	free(w);
	return kappa;
}

#endif
