/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fit_param.c - the free parameters of a fit: reading a numeric scene key,
 * its admissible range, and the transform theta(u) that keeps every trial
 * inside that range (see fit.h).  Values, units and ranges come from the
 * scene's typed accessors (hb_scene_get); values are written back with
 * hb_scene_set_number(), which checks them and keeps the scene's invariants
 * (derived masses, k).
 */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "hybounce/fit.h"
#include "hybounce/status.h"
#include "fit_impl.h"

/* 1 if the key can be free: a typed number of the scene, not a run setting. */
static int
fittable(const struct hb_scene_keyinfo *ki)
{
	return ki->kind == HB_SCENE_KEY_NUMBER && !ki->readonly
	    && strncmp(ki->key, "run.", 4) != 0 && strncmp(ki->key, "derived.", 8) != 0;
}

/* "law.c, law.alpha, body1.E, ..." : the keys of this scene that can be free. */
static void
accepted(const struct hb_scene *sc, char *buf, size_t n)
{
	struct hb_scene_keyinfo row, ki;
	size_t len;

	buf[0] = '\0';
	for (int i = 0; i < hb_scene_nkeys(sc); i++) {
		if (hb_scene_key(sc, i, &row) != HB_OK || hb_scene_get(sc, row.key, &ki, NULL) != HB_OK
		    || !fittable(&ki))
			continue;
		len = strlen(buf);
		snprintf(buf + len, n - len, "%s%s", len ? ", " : "", ki.key);
	}
}

/* The typed value of a key that can be free, or HB_EINVAL with a message. */
static int
find(const struct hb_scene *sc, const char *key, struct hb_scene_keyinfo *ki, char *msg, size_t n)
{
	char acc[640];

	if (hb_scene_get(sc, key, ki, NULL) == HB_OK && fittable(ki))
		return HB_OK;
	accepted(sc, acc, sizeof acc);
	if (strcmp(key, "law.k") == 0 || strncmp(key, "derived.", 8) == 0)
		return hb_status_set(msg, n, HB_EINVAL, "%s is derived from the materials (Hertz "
		    "contact theory); free body1.E or body2.E instead, or give masses instead of "
		    "materials to make k a parameter; accepted: %s", key, acc);
	return hb_status_set(msg, n, HB_EINVAL, "%s: not a numeric key that can be fitted; "
	    "accepted: %s", key, acc);
}

int
hb_fit_key_get(const struct hb_scene *sc, const char *key, double *v, char *msg, size_t n)
{
	struct hb_scene_keyinfo ki;

	if (find(sc, key, &ki, msg, n) != HB_OK)
		return HB_EINVAL;
	*v = ki.number;
	return HB_OK;
}

/*
 * Sets up free parameter fp for key in scene sc: its range, its transform
 * and its starting u.  Refuses derived values and starts on or outside the
 * range's bounds (the transform cannot reach them).
 */
