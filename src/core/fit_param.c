/*
 * fit_param.c - the free parameters of a fit: reading a numeric scene key,
 * its admissible range, and the transform theta(u) that keeps every trial
 * inside that range (see fit.h).  Values are written back with scene_set(),
 * which checks them and keeps the scene's invariants (derived masses, k).
 */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "hybounce/fit.h"
#include "hybounce/status.h"
#include "fit_impl.h"

/* The numeric keys that are not law parameters, with their ranges (scene.c). */
static const struct {
	const char *key;
	size_t off;
	double lo, hi;
} keys[] = {
#define OFF(f) offsetof(struct scene, f)
	{ "body1.E", OFF(body[0].E), 0, HUGE_VAL },
	{ "body1.nu", OFF(body[0].nu), -1, 0.5 },
	{ "body1.rho", OFF(body[0].rho), 0, HUGE_VAL },
	{ "body1.R", OFF(body[0].R), 0, HUGE_VAL },
	{ "body1.mass", OFF(body[0].mass), 0, HUGE_VAL },
	{ "body2.E", OFF(body[1].E), 0, HUGE_VAL },
	{ "body2.nu", OFF(body[1].nu), -1, 0.5 },
	{ "body2.rho", OFF(body[1].rho), 0, HUGE_VAL },
	{ "body2.R", OFF(body[1].R), 0, HUGE_VAL },
	{ "body2.mass", OFF(body[1].mass), 0, HUGE_VAL },
	{ "loads.g", OFF(loads.g), -HUGE_VAL, HUGE_VAL },
	{ "loads.F1", OFF(loads.F1), -HUGE_VAL, HUGE_VAL },
	{ "loads.F2", OFF(loads.F2), -HUGE_VAL, HUGE_VAL },
	{ "loads.F_e0", OFF(loads.Fe0), 0, HUGE_VAL },
	{ "loads.T_e", OFF(loads.Te), 0, HUGE_VAL },
	{ "loads.T_s", OFF(loads.Ts), 0, HUGE_VAL },
	{ "initial.x0", OFF(init.x0), 0, HUGE_VAL },
	{ "initial.v0", OFF(init.v0), -HUGE_VAL, HUGE_VAL },
	{ "initial.x_m0", OFF(init.xm0), -HUGE_VAL, HUGE_VAL },
	{ "initial.v_m0", OFF(init.vm0), -HUGE_VAL, HUGE_VAL },
#undef OFF
};

static void
accepted(const struct scene *sc, char *buf, size_t n)
{
	size_t len;

	snprintf(buf, n, "law.<parameter of %s>", sc->law != NULL ? sc->law->name : "the law");
	for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++) {
		len = strlen(buf);
		snprintf(buf + len, n - len, ", %s", keys[i].key);
	}
}

/* Finds key: fills *p (index into keys, or -1 - law parameter index). */
static int
find(const struct scene *sc, const char *key, int *p, char *msg, size_t n)
{
	char acc[640];

	if (strncmp(key, "law.", 4) == 0 && sc->law != NULL) {
		int i = law_param_index(sc->law, key + 4);

		if (i >= 0 && strcmp(sc->law->params[i].name, key + 4) == 0) {
			*p = -1 - i;
			return HB_OK;
		}
	}
	for (size_t i = 0; i < sizeof keys / sizeof keys[0]; i++)
		if (strcmp(keys[i].key, key) == 0) {
			*p = (int)i;
			return HB_OK;
		}
	accepted(sc, acc, sizeof acc);
	return status_set(msg, n, HB_EINVAL, "%s: not a numeric key that can be fitted; "
	    "accepted: %s", key, acc);
}

int
fit_key_get(const struct scene *sc, const char *key, double *v, char *msg, size_t n)
{
	int p;

	if (find(sc, key, &p, msg, n) != HB_OK)
		return HB_EINVAL;
	if (p < 0)
		*v = sc->par[-1 - p];
	else
		*v = *(const double *)((const char *)sc + keys[p].off);
	return HB_OK;
}

