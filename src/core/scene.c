/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * scene.c - the applied loads of a scene and their closed forms (see
 * scene.h).  The scene's defaults and derived values are in
 * scene_defaults.c, its keys in scene_keys.c (table), scene_keys_text.c
 * (a value as text), scene_keyinfo.c (typed access), scene_error.c (errors
 * as data), scene_set.c (reading a value), scene_validate.c and
 * scene_panel.c.
 *
 * Loads (paper, second study, eqs. ramp .. u_2), generalised by constant
 * forces F1, F2 and gravity g along -n1:
 *     S(w) = 0 (w < 0), (1 - cos pi w)/2 (0 <= w <= 1), 1 (w > 1)
 *     a(t) = v_m0 / T_s S'(t / T_s)
 *     F_e1 = F1 - m1 g - ramp (F_e0 (1 + S(t/T_e)) + m1 a(t))
 *     F_e2 = F2 - m2 g + ramp (F_e0 (1 + S(t/T_e)) - m2 a(t))
 * whence, in the full system, exactly (gravity and a(t) cancel):
 *     F_er = (m2 F_e1 - m1 F_e2)/(m1 + m2) = eta_c F1 - eta F2 - ramp F_e0 (1 + S(t/T_e))
 * and in the reduced system F_er = F_e1.
 */
#include <math.h>
#include <stddef.h>

#include "hybounce/scene.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* ---------------------------------------------------------------- */
/* Loads */

static double
ramp_S(double w)
{
	if (w < 0)
		return 0;
	if (w > 1)
		return 1;
	return 0.5 * (1.0 - cos(M_PI * w));
}

static double
ramp_Sd(double w)
{
	if (w < 0 || w > 1)
		return 0;
	return 0.5 * M_PI * sin(M_PI * w);
}

/* The drawing force of the ramp, F_e0 (1 + S(t/T_e)). */
static double
ramp_draw(const struct hb_scene *sc, double t)
{
	return sc->loads.Fe0 * (1.0 + ramp_S(t / sc->loads.Te));
}

/* a(t) = v_m0 / T_s S'(t / T_s) (eq. a_of_t). */
static double
ramp_a(const struct hb_scene *sc, double t)
{
	return sc->init.vm0 / sc->loads.Ts * ramp_Sd(t / sc->loads.Ts);
}

void
hb_scene_loads_at(const struct hb_scene *sc, double t, double *Fe1, double *Fe2)
{
	const struct hb_scene_loads *L = &sc->loads;
	double m1 = sc->d.m1, m2 = sc->d.m2;
	double f1 = L->F1 - m1 * L->g, f2 = 0;

	if (L->ramp)
		f1 -= ramp_draw(sc, t) + m1 * ramp_a(sc, t);
	if (sc->d.system == HB_SCENE_FULL) {
		f2 = L->F2 - m2 * L->g;
		if (L->ramp)
			f2 += ramp_draw(sc, t) - m2 * ramp_a(sc, t);
	}
	if (Fe1 != NULL)
		*Fe1 = f1;
	if (Fe2 != NULL)
		*Fe2 = f2;
}

/* The constant part of F_er. */
static double
fer_const(const struct hb_scene *sc)
{
	if (sc->d.system == HB_SCENE_FULL)
		return sc->d.etac * sc->loads.F1 - sc->d.eta * sc->loads.F2;
	return sc->loads.F1 - sc->d.m1 * sc->loads.g;
}

double
hb_scene_Fer(const struct hb_scene *sc, double t)
{
	double f = fer_const(sc);

	if (sc->loads.ramp) {
		f -= ramp_draw(sc, t);
		if (sc->d.system != HB_SCENE_FULL)
			f -= sc->d.m1 * ramp_a(sc, t);
	}
	return f;
}

int
hb_scene_load_kinks(const struct hb_scene *sc, double t0, double t1, double *out, int max)
{
	double k[2];
	int nk = 0, cnt = 0;

	if (!sc->loads.ramp)
		return 0;
	k[0] = sc->loads.Te;
	k[1] = sc->loads.Ts;
	if (k[1] < k[0]) {
		double tt = k[0];
		k[0] = k[1];
		k[1] = tt;
	}
	nk = k[0] == k[1] ? 1 : 2;
	for (int i = 0; i < nk; i++)
		if (k[i] > t0 && k[i] < t1 && cnt < max)
			out[cnt++] = k[i];
	return cnt;
}

int
hb_scene_Fer_constant(const struct hb_scene *sc, double t0, double t1)
{
	(void)t1;
	if (!sc->loads.ramp)
		return 1;
	if (t0 < sc->loads.Te)
		return 0;
	/* In the reduced system the m1 a(t) term is present until T_s. */
	if (sc->d.system != HB_SCENE_FULL && sc->init.vm0 != 0 && t0 < sc->loads.Ts)
		return 0;
	return 1;
}

/*
 * For one piece [a, b] and f(s) = cos(w s) (sine = 0) or sin(w s)
 * (sine = 1), writes I0 = int_a^b f and I1 = int_a^b (b - s) f, in forms
 * free of cancellation for short pieces: with u = b - s and h = b - a,
 *     I1 = cos(w b) Ic + sin(w b) Is            (cosine)
 *     I1 = sin(w b) Ic - cos(w b) Is            (sine)
 *     Ic = int_0^h u cos(w u) du,  Is = int_0^h u sin(w u) du
 * summed as series when w h < 1.
 */
