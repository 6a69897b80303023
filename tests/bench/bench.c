/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * bench.c - the work-precision benchmark of hybounce (`make bench`).
 *
 *     ./build/hybounce-bench [--out DIR] [--presets DIR] [--quick]
 *
 * For each preset of the paper (studies 1, 2 and 3) and the two presets with
 * a closed form (nonunique-separation, hertz-elastic), each GSL stepper and
 * rtol = atol in {1e-4, 1e-6, 1e-8, 1e-10, 1e-12}: the wall time of the
 * whole run (hb_sim_new + hb_sim_run, median of up to 5 runs, clock_gettime
 * CLOCK_MONOTONIC in this process), the steps, the right-hand-side
 * evaluations and the error on what users read.  Then the paper's own
 * setting, the reductions of DESIGN.md section 3, the cost against the
 * horizon and the number of collisions, and the memory of a 100 s run.
 *
 * Writes DIR/report.md, DIR/work-precision.csv and prints ASCII
 * work-precision plots (log error against log time) to the terminal.
 *
 * Errors (all relative, the largest over the collisions matched by index):
 *   t     max(|d t_e|, |d t_s|) / t_d   (event times against the collision's
 *         own duration: an absolute error in t means nothing without the
 *         contact's time scale, and t/t would hide errors late in a run)
 *   e     |d e_i| / e_i
 *   xc    |d x_c^max| / x_c^max
 *   F     |d F_c^max| / F_c^max
 *   T     the state at the horizon: max(|d x(T)| / X, |d v(T)| / V), X and
 *         V the largest |x| and |v| of the reference arc; for hertz-elastic
 *         the relative change of the mechanical energy instead
 *   coll  max(t, e, xc, F): the collision error plotted
 * A different number of collisions is reported (column dn) and makes the
 * cell's error at least 1 (the runs no longer describe the same motion).
 *
 * Reference: computed once per preset with rk8pd at rtol 1e-14, atol 1e-18
 * (REF_A), and with rkck at the same (REF_B); rk8pd is measured against REF_B,
 * every other stepper against REF_A, so no method is measured against
 * itself.  |REF_A - REF_B| is reported as the floor of the measurement.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <time.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include "hybounce/check.h"
#include "hybounce/preset.h"
#include "hybounce/scene.h"
#include "hybounce/sim.h"
#include "hybounce/status.h"

enum { NTOL = 5, NSTEP = HB_STEPPER_AUTO /* the GSL steppers */, MAXREP = 5 };

static const double tols[NTOL] = { 1e-4, 1e-6, 1e-8, 1e-10, 1e-12 };
static const char stepper_letter[NSTEP] = { 'P', 'F', 'C', 'M', 'I', 'B' };

enum ref_kind { REF_RUN, REF_LINEAR, REF_HERTZ };

struct study {
	const char *preset;
	const char *label;
	int paper;          /* 1 for the studies of the paper */
	enum ref_kind kind;
};

static const struct study studies[] = {
	{ "steel-on-bitumen", "study 1 (steel on bitumen, BWMCL)", 1, REF_RUN },
	{ "ptfe-pom", "study 2 (PTFE on POM, BWSHCCL, full system)", 1, REF_RUN },
	{ "permanent-contact-shccl", "study 3 (SHCCL)", 1, REF_RUN },
	{ "permanent-contact-bwshccl", "study 3 (BWSHCCL)", 1, REF_RUN },
	{ "permanent-contact-bwmcl", "study 3 (BWMCL)", 1, REF_RUN },
	{ "nonunique-separation", "closed form: linear law", 0, REF_LINEAR },
	{ "hertz-elastic", "closed form: Hertz elastic", 0, REF_HERTZ },
};
enum { NSTUDY = sizeof studies / sizeof studies[0] };

/* What a run gives to its reader. */
struct obs {
	int status;             /* 0 ok, 1 failed, 2 over budget */
	char msg[400];
	double sec;             /* median wall time */
	double cpu;             /* median CPU time in hb_sim_advance (hb_sim_stats.seconds) */
	int reps;
	long steps, rejected, rhs, jac, kinks;
	int stiff, switched;    /* the engine's stiffness verdict */
	double hrho;            /* largest h max(-Re lambda) it saw */
	size_t n;               /* completed collisions */
	struct hb_collision *c;
	int live;               /* 1: a contact is in progress at the end */
	struct hb_collision lc;    /* its values so far */
	double tT, xT, vT;      /* state at the end */
	int qT;
	long jT;
	double X, V;            /* largest |x|, |v| of the arc */
	double dE;              /* relative change of mechanical energy (hertz) */
	size_t samples, bytes;
	int thinned;
};

struct err {
	double t, e, xc, F, T, coll;
	double tabs;            /* max |d t_e|, |d t_s| in seconds */
	long dn;
};

static double budget_s = 20.0;   /* CPU seconds at most per run */
static int quick;
static double hertz_quad;       /* relative gap of the t_d quadrature, 96 vs 64 nodes */

static double
now(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static int
cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return (x > y) - (x < y);
}

static void
obs_free(struct obs *o)
{
	free(o->c);
	o->c = NULL;
	o->n = 0;
}

/* Mechanical energy of the reduced system under gravity and a Hertz law. */
static double
hertz_energy(const struct hb_scene *sc, const struct hb_arc_sample *a)
{
	int ik = hb_law_param_index(sc->law, "k"), ip = hb_law_param_index(sc->law, "p");
	double k = sc->par[ik], p = sc->par[ip], E;

	E = 0.5 * sc->d.m * a->v * a->v + sc->d.m * sc->loads.g * a->x;
	if (a->q && a->xc < 0)
		E += k * pow(-a->xc, p + 1) / (p + 1);
	return E;
}

/* One finished run into o (collisions copied). */
static void
collect(struct hb_sim *s, struct obs *o)
{
	const struct hb_arc *a = hb_sim_arc(s);
	const struct hb_sim_stats *st = hb_sim_stats(s);
	const struct hb_arc_sample *l = hb_arc_last(a);
	size_t i, n = hb_arc_len(a);

	o->steps = st->steps;
	o->rejected = st->rejected;
	o->rhs = st->rhs;
	o->jac = st->jac;
	o->kinks = st->kinks;
	o->stiff = st->stiff;
	o->switched = st->switched;
	o->hrho = st->stiff_hrho;
	o->n = hb_sim_ncollisions(s);
	o->live = hb_sim_contact_live(s, &o->lc);
	o->c = calloc(o->n ? o->n : 1, sizeof *o->c);
	for (i = 0; i < o->n; i++)
		o->c[i] = *hb_sim_collision(s, i);
	o->tT = l->t;
	o->xT = l->x;
	o->vT = l->v;
	o->qT = l->q;
	o->jT = l->j;
	o->X = o->V = 0;
	for (i = 0; i < n; i++) {
		o->X = fmax(o->X, fabs(hb_arc_at(a, i)->x));
		o->V = fmax(o->V, fabs(hb_arc_at(a, i)->v));
	}
	if (hb_sim_scene(s)->law == hb_law_find("hertz")) {
		double E0 = hertz_energy(hb_sim_scene(s), hb_arc_at(a, 0));

		o->dE = fabs(hertz_energy(hb_sim_scene(s), l) - E0) / fabs(E0);
	}
	o->samples = n;
	o->bytes = hb_arc_bytes(a);
	o->thinned = hb_arc_thinned(a);
}

/* One timed run; returns the wall time, or a negative value on failure. */
static double
run_once(const struct hb_scene *sc, struct obs *o, int keep)
{
	char msg[380];
	struct hb_sim *s;
	double t0 = now(), t1, cpu = 0;
	int rc = HB_OK;

	s = hb_sim_new(sc, msg, sizeof msg);
	if (!s) {
		o->status = 1;
		snprintf(o->msg, sizeof o->msg, "sim_new: %s", msg);
		return -1;
	}
	while (hb_sim_end(s) == HB_SIM_RUNNING) {
		rc = hb_sim_advance(s, 0, 1.0);
		if (rc != HB_OK)
			break;
		cpu = hb_sim_stats(s)->seconds;
		if (cpu > budget_s)
			break;
	}
	t1 = now();
	if (hb_sim_end(s) == HB_SIM_RUNNING) {
		o->status = 2;
		snprintf(o->msg, sizeof o->msg, "over budget: %.0f s of CPU, t = %.6g s",
		         budget_s, hb_arc_last(hb_sim_arc(s))->t);
	} else if (hb_sim_end(s) == HB_SIM_END_FAIL) {
		o->status = 1;
		snprintf(o->msg, sizeof o->msg, "%s", hb_sim_errmsg(s));
	} else {
		o->status = 0;
		o->msg[0] = 0;
	}
	if (keep) {
		obs_free(o);
		collect(s, o);
	}
	o->cpu = hb_sim_stats(s)->seconds;
	hb_sim_free(s);
	return o->status ? -1 : t1 - t0;
}

/* Timed runs: up to MAXREP, fewer when a run is slow; o gets the median. */
static void
run_timed(const struct hb_scene *sc, struct obs *o, int maxrep)
{
	double t[MAXREP], c[MAXREP];
	int r, reps;

	memset(o, 0, sizeof *o);
	t[0] = run_once(sc, o, 1);
	c[0] = o->cpu;
	if (o->status) {
		o->sec = NAN;
		o->reps = 1;
		return;
	}
	reps = t[0] > 0.5 ? 1 : t[0] > 0.1 ? 3 : maxrep;
	if (quick && reps > 3)
		reps = 3;
	for (r = 1; r < reps; r++) {
		struct obs tmp = { 0 };

		t[r] = run_once(sc, &tmp, 0);
		c[r] = tmp.cpu;
	}
	qsort(t, reps, sizeof t[0], cmp_double);
	qsort(c, reps, sizeof c[0], cmp_double);
	o->sec = reps % 2 ? t[reps / 2] : 0.5 * (t[reps / 2 - 1] + t[reps / 2]);
	o->cpu = reps % 2 ? c[reps / 2] : 0.5 * (c[reps / 2 - 1] + c[reps / 2]);
	o->reps = reps;
}

static double
rel(double a, double b)
{
	double d = fabs(a - b), m = fabs(b);

	if (d == 0)
		return 0;
	return m > 0 ? d / m : d;
}

/* Errors of o against the reference r (kind REF_HERTZ: T is the energy). */
static void
compare(const struct obs *o, const struct obs *r, enum ref_kind kind, struct err *e)
{
	size_t i, n = o->n < r->n ? o->n : r->n;

	memset(e, 0, sizeof *e);
	for (i = 0; i < n; i++) {
		const struct hb_collision *a = &o->c[i], *b = &r->c[i];
		double dt = fmax(fabs(a->te - b->te), fabs(a->ts - b->ts)) / b->td;

		e->t = fmax(e->t, dt);
		e->tabs = fmax(e->tabs, fmax(fabs(a->te - b->te), fabs(a->ts - b->ts)));
		e->e = fmax(e->e, rel(a->e, b->e));
		e->xc = fmax(e->xc, rel(a->xcmax, b->xcmax));
		e->F = fmax(e->F, rel(a->Fcmax, b->Fcmax));
	}
	e->dn = (long)o->n - (long)r->n;
	if (o->live && r->live && !e->dn) {
		e->t = fmax(e->t, fabs(o->lc.te - r->lc.te) / fmax(r->lc.td, 1e-300));
		e->xc = fmax(e->xc, rel(o->lc.xcmax, r->lc.xcmax));
		e->F = fmax(e->F, rel(o->lc.Fcmax, r->lc.Fcmax));
	}
	if (kind == REF_HERTZ)
		e->T = o->dE;
	else
		e->T = fmax(fabs(o->xT - r->xT) / r->X, fabs(o->vT - r->vT) / r->V);
	e->coll = fmax(fmax(e->t, e->e), fmax(e->xc, e->F));
	if (e->dn)
		e->coll = fmax(e->coll, 1.0);
}

/* ---------------------------------------------------------------------- */
/* Closed forms.                                                            */

/* The linear law k min(x_c, 0), no load: one collision, exact. */
static void
closed_linear(const struct hb_scene *sc, struct obs *r)
{
	double k = sc->par[hb_law_param_index(sc->law, "k")], m = sc->d.m;
	double w = sqrt(k / m), v0 = fabs(sc->init.v0);

	memset(r, 0, sizeof *r);
	r->n = 1;
	r->c = calloc(1, sizeof *r->c);
	r->c[0].te = sc->init.x0 / v0;
	r->c[0].td = M_PI / w;
	r->c[0].ts = r->c[0].te + r->c[0].td;
	r->c[0].e = 1.0;
	r->c[0].xcmax = v0 / w;
	r->c[0].Fcmax = k * v0 / w;
	r->tT = sc->run.T;
	r->xT = v0 * (sc->run.T - r->c[0].ts);
	r->vT = v0;
	r->X = fmax(sc->init.x0, r->xT);
	r->V = v0;
}

struct hz {
	double v2, g, km, d, p;
};

/* f(x) = v^2 + 2 g x - 2 (k/m) x^(p+1) / (p+1): the squared speed at indentation x. */
static double
hz_f(const struct hz *h, double x)
{
	return h->v2 + 2 * h->g * x - 2 * h->km * pow(x, h->p + 1) / (h->p + 1);
}

static double
hz_integrand(double s, void *params)
{
	const struct hz *h = params;
	double x = h->d * (1 - s * s), f = hz_f(h, x);

	return f > 0 ? 2 * h->d * s / sqrt(f) : 0.0;
}

/*
 * Hertz elastic under gravity, body dropped from rest at x0: every approach
 * at v = sqrt(2 g x0), e = 1, the greatest indentation d from the energy
 * balance m v^2/2 + m g d = k d^(p+1)/(p+1) (Newton), F_c^max = k d^p, the
 * contact's duration t_d = 2 int_0^d dx / sqrt(f(x)) by quadrature
 * (x = d (1 - s^2) removes the end singularity), flights 2 v / g.
 */
static void
closed_hertz(const struct hb_scene *sc, struct obs *r)
{
	struct hz h;
	double k = sc->par[hb_law_param_index(sc->law, "k")], v, tf, te0, td, res, aerr;
	gsl_integration_glfixed_table *tab = gsl_integration_glfixed_table_alloc(96);
	gsl_integration_glfixed_table *tab2 = gsl_integration_glfixed_table_alloc(64);
	gsl_function F;
	size_t n, i;
	int it;

	memset(r, 0, sizeof *r);
	h.g = sc->loads.g;
	h.p = sc->par[hb_law_param_index(sc->law, "p")];
	h.km = k / sc->d.m;
	v = sqrt(2 * h.g * sc->init.x0);
	h.v2 = v * v;
	h.d = pow((h.p + 1) * h.v2 / (2 * h.km), 1 / (h.p + 1));
	for (it = 0; it < 50; it++) {
		double f = hz_f(&h, h.d), df = 2 * h.g - 2 * h.km * pow(h.d, h.p);

		h.d -= f / df;
		if (fabs(f / df) < 1e-17 * h.d)
			break;
	}
	F.function = hz_integrand;
	F.params = &h;
	/* The integrand is analytic on [0, 1]: fixed Gauss-Legendre converges fast. */
	res = gsl_integration_glfixed(&F, 0, 1, tab);
	aerr = fabs(res - gsl_integration_glfixed(&F, 0, 1, tab2));
	gsl_integration_glfixed_table_free(tab);
	gsl_integration_glfixed_table_free(tab2);
	td = 2 * res;
	hertz_quad = aerr / res;
	te0 = sqrt(2 * sc->init.x0 / h.g);
	tf = 2 * v / h.g;
	n = 0;
	while (te0 + n * (td + tf) + td < sc->run.T)
		n++;
	r->n = n;
	r->c = calloc(n ? n : 1, sizeof *r->c);
	for (i = 0; i < n; i++) {
		r->c[i].te = te0 + i * (td + tf);
		r->c[i].td = td;
		r->c[i].ts = r->c[i].te + td;
		r->c[i].e = 1.0;
		r->c[i].xcmax = h.d;
		r->c[i].Fcmax = k * pow(h.d, h.p);
	}
	r->X = sc->init.x0;
	r->V = v;
}

/* ---------------------------------------------------------------------- */
/* Output helpers.                                                          */

static int
load(const char *dir, const char *name, struct hb_scene *sc)
{
	char path[1024], msg[512];

	snprintf(path, sizeof path, "%s/%s.preset", dir, name);
	if (hb_preset_load(path, sc, msg, sizeof msg)) {
		fprintf(stderr, "hybounce-bench: %s\n", msg);
		return -1;
	}
	return 0;
}

static void
set(struct hb_scene *sc, const char *key, const char *val)
{
	char msg[512];

	if (hb_scene_set(sc, key, val, msg, sizeof msg)) {
		fprintf(stderr, "hybounce-bench: %s\n", msg);
		exit(1);
	}
}

static void
set_tol(struct hb_scene *sc, int stepper, double rtol, double atol)
{
	sc->run.stepper = stepper;
	sc->run.limits = 0; /* every stepper at every tolerance: the bench measures them */
	sc->run.rtol = rtol;
	sc->run.atol = atol;
}

static const char *
fmt_e(char *buf, double x)
{
	if (isnan(x))
		snprintf(buf, 16, "-");
	else if (x == 0)
		snprintf(buf, 16, "0");
	else
		snprintf(buf, 16, "%.1e", x);
	return buf;
}

/* ASCII work-precision plot: log10 error (rows) against log10 ms (columns). */
enum { PW = 64, PH = 18 };

struct point {
	double ms, err;
	char c;
};

static void
plot(FILE *f, const char *title, const struct point *p, int np)
{
	char g[PH][PW + 1];
	double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
	int i, r;

	for (i = 0; i < np; i++) {
		double x = log10(p[i].ms), y = log10(fmax(p[i].err, 1e-16));

		x0 = fmin(x0, x), x1 = fmax(x1, x);
		y0 = fmin(y0, y), y1 = fmax(y1, y);
	}
	if (np == 0)
		return;
	x0 = floor(x0 * 2) / 2, x1 = ceil(x1 * 2) / 2;
	y0 = floor(y0), y1 = ceil(y1);
	if (x1 <= x0)
		x1 = x0 + 0.5;
	if (y1 <= y0)
		y1 = y0 + 1;
	for (r = 0; r < PH; r++) {
		memset(g[r], ' ', PW);
		g[r][PW] = 0;
	}
	for (i = 0; i < np; i++) {
		double x = log10(p[i].ms), y = log10(fmax(p[i].err, 1e-16));
		int cx = (int)lround((x - x0) / (x1 - x0) * (PW - 1));
		int cy = (int)lround((y1 - y) / (y1 - y0) * (PH - 1));
		char *cell = &g[cy][cx];

		*cell = (*cell == ' ' || *cell == p[i].c) ? p[i].c : '*';
	}
	fprintf(f, "%s\n", title);
	for (r = 0; r < PH; r++) {
		double y = y1 - (y1 - y0) * r / (PH - 1);

		if (r == 0 || r == PH - 1 || r == PH / 2)
			fprintf(f, "%7.1e |%s\n", pow(10, y), g[r]);
		else
			fprintf(f, "        |%s\n", g[r]);
	}
	fprintf(f, "        +");
	for (i = 0; i < PW; i++)
		putc('-', f);
	fprintf(f, "\n        %-8.3g%*s%8.3g ms (wall, log scale)\n", pow(10, x0), PW - 14, "",
	        pow(10, x1));
	fprintf(f, "        P rk8pd  F rkf45  C rkck  M msbdf  I rk4imp  B bsimp  "
	           "(* several); y: collision error\n\n");
}

/* ---------------------------------------------------------------------- */

struct cell {
	struct obs o;
	struct err e;
};

static struct cell grid[NSTUDY][NSTEP][NTOL];

/* Settings with atol below rtol (the grid has rtol = atol). */
static const struct {
	int st;
	double rtol, atol;
} extra[] = {
	{ HB_STEPPER_RK8PD, 1e-10, 1e-14 }, { HB_STEPPER_RK8PD, 1e-11, 1e-16 },
	{ HB_STEPPER_RK8PD, 1e-12, 1e-14 }, { HB_STEPPER_RK8PD, 1e-12, 1e-16 },
	{ HB_STEPPER_RK8PD, 1e-13, 1e-14 }, { HB_STEPPER_RK8PD, 1e-13, 1e-16 },
	/* DOP853 with dense output and kinks as modes (issue 8); 3e-14/1e-14 the presets' default */
	{ HB_STEPPER_DOP853, 1e-12, 1e-14 }, { HB_STEPPER_DOP853, 1e-13, 1e-14 },
	{ HB_STEPPER_DOP853, 3e-14, 1e-14 }, { HB_STEPPER_DOP853, 1e-14, 1e-14 },
};
enum { NEXTRA = sizeof extra / sizeof extra[0] };
static struct cell xgrid[NSTUDY][NEXTRA];
static char best_label[96];
static struct obs refA[NSTUDY], refB[NSTUDY], paper[NSTUDY], dflt[NSTUDY];
static struct err refAB[NSTUDY], paperE[NSTUDY], dfltE[NSTUDY];

static const struct obs *
reference_for(int s, int stepper)
{
	return stepper == HB_STEPPER_RK8PD ? &refB[s] : &refA[s];
}

/*
 * 1 if the cells (one per study) meet the targets on every paper study:
 * same collision count, each error <= max(paper / 10, reference floor),
 * run < 16 ms.  *slow: the slowest study's ms; *ratio: worst error / paper's.
 */
static int
qualify(const struct cell *const *cells, double *slow, double *ratio)
{
	int ok = 1, s, i;

	*slow = 0;
	*ratio = 0;
	for (s = 0; s < NSTUDY; s++) {
		const struct cell *c = cells[s];
		const struct err *p = &paperE[s];
		double q[5][3] = { { c->e.t, p->t, refAB[s].coll }, { c->e.e, p->e, refAB[s].coll },
		                   { c->e.xc, p->xc, refAB[s].coll }, { c->e.F, p->F, refAB[s].coll },
		                   { c->e.T, p->T, refAB[s].T } };

		if (!studies[s].paper)
			continue;
		if (c->o.status || c->e.dn || paper[s].status) {
			ok = 0;
			*slow = INFINITY;
			continue;
		}
		*slow = fmax(*slow, c->o.sec * 1e3);
		for (i = 0; i < 5; i++) {
			*ratio = fmax(*ratio, q[i][0] / fmax(q[i][1], q[i][2]));
			if (q[i][0] > fmax(q[i][1] / 10, q[i][2]))
				ok = 0;
		}
	}
	if (*slow >= 16)
		ok = 0;
	return ok;
}

static int
mkdir_p(const char *d)
{
	if (mkdir(d, 0777) && errno != EEXIST) {
		fprintf(stderr, "hybounce-bench: %s: %s\n", d, strerror(errno));
		return -1;
	}
	return 0;
}

/*
 * --refcheck PRESET: candidate references compared pairwise (collision error
 * and horizon error), to choose the reference settings.
 */
static int
ref_check(const char *pdir, const char *name)
{
	static const struct {
		int st;
		double rtol, atol;
	} cand[] = {
		{ HB_STEPPER_RK8PD, 1e-14, 1e-14 }, { HB_STEPPER_RK8PD, 1e-14, 1e-16 },
		{ HB_STEPPER_RK8PD, 1e-14, 1e-18 }, { HB_STEPPER_RK8PD, 1e-13, 1e-16 },
		{ HB_STEPPER_RKCK, 1e-14, 1e-14 },  { HB_STEPPER_RKCK, 1e-14, 1e-18 },
		{ HB_STEPPER_RKF45, 1e-14, 1e-18 }, { HB_STEPPER_RK4IMP, 1e-14, 1e-18 },
		{ HB_STEPPER_MSBDF, 1e-14, 1e-18 },
	};
	enum { NC = sizeof cand / sizeof cand[0] };
	struct obs o[NC];
	struct hb_scene sc;
	struct err e;
	int a, b;

	for (a = 0; a < NC; a++) {
		if (load(pdir, name, &sc))
			return 1;
		set_tol(&sc, cand[a].st, cand[a].rtol, cand[a].atol);
		run_timed(&sc, &o[a], 1);
		printf("%d: %-6s %g/%g  %s %.1f ms  %zu collisions  %ld steps\n", a,
		       hb_scene_stepper_name(cand[a].st), cand[a].rtol, cand[a].atol,
		       o[a].status ? o[a].msg : "ok", o[a].sec * 1e3, o[a].n, o[a].steps);
	}
	printf("collision error (t,e,xc,F max) / horizon error, row against column\n    ");
	for (b = 0; b < NC; b++)
		printf("%17d", b);
	printf("\n");
	for (a = 0; a < NC; a++) {
		printf("%2d: ", a);
		for (b = 0; b < NC; b++) {
			if (o[a].status || o[b].status) {
				printf("%17s", "-");
				continue;
			}
			compare(&o[a], &o[b], REF_RUN, &e);
			printf("  %7.1e/%7.1e", e.coll, e.T);
		}
		printf("\n");
	}
	for (a = 0; a < NC; a++)
		obs_free(&o[a]);
	return 0;
}

int
main(int argc, char **argv)
{
	const char *out = "build/bench", *pdir = "presets", *refcheck = NULL;
	char path[1024], b1[16], b2[16], b3[16], b4[16], b5[16], b6[16];
	FILE *md, *csv;
	struct hb_scene sc;
	double T0 = now();
	int i, s, st, t;

	for (i = 1; i < argc; i++) {
		if (!strcmp(argv[i], "--out") && i + 1 < argc)
			out = argv[++i];
		else if (!strcmp(argv[i], "--presets") && i + 1 < argc)
			pdir = argv[++i];
		else if (!strcmp(argv[i], "--refcheck") && i + 1 < argc)
			refcheck = argv[++i];
		else if (!strcmp(argv[i], "--quick"))
			quick = 1, budget_s = 5;
		else {
			fprintf(stderr, "usage: hybounce-bench [--out DIR] [--presets DIR] [--quick]\n");
			return 2;
		}
	}
	gsl_set_error_handler_off();
	if (refcheck)
		return ref_check(pdir, refcheck);
	if (mkdir_p(out))
		return 1;
	snprintf(path, sizeof path, "%s/report.md", out);
	md = fopen(path, "w");
	snprintf(path, sizeof path, "%s/work-precision.csv", out);
	csv = fopen(path, "w");
	if (!md || !csv) {
		fprintf(stderr, "hybounce-bench: cannot write in %s\n", out);
		return 1;
	}

	/* References. */
	for (s = 0; s < NSTUDY; s++) {
		if (load(pdir, studies[s].preset, &sc))
			return 1;
		set_tol(&sc, HB_STEPPER_RK8PD, 1e-14, 1e-18);
		run_timed(&sc, &refA[s], 1);
		set_tol(&sc, HB_STEPPER_RKCK, 1e-14, 1e-18);
		run_timed(&sc, &refB[s], 1);
		if (refA[s].status || refB[s].status) {
			fprintf(stderr, "hybounce-bench: %s: reference failed: %s%s\n",
			        studies[s].preset, refA[s].msg, refB[s].msg);
			return 1;
		}
		compare(&refB[s], &refA[s], REF_RUN, &refAB[s]);
		if (studies[s].kind != REF_RUN) {
			/* Closed form: replaces both references. */
			struct obs cf;

			if (studies[s].kind == REF_LINEAR)
				closed_linear(&sc, &cf);
			else
				closed_hertz(&sc, &cf);
			compare(&refA[s], &cf, studies[s].kind, &refAB[s]);
			obs_free(&refA[s]);
			obs_free(&refB[s]);
			refA[s] = cf;
			refB[s] = cf;
			refB[s].c = malloc((cf.n ? cf.n : 1) * sizeof *cf.c);
			memcpy(refB[s].c, cf.c, cf.n * sizeof *cf.c);
		}
		fprintf(stderr, "reference %-26s %3zu collisions  rk8pd vs %s: coll %.1e  T %.1e\n",
		        studies[s].preset, refA[s].n,
		        studies[s].kind == REF_RUN ? "rkck" : "closed form", refAB[s].coll,
		        refAB[s].T);
	}

	/* The grid. */
	fprintf(csv, "preset,stepper,rtol,atol,status,ms,cpu_ms,reps,steps,rejected,rhs,jac,"
	             "collisions,dn,err_t,err_t_abs_s,err_e,err_xcmax,err_Fcmax,err_coll,err_T,reference,message\n");
	for (s = 0; s < NSTUDY; s++) {
		if (load(pdir, studies[s].preset, &sc))
			return 1;
		for (st = 0; st < NSTEP; st++)
			for (t = 0; t < NTOL; t++) {
				struct cell *c = &grid[s][st][t];

				set_tol(&sc, st, tols[t], tols[t]);
				run_timed(&sc, &c->o, MAXREP);
				if (!c->o.status)
					compare(&c->o, reference_for(s, st), studies[s].kind, &c->e);
				fprintf(csv, "%s,%s,%g,%g,%s,%.6g,%.6g,%d,%ld,%ld,%ld,%ld,%zu,%ld,"
				             "%.3e,%.3e,%.3e,%.3e,%.3e,%.3e,%.3e,%s,\"",
				        studies[s].preset, hb_scene_stepper_name(st), tols[t], tols[t],
				        c->o.status == 0 ? "ok" : c->o.status == 1 ? "failed" : "budget",
				        c->o.sec * 1e3, c->o.cpu * 1e3, c->o.reps, c->o.steps, c->o.rejected, c->o.rhs,
				        c->o.jac, c->o.n, c->e.dn, c->e.t, c->e.tabs, c->e.e, c->e.xc, c->e.F,
				        c->e.coll, c->e.T,
				        studies[s].kind != REF_RUN ? "closed form"
				        : st == HB_STEPPER_RK8PD ? "rkck 1e-14/1e-18" : "rk8pd 1e-14/1e-18");
				for (const char *q = c->o.msg; *q; q++)
					fprintf(csv, *q == '"' ? "\"\"" : "%c", *q);
				fprintf(csv, "\"\n");
				if (c->o.status)
					fprintf(stderr, "  %s %s %g: %s\n", studies[s].preset,
					        hb_scene_stepper_name(st), tols[t], c->o.msg);
			}
		fprintf(stderr, "grid %-26s done (%.0f s)\n", studies[s].preset, now() - T0);
	}

	/* The paper's setting (DOP853 rtol 1e-11, atol 1e-14) and the presets' own. */
	for (s = 0; s < NSTUDY; s++) {
		if (load(pdir, studies[s].preset, &sc))
			return 1;
		run_timed(&sc, &dflt[s], MAXREP);
		if (!dflt[s].status)
			compare(&dflt[s], reference_for(s, sc.run.stepper), studies[s].kind, &dfltE[s]);
		set_tol(&sc, HB_STEPPER_RK8PD, 1e-11, 1e-14);
		run_timed(&sc, &paper[s], MAXREP);
		if (!paper[s].status)
			compare(&paper[s], &refB[s], studies[s].kind, &paperE[s]);
	}

	fprintf(md, "# hybounce work-precision report\n\n");
	fprintf(md, "Generated by `make bench` (tests/bench/bench.c). Wall time of the whole run "
	            "(sim_new + sim_run) measured in-process with clock_gettime, median of up to "
	            "5 runs (3 when a run takes over 0.1 s, 1 over 0.5 s). Errors are relative, "
	            "the largest over the collisions matched by index: **t** = max(|dt_e|, |dt_s|) "
	            "/ t_d (event times against the collision's own duration), **e** = restitution, "
	            "**xc** = x_c^max, **F** = F_c^max, **coll** = max of the four (a different "
	            "collision count, column dn, counts as 1), **T** = state at the horizon, "
	            "max(|dx|/X, |dv|/V) with X, V the largest |x|, |v| of the reference "
	            "(hertz-elastic: relative change of the mechanical energy).\n\n");
	fprintf(md, "Reference: rk8pd at rtol 1e-14, atol 1e-18 for every stepper but rk8pd, which is "
	            "measured against rkck at the same setting (atol 1e-18 rather than 1e-14: "
	            "`hybounce-bench --refcheck steel-on-bitumen` shows rkck at atol 1e-14 "
	            "2.4e-10 away from every tight rk8pd run, at 1e-18 within 1e-11); closed forms for nonunique-separation (t_d = "
	            "pi/omega, e = 1, x_c^max = v0/omega, exact flight) and hertz-elastic (e = 1, "
	            "x_c^max from m v^2/2 + m g d = k d^(p+1)/(p+1), F_c^max = k d^p, t_d by "
	            "quadrature, flights 2v/g; energy conserved).\n\n");
	fprintf(md, "## References\n\n| preset | collisions | rk8pd vs rkck, both 1e-14/1e-18 (or "
	            "closed form): coll | T | ms (rk8pd 1e-14/1e-18) |\n|---|---|---|---|---|\n");
	for (s = 0; s < NSTUDY; s++)
		fprintf(md, "| %s | %zu | %s | %s | %s |\n", studies[s].preset, refA[s].n,
		        fmt_e(b1, refAB[s].coll), fmt_e(b2, refAB[s].T),
		        studies[s].kind == REF_RUN ? (snprintf(b3, 16, "%.2f", refA[s].sec * 1e3), b3) : "-");
	fprintf(md, "\nThe Hertz contact duration by 96- and 64-node Gauss-Legendre differs by %.1e "
	            "(relative).\n", hertz_quad);

	/* Extra settings with atol below rtol (rk8pd, dop853), for the choice of the default. */
	for (s = 0; s < NSTUDY; s++) {
		if (load(pdir, studies[s].preset, &sc))
			return 1;
		for (i = 0; i < NEXTRA; i++) {
			struct cell *c = &xgrid[s][i];

			set_tol(&sc, extra[i].st, extra[i].rtol, extra[i].atol);
			run_timed(&sc, &c->o, MAXREP);
			if (!c->o.status)
				compare(&c->o, reference_for(s, extra[i].st), studies[s].kind, &c->e);
			fprintf(csv, "%s,%s,%g,%g,%s,%.6g,%.6g,%d,%ld,%ld,%ld,%ld,%zu,%ld,"
			             "%.3e,%.3e,%.3e,%.3e,%.3e,%.3e,%.3e,%s,\"%s\"\n",
			        studies[s].preset, hb_scene_stepper_name(extra[i].st), extra[i].rtol,
			        extra[i].atol, c->o.status ? "failed" : "ok", c->o.sec * 1e3, c->o.cpu * 1e3,
			        c->o.reps,
			        c->o.steps, c->o.rejected, c->o.rhs, c->o.jac, c->o.n, c->e.dn, c->e.t,
			        c->e.tabs, c->e.e, c->e.xc, c->e.F, c->e.coll, c->e.T,
			        studies[s].kind != REF_RUN       ? "closed form"
			        : extra[i].st == HB_STEPPER_RK8PD ? "rkck 1e-14/1e-18" : "rk8pd 1e-14/1e-18",
			        c->o.status ? "failed" : "");
		}
	}
	/* Tables and plots per study. */
	for (s = 0; s < NSTUDY; s++) {
		struct point pts[NSTEP * NTOL];
		int np = 0;
		char title[160];

		fprintf(md, "\n## %s — %s\n\n", studies[s].preset, studies[s].label);
		fprintf(md, "| stepper | tol | ms | steps | rhs | n | dn | t | e | xc | F | T |\n"
		            "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
		for (st = 0; st < NSTEP; st++)
			for (t = 0; t < NTOL; t++) {
				struct cell *c = &grid[s][st][t];

				if (c->o.status) {
					fprintf(md, "| %s | %g | failed | | | | | | | | | %s |\n",
					        hb_scene_stepper_name(st), tols[t], c->o.msg);
					continue;
				}
				fprintf(md, "| %s | %g | %.2f | %ld | %ld | %zu | %ld | %s | %s | %s | %s | %s |\n",
				        hb_scene_stepper_name(st), tols[t], c->o.sec * 1e3, c->o.steps,
				        c->o.rhs, c->o.n, c->e.dn, fmt_e(b1, c->e.t), fmt_e(b2, c->e.e),
				        fmt_e(b3, c->e.xc), fmt_e(b4, c->e.F), fmt_e(b5, c->e.T));
				pts[np].ms = c->o.sec * 1e3;
				pts[np].err = c->e.coll;
				pts[np].c = stepper_letter[st];
				np++;
			}
		if (!paper[s].status)
			fprintf(md, "| **paper** rk8pd | 1e-11/1e-14 | %.2f | %ld | %ld | %zu | %ld | %s | %s | %s | %s | %s |\n",
			        paper[s].sec * 1e3, paper[s].steps, paper[s].rhs, paper[s].n, paperE[s].dn,
			        fmt_e(b1, paperE[s].t), fmt_e(b2, paperE[s].e), fmt_e(b3, paperE[s].xc),
			        fmt_e(b4, paperE[s].F), fmt_e(b5, paperE[s].T));
		for (i = 0; i < NEXTRA; i++) {
			const struct cell *c = &xgrid[s][i];

			if (c->o.status)
				continue;
			fprintf(md, "| %s (%ld rejected) | %g/%g | %.2f | %ld | %ld | %zu | %ld | %s | %s | %s | %s | %s |\n",
			        hb_scene_stepper_name(extra[i].st), c->o.rejected,
			        extra[i].rtol, extra[i].atol, c->o.sec * 1e3, c->o.steps, c->o.rhs, c->o.n,
			        c->e.dn, fmt_e(b1, c->e.t), fmt_e(b2, c->e.e), fmt_e(b3, c->e.xc),
			        fmt_e(b4, c->e.F), fmt_e(b5, c->e.T));
		}
		snprintf(title, sizeof title, "work-precision: %s (%s)", studies[s].preset,
		         studies[s].label);
		plot(stdout, title, pts, np);
		fprintf(md, "\n```\n");
		plot(md, title, pts, np);
		fprintf(md, "```\n");
	}

	/* Paper setting against the preset defaults. */
	fprintf(md, "\n## The paper's setting and the presets' default\n\n"
	            "The paper used DOP853 at rtol 1e-11, atol 1e-14 (absolute, SI units). Its stand-in "
	            "here is rk8pd (Dormand-Prince 8(9)) at rtol 1e-11, atol 1e-14, where our atol is "
	            "relative to each component's scale (sim.h, sim_stats.scale): for an indentation "
	            "of scale 1e-4 m it means 1e-18 m, tighter than the paper's 1e-14 m, and for a "
	            "velocity of 1 m/s it is the same. With rtol 1e-11 dominating on every component "
	            "that is not near zero, the mapping is faithful on the observables; the engine "
	            "also ends steps on the law's kinks (DESIGN.md 4a), which DOP853 did not.\n\n");
	fprintf(md, "| preset | setting | ms | cpu ms | n | t (/t_d) | t (s) | e | xc | F | T |\n"
	            "|---|---|---|---|---|---|---|---|---|---|---|\n");
	for (s = 0; s < NSTUDY; s++) {
		if (load(pdir, studies[s].preset, &sc))
			return 1;
		if (!paper[s].status)
			fprintf(md, "| %s | paper: rk8pd 1e-11/1e-14 | %.2f | %.2f | %zu | %s | %s | %s | %s | %s | %s |\n",
			        studies[s].preset, paper[s].sec * 1e3, paper[s].cpu * 1e3, paper[s].n, fmt_e(b1, paperE[s].t),
			        fmt_e(b6, paperE[s].tabs),
			        fmt_e(b2, paperE[s].e), fmt_e(b3, paperE[s].xc), fmt_e(b4, paperE[s].F),
			        fmt_e(b5, paperE[s].T));
		else
			fprintf(md, "| %s | paper | failed: %s |||||||\n", studies[s].preset, paper[s].msg);
		if (!dflt[s].status)
			fprintf(md, "| %s | preset: %s %g/%g | %.2f | %.2f | %zu | %s | %s | %s | %s | %s | %s |\n",
			        studies[s].preset, hb_scene_stepper_name(sc.run.stepper), sc.run.rtol,
			        sc.run.atol, dflt[s].sec * 1e3, dflt[s].cpu * 1e3, dflt[s].n, fmt_e(b1, dfltE[s].t),
			        fmt_e(b6, dfltE[s].tabs),
			        fmt_e(b2, dfltE[s].e), fmt_e(b3, dfltE[s].xc), fmt_e(b4, dfltE[s].F),
			        fmt_e(b5, dfltE[s].T));
		else
			fprintf(md, "| %s | preset | failed: %s |||||||\n", studies[s].preset, dflt[s].msg);
	}

	fprintf(md, "\n## Choice of the default\n\nA setting qualifies when, on every paper study, it "
	            "completes with the reference's collision count, each error (t, e, xc, F, T) is at "
	            "most a tenth of the paper setting's or within the floor of the references (their "
	            "own disagreement, table References), and the run takes < 16 ms. ratio = the worst "
	            "error divided by the paper setting's (or by the floor when the paper's is below "
	            "it) on the same observable and study: below 1 means at least as accurate as the "
	            "paper's setting.\n\n"
	            "| stepper | rtol | atol | qualifies | slowest study ms | worst ratio to paper |\n"
	            "|---|---|---|---|---|---|\n");
	{
		int best = -1;
		double best_ms = 1e300;

		for (i = 0; i < NSTEP * NTOL + NEXTRA; i++) {
			const struct cell *cells[NSTUDY];
			int ok, cst;
			double slow, ratio, rt, at;

			for (s = 0; s < NSTUDY; s++)
				cells[s] = i < NSTEP * NTOL ? &grid[s][i / NTOL][i % NTOL]
				                            : &xgrid[s][i - NSTEP * NTOL];
			if (i < NSTEP * NTOL)
				cst = i / NTOL, rt = at = tols[i % NTOL];
			else
				cst = extra[i - NSTEP * NTOL].st, rt = extra[i - NSTEP * NTOL].rtol,
				at = extra[i - NSTEP * NTOL].atol;
			ok = qualify(cells, &slow, &ratio);
			fprintf(md, "| %s | %g | %g | %s | %.2f | %.2g |\n", hb_scene_stepper_name(cst), rt, at,
			        ok ? "**yes**" : "no", slow, ratio);
			if (ok && slow < best_ms) {
				best_ms = slow;
				best = i;
				snprintf(best_label, sizeof best_label, "%s at rtol %g, atol %g",
				         hb_scene_stepper_name(cst), rt, at);
			}
		}
		if (best >= 0)
			fprintf(md, "\nFastest qualifying setting: **%s** (slowest paper study %.2f ms).\n",
			        best_label, best_ms);
		else
			fprintf(md, "\nNo setting tried meets every target.\n");
		printf("fastest setting meeting the targets: %s\n", best >= 0 ? best_label : "none");
	}

	/* Kinks (DESIGN.md 4a): steps ended on them, or run over them. */
	fprintf(md, "\n## Kinks (DESIGN.md section 4a)\n\nEach paper study at the paper's setting "
	            "(rk8pd 1e-11/1e-14) and at the preset's, with run.kinks = yes (steps end on the "
	            "law's switching functions and the loads' kinks: the engine's way) and no (the "
	            "steps run over them, as DOP853 did in the paper). Errors against the references, "
	            "as in the grid; ms = median of 5.\n\n"
	            "| preset | setting | kinks | ms | steps | rejected | rhs | kinks ended | t (/t_d) | e | xc | F | T |\n"
	            "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
	for (s = 0; s < NSTUDY; s++) {
		int w, kk;

		if (!studies[s].paper)
			continue;
		for (w = 0; w < 2; w++)
			for (kk = 1; kk >= 0; kk--) {
				struct obs o;
				struct err e = { 0 };

				if (load(pdir, studies[s].preset, &sc))
					return 1;
				if (w == 0)
					set_tol(&sc, HB_STEPPER_RK8PD, 1e-11, 1e-14);
				sc.run.kinks = kk;
				run_timed(&sc, &o, MAXREP);
				if (o.status) {
					fprintf(md, "| %s | %s | %s | failed: %s ||||||||||\n", studies[s].preset,
					        w ? "preset" : "paper", kk ? "yes" : "no", o.msg);
					obs_free(&o);
					continue;
				}
				compare(&o, reference_for(s, sc.run.stepper), studies[s].kind, &e);
				fprintf(md, "| %s | %s %g/%g | %s | %.2f | %ld | %ld | %ld | %ld | %s | %s | %s | %s | %s |\n",
				        studies[s].preset, w ? "preset" : "paper", sc.run.rtol, sc.run.atol,
				        kk ? "yes" : "no", o.sec * 1e3, o.steps, o.rejected, o.rhs, o.kinks,
				        fmt_e(b1, e.t), fmt_e(b2, e.e), fmt_e(b3, e.xc), fmt_e(b4, e.F),
				        fmt_e(b5, e.T));
				obs_free(&o);
			}
	}
	fprintf(stderr, "kinks done (%.0f s)\n", now() - T0);

	/* Reductions. */
	fprintf(md, "\n## Reductions (DESIGN.md section 3)\n\nEach paper study at its preset "
	            "setting with run.reductions = all, then with one reduction turned off, then none. "
	            "ms = median of 5; coll = largest collision error against the run with all "
	            "reductions (the reductions must not change the answer beyond the tolerance).\n\n"
	            "| preset | reductions | ms | cpu ms | steps | rhs | ratio to all (cpu) | coll vs all |\n"
	            "|---|---|---|---|---|---|---|---|\n");
	{
		static const char *const red[][2] = {
			{ "all", "all" },
			{ "contact,com", "all but flight (flight integrated)" },
			{ "flight,com", "all but contact (x integrated in contact)" },
			{ "flight,contact", "all but com (centre of mass integrated)" },
			{ "none", "none" },
		};

		for (s = 0; s < NSTUDY; s++) {
			struct obs all = { 0 };

			if (!studies[s].paper)
				continue;
			for (i = 0; i < 5; i++) {
				struct obs o;
				struct err e = { 0 };

				if (load(pdir, studies[s].preset, &sc))
					return 1;
				set(&sc, "run.reductions", red[i][0]);
				run_timed(&sc, &o, MAXREP);
				if (o.status) {
					fprintf(md, "| %s | %s | failed: %s |||||\n", studies[s].preset,
					        red[i][1], o.msg);
					obs_free(&o);
					continue;
				}
				if (i == 0)
					all = o;
				else
					compare(&o, &all, REF_RUN, &e);
				fprintf(md, "| %s | %s | %.2f | %.2f | %ld | %ld | %.2f | %s |\n", studies[s].preset,
				        red[i][1], o.sec * 1e3, o.cpu * 1e3, o.steps, o.rhs, o.cpu / all.cpu,
				        i ? fmt_e(b1, e.coll) : "-");
				if (i)
					obs_free(&o);
			}
			obs_free(&all);
		}
	}

	/* Hard cases: every stepper at 1e-8 and 1e-10 against rk8pd 1e-14/1e-18. */
	fprintf(md, "\n## Hard cases (presets/hard-*.preset, tests/test_hard.c)\n\n"
	            "Each hard preset with every stepper at rtol = atol = 1e-8 and 1e-10, against "
	            "rk8pd at rtol 1e-14, atol 1e-18 (rk8pd rows: against rkck at the same). Errors as "
	            "above; a contact still in progress at T is compared too (x_c^max, F_c^max so far). "
	            "e_max = the largest restitution of the run. stiff: the engine's verdict "
	            "(sim_stats.stiff: h max(-Re lambda) of the contact flow beyond 1 at eight "
	            "checks in a row of an explicit stepper; h rho = the largest seen); auto = "
	            "run.stepper auto, which goes over to bsimp on that verdict.\n\n"
	            "| preset | stepper | tol | ms | steps | rhs | n | dn | coll | T | e_max | stiff (h rho) |\n"
	            "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
	{
		static const char *const hard[] = {
			"hard-stiff-maxwell", "hard-bouc-wen-beta", "hard-n1", "hard-drop-1um",
			"hard-bounce-end", "hard-slow-impact-hertz", "hard-slow-impact-shccl",
			"hard-linear-maxwell",
		};
		static const double htol[] = { 1e-8, 1e-10 };

		for (i = 0; i < (int)(sizeof hard / sizeof hard[0]); i++) {
			struct obs ra, rb;

			if (load(pdir, hard[i], &sc))
				return 1;
			set_tol(&sc, HB_STEPPER_RK8PD, 1e-14, 1e-18);
			run_timed(&sc, &ra, 1);
			set_tol(&sc, HB_STEPPER_RKCK, 1e-14, 1e-18);
			run_timed(&sc, &rb, 1);
			if (ra.status)
				fprintf(md, "| %s | reference rk8pd 1e-14/1e-18 | failed: %s |||||||||\n",
				        hard[i], ra.msg);
			if (rb.status)
				fprintf(md, "| %s | reference rkck 1e-14/1e-18 | failed: %s |||||||||\n",
				        hard[i], rb.msg);
			for (st = 0; st < HB_STEPPER_COUNT; st++)
				for (t = 0; t < 2; t++) {
					struct obs o;
					struct err e = { 0 };
					const struct obs *ref = st == HB_STEPPER_RK8PD ? &rb : &ra;
					double emax = 0;
					size_t k;

					set_tol(&sc, st, htol[t], htol[t]);
					run_timed(&sc, &o, 3);
					if (o.status) {
						fprintf(md, "| %s | %s | %g | failed: %s ||||||||\n", hard[i],
						        hb_scene_stepper_name(st), htol[t], o.msg);
						fprintf(stderr, "  %s %s %g: %s\n", hard[i],
						        hb_scene_stepper_name(st), htol[t], o.msg);
						obs_free(&o);
						continue;
					}
					for (k = 0; k < o.n; k++)
						emax = fmax(emax, o.c[k].e);
					if (!ref->status)
						compare(&o, ref, REF_RUN, &e);
					char sv[64];

					snprintf(sv, sizeof sv, "%s (%.2g)", o.switched ? "yes: went implicit" : o.stiff ? "yes" : "no", o.hrho);
					fprintf(md, "| %s | %s | %g | %.2f | %ld | %ld | %zu | %ld | %s | %s | %s | %s |\n",
					        hard[i], hb_scene_stepper_name(st), htol[t], o.sec * 1e3, o.steps,
					        o.rhs, o.n, ref->status ? 0 : e.dn,
					        ref->status ? "-" : fmt_e(b1, e.coll),
					        ref->status ? "-" : fmt_e(b2, e.T),
					        o.n ? (snprintf(b3, 16, "%.9f", emax), b3) : "-", sv);
					obs_free(&o);
				}
			obs_free(&ra);
			obs_free(&rb);
			fprintf(stderr, "hard %-26s done (%.0f s)\n", hard[i], now() - T0);
		}
	}

	/* Cost against the horizon and the number of collisions; memory of 100 s. */
	fprintf(md, "\n## Cost against the horizon and the number of collisions\n\n"
	            "| preset | T (s) | collisions | jumps | ms | steps | rhs | kinks | samples | arc bytes |\n"
	            "|---|---|---|---|---|---|---|---|---|---|\n");
	{
		static const struct {
			const char *preset, *T;
		} hz[] = {
			{ "steel-on-bitumen", "0.25 s" }, { "steel-on-bitumen", "0.5 s" },
			{ "steel-on-bitumen", "1 s" }, { "steel-on-bitumen", "2 s" },
			{ "steel-on-bitumen", "5 s" }, { "steel-on-bitumen", "10 s" },
			{ "hertz-elastic", "0.3 s" }, { "hertz-elastic", "1 s" },
			{ "hertz-elastic", "3 s" }, { "hertz-elastic", "10 s" },
			{ "ptfe-pom", "0.25 s" }, { "ptfe-pom", "0.5 s" }, { "ptfe-pom", "1 s" },
		};

		for (i = 0; i < (int)(sizeof hz / sizeof hz[0]); i++) {
			struct obs o;

			if (load(pdir, hz[i].preset, &sc))
				return 1;
			set(&sc, "run.T", hz[i].T);
			run_timed(&sc, &o, 3);
			if (o.status)
				fprintf(md, "| %s | %s | failed: %s ||||||||\n", hz[i].preset, hz[i].T, o.msg);
			else
				fprintf(md, "| %s | %g | %zu | %ld | %.2f | %ld | %ld | %ld | %zu | %zu |\n",
				        hz[i].preset, sc.run.T, o.n, o.jT, o.sec * 1e3, o.steps, o.rhs,
				        o.kinks, o.samples, o.bytes);
			obs_free(&o);
		}
	}
	{
		/*
		 * In a child process, so that its max RSS is the run's own and not
		 * the bench's: the child sends its numbers through a pipe.
		 */
		struct mem {
			int ok;
			char end[200];
			double wall;
			long steps, rhs, kinks;
			size_t ncoll, samples, peak_n, peak;
			int thinned;
		} mr = { 0 };
		struct rusage ru;
		int fd[2], wst;
		pid_t pid;

		if (load(pdir, "steel-on-bitumen", &sc))
			return 1;
		set(&sc, "run.T", "100 s");
		fflush(NULL);
		if (pipe(fd) || (pid = fork()) < 0) {
			fprintf(stderr, "hybounce-bench: fork: %s\n", strerror(errno));
			return 1;
		}
		if (pid == 0) {
			char msg[400];
			struct hb_sim *sm;
			double t0 = now();

			close(fd[0]);
			sm = hb_sim_new(&sc, msg, sizeof msg);
			if (sm) {
				while (hb_sim_end(sm) == HB_SIM_RUNNING) {
					if (hb_sim_advance(sm, 500, 0) != HB_OK)
						break;
					if (hb_arc_bytes(hb_sim_arc(sm)) > mr.peak)
						mr.peak = hb_arc_bytes(hb_sim_arc(sm));
					if (hb_arc_len(hb_sim_arc(sm)) > mr.peak_n)
						mr.peak_n = hb_arc_len(hb_sim_arc(sm));
				}
				mr.wall = now() - t0;
				mr.ok = 1;
				snprintf(mr.end, sizeof mr.end, "%s", hb_sim_end_str(sm));
				mr.steps = hb_sim_stats(sm)->steps;
				mr.rhs = hb_sim_stats(sm)->rhs;
				mr.kinks = hb_sim_stats(sm)->kinks;
				mr.ncoll = hb_sim_ncollisions(sm);
				mr.samples = hb_arc_len(hb_sim_arc(sm));
				mr.thinned = hb_arc_thinned(hb_sim_arc(sm));
				hb_sim_free(sm);
			} else
				snprintf(mr.end, sizeof mr.end, "sim_new: %.180s", msg);
			if (write(fd[1], &mr, sizeof mr) != (ssize_t)sizeof mr)
				_exit(1);
			_exit(0);
		}
		close(fd[1]);
		if (read(fd[0], &mr, sizeof mr) != (ssize_t)sizeof mr)
			mr.ok = 0;
		close(fd[0]);
		waitpid(pid, &wst, 0);
		getrusage(RUSAGE_CHILDREN, &ru);
		fprintf(md, "\n## Memory: study 1 with T = 100 s\n\n"
		            "Run in a child process (max RSS is the run's own, GSL and libc included); "
		            "peak arc bytes sampled every 500 steps.\n\n"
		            "| end | wall s | steps | rhs | kinks | collisions | samples (end) | samples (peak) "
		            "| thinning passes | peak arc bytes | process max RSS |\n"
		            "|---|---|---|---|---|---|---|---|---|---|---|\n");
		if (!mr.ok)
			fprintf(md, "| failed: %s ||||||||||\n", mr.end);
		else
			fprintf(md, "| %s | %.2f | %ld | %ld | %ld | %zu | %zu | %zu | %d | %.2f MiB | %.1f MiB |\n",
			        mr.end, mr.wall, mr.steps, mr.rhs, mr.kinks, mr.ncoll, mr.samples,
			        mr.peak_n, mr.thinned, mr.peak / 1048576.0, ru.ru_maxrss / 1024.0);
		printf("100 s of study 1: %.2f s wall, peak arc %.2f MiB, %d thinning passes, "
		       "max RSS %.1f MiB\n", mr.wall, mr.peak / 1048576.0, mr.thinned,
		       ru.ru_maxrss / 1024.0);
	}

	fprintf(md, "\nTotal bench time: %.0f s.\n", now() - T0);
	fclose(md);
	fclose(csv);
	for (s = 0; s < NSTUDY; s++) {
		obs_free(&refA[s]);
		obs_free(&refB[s]);
		obs_free(&paper[s]);
		obs_free(&dflt[s]);
		for (st = 0; st < NSTEP; st++)
			for (t = 0; t < NTOL; t++)
				obs_free(&grid[s][st][t].o);
		for (i = 0; i < NEXTRA; i++)
			obs_free(&xgrid[s][i].o);
	}
	printf("report: %s/report.md, %s/work-precision.csv (%.0f s)\n", out, out, now() - T0);
	return 0;
}
