/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * collisions.h - per-collision observables (paper eqs. t_d .. Lambda).
 *
 * Collision i is the contact occupying flow interval 2i + 1 that ends in a
 * separation; every quantity is read at (t, 2i + 1), before the jump.
 * x_c^max and F_c^max are located extrema (not sample maxima); W, J_Fc and
 * J_Fe are integrated with the contact's flow, to the integrator's accuracy.
 */
#ifndef HB_COLLISIONS_H
#define HB_COLLISIONS_H
#include "export.h"
HB_BEGIN_DECLS

struct hb_collision {
	long i;          /* 0, 1, ... */
	long j;          /* flow interval of the contact (2i + 1) */
	double te, ts;   /* commencement and separation, s */
	double td;       /* t_s - t_e */
	double tf;       /* flight that follows: t_e^{i+1} - t_s; NAN until known */
	double vi;       /* approach velocity v(t_e), m/s (negative) */
	double e;        /* -v(t_s) / v_i */
	double xcmax;    /* greatest |x_c|, m */
	double Fcmax;    /* greatest F_c, N */
	double xcr;      /* |x_c(t_s)|, m */
	double W;        /* -int F_c v dt, J */
	double JFc, JFe; /* impulses, N s */
	double Lambda;   /* J_Fe / J_Fc */
	double xcr_sum;  /* x_c^r summed over collisions 0 .. i (the thinned ones too), m */
	int complete;    /* 0 for the contact in progress (values so far, ts = now) */
	int k;           /* the interface's number (docs/chains.md: k joins bodies k and k + 1;
	                    0 the floor's); 1 in the full system, 0 in the reduced one */
};

HB_END_DECLS

#endif