static void
piece_trig(double w, double a, double b, int sine, double *I0, double *I1)
{
	double h = b - a, th = w * h, Ic, Is, mid = 0.5 * w * (a + b);
	double sh = sin(0.5 * th);

	if (fabs(th) < 1.0) {
		/* th^2 sum (-1)^(k+1) th^(2k-2) (2k-1)/(2k)!, th^3 sum (-1)^(k+1) th^(2k-2) 2k/(2k+1)! */
		double sc_ = 0, ss = 0, pw = 1, fc = 2, fs = 6; /* (2k)!, (2k+1)! at k = 1 */
		for (int k = 1; k <= 12; k++) {
			double sg = (k % 2) ? 1 : -1;
			sc_ += sg * pw * (2 * k - 1) / fc;
			ss += sg * pw * (2 * k) / fs;
			pw *= th * th;
			fc *= (2 * k + 1) * (2 * k + 2);
			fs *= (2 * k + 2) * (2 * k + 3);
		}
		Ic = h * h * sc_;
		Is = h * h * th * ss;
	} else {
		Ic = (th * sin(th) - 2.0 * sh * sh) / (w * w);
		Is = (sin(th) - th * cos(th)) / (w * w);
	}
	if (!sine) {
		*I0 = 2.0 * cos(mid) * sh / w;   /* (sin wb - sin wa)/w */
		*I1 = cos(w * b) * Ic + sin(w * b) * Is;
	} else {
		*I0 = 2.0 * sin(mid) * sh / w;   /* (cos wa - cos wb)/w */
		*I1 = sin(w * b) * Ic - cos(w * b) * Is;
	}
}

/*
 * The integrals of F_er over a piece [a, b] on which it is smooth:
 * I0 = int_a^b F_er, I1 = int_a^b (b - s) F_er(s) ds.
 */
static void
fer_piece(const struct hb_scene *sc, double a, double b, double *I0, double *I1)
{
	double h = b - a, c = fer_const(sc), J0, J1;
	double mid = 0.5 * (a + b);

	*I0 = 0;
	*I1 = 0;
	if (sc->loads.ramp) {
		double Te = sc->loads.Te, Fe0 = sc->loads.Fe0;
		/* F_e0 (1 + S(s/T_e)): F_e0 before 0, 2 F_e0 after T_e,
		 * 3/2 F_e0 - F_e0/2 cos(pi s/T_e) between. */
		if (mid < 0)
			c -= Fe0;
		else if (mid > Te)
			c -= 2 * Fe0;
		else {
			c -= 1.5 * Fe0;
			piece_trig(M_PI / Te, a, b, 0, &J0, &J1);
			*I0 += 0.5 * Fe0 * J0;
			*I1 += 0.5 * Fe0 * J1;
		}
		if (sc->d.system != HB_SCENE_FULL && mid > 0 && mid < sc->loads.Ts) {
			/* m1 a(s) = m1 v_m0 / T_s (pi/2) sin(pi s / T_s) */
			double Ts = sc->loads.Ts, A = sc->d.m1 * sc->init.vm0 / Ts * 0.5 * M_PI;
			piece_trig(M_PI / Ts, a, b, 1, &J0, &J1);
			*I0 -= A * J0;
			*I1 -= A * J1;
		}
	}
	*I0 += c * h;
	*I1 += c * h * h / 2;
}

void
hb_scene_flight_increment(const struct hb_scene *sc, double t0, double t1, double *dx, double *dv)
{
	double cuts[4], x = 0, v = 0, a = t0;
	int nc = 0;

	if (sc->loads.ramp) {
		double k[3] = { 0, sc->loads.Te, sc->loads.Ts };
		for (int i = 0; i < 3; i++)
			if (k[i] > t0 && k[i] < t1)
				cuts[nc++] = k[i];
		for (int i = 1; i < nc; i++)
			for (int j = i; j > 0 && cuts[j] < cuts[j - 1]; j--) {
				double tt = cuts[j];
				cuts[j] = cuts[j - 1];
				cuts[j - 1] = tt;
			}
	}
	cuts[nc++] = t1;
	for (int i = 0; i < nc; i++) {
		double b = cuts[i], I0, I1;
		if (b <= a)
			continue;
		fer_piece(sc, a, b, &I0, &I1);
		v += I0;
		x += (t1 - b) * I0 + I1;
		a = b;
	}
	*dx = x / sc->d.m;
	*dv = v / sc->d.m;
}

/*
 * Eq. com in closed form: dv_m/dt = (F_e1 + F_e2)/(m1 + m2)
 *     = (F1 + F2)/(m1 + m2) - g - ramp a(t),
 * so v_m = v_m0 + c t - ramp v_m0 S(t/T_s) and
 * x_m = x_m0 + v_m0 t + c t^2/2 - ramp v_m0 int_0^t S(s/T_s) ds.
 */
void
hb_scene_com(const struct hb_scene *sc, double t, double *xm, double *vm)
{
	double c, x, v;

	if (sc->d.system != HB_SCENE_FULL) {
		*xm = 0;
		*vm = 0;
		return;
	}
	c = (sc->loads.F1 + sc->loads.F2) / (sc->d.m1 + sc->d.m2) - sc->loads.g;
	x = sc->init.xm0 + sc->init.vm0 * t + 0.5 * c * t * t;
	v = sc->init.vm0 + c * t;
	if (sc->loads.ramp && t > 0) {
		double Ts = sc->loads.Ts, iS;
		if (t <= Ts)
			iS = 0.5 * t - Ts / (2.0 * M_PI) * sin(M_PI * t / Ts);
		else
			iS = 0.5 * Ts + (t - Ts);
		x -= sc->init.vm0 * iS;
		v -= sc->init.vm0 * ramp_S(t / Ts);
	}
	*xm = x;
	*vm = v;
}