/*
 * Sets up free parameter fp for key in scene sc: its range, its transform
 * and its starting u.  Refuses derived values and starts on or outside the
 * range's bounds (the transform cannot reach them).
 */
int
fit_param_init(const struct scene *sc, const char *key, struct fit_param *fp,
               char *msg, size_t n)
{
	int p;
	double v = NAN;

	memset(fp, 0, sizeof *fp);
	snprintf(fp->key, sizeof fp->key, "%s", key);
	if (find(sc, key, &p, msg, n) != HB_OK)
		return HB_EINVAL;
	fit_key_get(sc, key, &v, msg, n);
	fp->beta = -1;
	if (p < 0) {
		const struct law_param *pp = &sc->law->params[-1 - p];

		if ((pp->flags & LAW_PARAM_STIFFNESS) && sc->d.k_derived)
			return status_set(msg, n, HB_EINVAL, "%s is derived from the materials by "
			    "eq. k_hertz; free body1.E or body2.E instead, or give masses instead of "
			    "materials to make k a parameter", key);
		fp->lo = pp->lo;
		fp->hi = pp->hi;
		if (strcmp(pp->name, "gamma") == 0 && law_param_index(sc->law, "beta") >= 0
		    && sc->law->check != NULL) {
			fp->beta = law_param_index(sc->law, "beta");
			fp->lo = -HUGE_VAL; /* bounded by beta through the transform */
			fp->hi = HUGE_VAL;
		}
	} else {
		fp->lo = keys[p].lo;
		fp->hi = keys[p].hi;
		if (strncmp(key, "body", 4) == 0) {
			const struct scene_body *b = &sc->body[key[4] - '1'];
			const char *f = key + 6;

			if ((strcmp(f, "E") == 0 || strcmp(f, "nu") == 0) && !b->has_material)
				return status_set(msg, n, HB_EINVAL, "%s: body %c is given by its mass, "
				    "not a material; accepted: a key the scene uses", key, key[4]);
			if (strcmp(f, "rho") == 0 && (b->mass_given || !(b->rho > 0)))
				return status_set(msg, n, HB_EINVAL, "%s: the mass of body %c is "
				    "given, not derived from rho; free %.6s.mass instead", key, key[4], key);
			if (strcmp(f, "mass") == 0 && !b->mass_given)
				return status_set(msg, n, HB_EINVAL, "%s: the mass of body %c is "
				    "derived from rho and R; free %.6s.rho instead", key, key[4], key);
		}
	}
	if (!isfinite(v))
		return status_set(msg, n, HB_EINVAL, "%s = %g: a free parameter needs a finite "
		    "start", key, v);
	if (fp->beta >= 0) {
		double b = sc->par[fp->beta];

		if (!(b > 0) || !(fabs(v) < b))
			return status_set(msg, n, HB_EINVAL, "%s = %g: the start must lie inside "
			    "(-beta, beta) = (%g, %g); set another with --set", key, v, -b, b);
		fp->u0 = atanh(v / b);
		return HB_OK;
	}
	if (!(v > fp->lo) || !(v < fp->hi))
		return status_set(msg, n, HB_EINVAL, "%s = %g: the start must lie inside the "
		    "range (%g, %g), not on a bound; set another with --set", key, v, fp->lo,
		    fp->hi);
	if (isfinite(fp->lo) && isfinite(fp->hi))
		fp->u0 = -log((fp->hi - fp->lo) / (v - fp->lo) - 1);
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
		double s = 1 / (1 + exp(-u));

		t = fp->lo + (fp->hi - fp->lo) * s;
		*dth = (fp->hi - fp->lo) * s * (1 - s);
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
 * Returns 0 or HB_EINVAL with scene_set's message.
 */
int
fit_param_apply(struct scene *sc, const struct fit_param *fp, int np, const double *u,
                double *th, double *T, char *msg, size_t n)
{
	char txt[40];
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
			snprintf(txt, sizeof txt, "%.17g", th[i]);
			if (scene_set(sc, fp[i].key, txt, msg, n) != HB_OK)
				return HB_EINVAL;
		}
	return scene_derive(sc, msg, n);
}