int
fit_param_init(const struct hb_scene *sc, const char *key, struct fit_param *fp,
               char *msg, size_t n)
{
	struct hb_scene_keyinfo ki;
	double v;

	memset(fp, 0, sizeof *fp);
	snprintf(fp->key, sizeof fp->key, "%s", key);
	if (find(sc, key, &ki, msg, n) != HB_OK)
		return HB_EINVAL;
	v = ki.number;
	fp->beta = -1;
	fp->lo = ki.limits.lo;
	fp->hi = ki.limits.hi;
	if (strcmp(key, "law.gamma") == 0 && hb_law_param_index(sc->law, "beta") >= 0
	    && sc->law->check != NULL) {
		fp->beta = hb_law_param_index(sc->law, "beta");
		fp->lo = -HUGE_VAL; /* bounded by beta through the transform */
		fp->hi = HUGE_VAL;
	}
	if (strncmp(key, "body", 4) == 0 && (key[4] == '1' || key[4] == '2') && key[5] == '.') {
		const struct hb_scene_body *b = &sc->body[key[4] - '1'];
		const char *f = key + 6;

		if ((strcmp(f, "E") == 0 || strcmp(f, "nu") == 0) && !b->has_material)
			return hb_status_set(msg, n, HB_EINVAL, "%s: body %c is given by its mass, "
			    "not a material; accepted: a key the scene uses", key, key[4]);
		if (strcmp(f, "rho") == 0 && (b->mass_given || !(b->rho > 0)))
			return hb_status_set(msg, n, HB_EINVAL, "%s: the mass of body %c is "
			    "given, not derived from rho; free %.6s.mass instead", key, key[4], key);
		if (strcmp(f, "mass") == 0 && !b->mass_given)
			return hb_status_set(msg, n, HB_EINVAL, "%s: the mass of body %c is "
			    "derived from rho and R; free %.6s.rho instead", key, key[4], key);
	}
	if (!isfinite(v))
		return hb_status_set(msg, n, HB_EINVAL, "%s = %g: a free parameter needs a finite "
		    "start", key, v);
	if (fp->beta >= 0) {
		double b = sc->par[fp->beta];

		if (!(b > 0) || !(fabs(v) < b))
			return hb_status_set(msg, n, HB_EINVAL, "%s = %g: the start must lie inside "
			    "(-beta, beta) = (%g, %g); set another with --set", key, v, -b, b);
		fp->u0 = atanh(v / b);
		return HB_OK;
	}
	if (!(v > fp->lo) || !(v < fp->hi))
		return hb_status_set(msg, n, HB_EINVAL, "%s = %g: the start must lie inside the "
		    "range (%g, %g), not on a bound; set another with --set", key, v, fp->lo,
		    fp->hi);
	fp->k = 1;
	if (isfinite(fp->lo) && isfinite(fp->hi)) {
		/*
		 * The rate k: the logistic's slope at the start is at most the
		 * start's magnitude, else a range of 2e5 m/s would turn a
		 * difference step of 1e-6 in u into 0.05 m/s of v0.
		 */
		double s0 = (v - fp->lo) / (fp->hi - fp->lo), slope = (fp->hi - fp->lo) * s0 * (1 - s0);
		double mag = v != 0 ? fabs(v) : 1;

		if (slope > mag)
			fp->k = mag / slope;
		fp->u0 = -log((fp->hi - fp->lo) / (v - fp->lo) - 1) / fp->k;
	}
	else if (isfinite(fp->lo))
		fp->u0 = log(v - fp->lo);
	else if (isfinite(fp->hi))
		fp->u0 = -log(fp->hi - v);
	else
		fp->u0 = v;
	return HB_OK;
}

/* theta(u) and d theta / d u for a parameter without a beta link. */
static double
theta_of(const struct fit_param *fp, double u, double *dth)
{
	double t;

	if (isfinite(fp->lo) && isfinite(fp->hi)) {
		double s = 1 / (1 + exp(-fp->k * u));

		t = fp->lo + (fp->hi - fp->lo) * s;
		*dth = fp->k * (fp->hi - fp->lo) * s * (1 - s);
		/* the logistic rounds to a bound far out; stay strictly inside */
		if (!(t > fp->lo))
			t = nextafter(fp->lo, fp->hi);
		if (!(t < fp->hi))
			t = nextafter(fp->hi, fp->lo);
		return t;
	}
	if (isfinite(fp->lo)) {
		*dth = exp(u);
		t = fp->lo + *dth;
		return t > fp->lo ? t : nextafter(fp->lo, HUGE_VAL);
	}
	if (isfinite(fp->hi)) {
		*dth = exp(-u);
		t = fp->hi - *dth;
		return t < fp->hi ? t : nextafter(fp->hi, -HUGE_VAL);
	}
	*dth = 1;
	return u;
}

/*
 * Writes theta(u) of every free parameter into sc (gamma after beta) and
 * fills th[] and the transform's Jacobian T[i * np + j] = d theta_i / d u_j.
 * Returns 0 or HB_EINVAL with hb_scene_set's message.
 */
int
fit_param_apply(struct hb_scene *sc, const struct fit_param *fp, int np, const double *u,
                double *th, double *T, char *msg, size_t n)
{
	struct hb_scene_error err;
	char m[512];
	double d;

	if (T != NULL)
		memset(T, 0, (size_t)np * (size_t)np * sizeof *T);
	for (int pass = 0; pass < 2; pass++)
		for (int i = 0; i < np; i++) {
			if ((fp[i].beta >= 0) != (pass == 1))
				continue;
			if (fp[i].beta >= 0) {
				double b = sc->par[fp[i].beta], tu = tanh(u[i]);

				th[i] = b * tu;
				d = b * (1 - tu * tu);
				for (int j = 0; T != NULL && j < np; j++)
					if (strcmp(fp[j].key, "law.beta") == 0)
						T[i * np + j] = tu * T[j * np + j];
			} else {
				th[i] = theta_of(&fp[i], u[i], &d);
			}
			if (T != NULL)
				T[i * np + i] = d;
			if (hb_scene_set_number(sc, fp[i].key, th[i], &err) != HB_OK)
				return hb_status_set(msg, n, HB_EINVAL, "%s",
				    hb_scene_error_str(&err, m, sizeof m));
		}
	return hb_scene_derive(sc, msg, n);
}
