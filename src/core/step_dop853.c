/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * step_dop853.c - DOP853 as a GSL odeiv2 step type (see step_dop853.h).
 *
 * Coefficients: Hairer, Norsett and Wanner, Solving Ordinary Differential
 * Equations I (2nd ed., Springer 1993), section II.10, as printed in their
 * code dop853.f (stages 1-12 and the weights of the 8th-order solution;
 * the 5th-order error weights e5 of the estimate; stages 14-16 and the
 * weights d4..d7 of the continuous extension).  Stage 13 is f(t + h, y(t + h)), which is also the first
 * stage of the next step.
 *
 * The error estimate is the 5th-order one of dop853.f, per component
 * (GSL's controls take a vector of estimates):
 *     err_i = h |e5_i|,  e5_i = sum_j e5_j k_ji.
 * dop853.f combines it with the 3rd-order estimate e3 = (b8 - b3) . k as
 * h e5^2 / sqrt(e5^2 + 0.01 e3^2), which is of the order of the 8th-order
 * solution's local error; measured against the binary128 reference of
 * tests/reference/ (make bench-steppers), that combination let steps
 * through whose error the global error then carried: on study 1 at rtol
 * 1e-11 the 7th contact put 5.5e-10 into W and e (476 x rk8pd's error at
 * that tolerance; 11 to 476 x over rtol 1e-6 ... 1e-12), with dense output
 * or without, per component or over the norm as dop853.f has it.  With
 * the 5th-order estimate alone the global error is within 0.1 to 7.9 x
 * rk8pd's at every one of those tolerances on the paper's studies, for
 * about 1.1 to 2.1 x the evaluations.
 *
 * The dense output on [t0, t0 + h], with s = (t - t0) / h, s1 = 1 - s:
 *     y(t) = r1 + s (r2 + s1 (r3 + s (r4 + s1 (r5 + s (r6 + s1 (r7 + s r8))))))
 * with r1 = y0, r2 = y1 - y0, r3 = h f0 - r2, r4 = r2 - h f1 - r3 and
 * r5..r8 = h (d4..d7 . k).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "step_common.h"
#include "step_dop853.h"

enum { NSTAGE = 16 };

/* Nodes c_i of the stages 1..16 (index i - 1); stage 12 and 13 are at t + h. */
static const double C[NSTAGE] = {
	0.0,
	0.526001519587677318785587544488e-01,
	0.789002279381515978178381316732e-01,
	0.118350341907227396726757197510e+00,
	0.281649658092772603273242802490e+00,
	0.333333333333333333333333333333e+00,
	0.25e+00,
	0.307692307692307692307692307692e+00,
	0.651282051282051282051282051282e+00,
	0.6e+00,
	0.857142857142857142857142857142e+00,
	1.0,
	1.0,
	0.1e+00,
	0.2e+00,
	0.777777777777777777777777777778e+00,
};

/* A sparse row: the stages (index from 0) it uses and their weights. */
struct row {
	int n;
	int j[9];
	double a[9];
};

/* Rows of the Butcher matrix of stages 2..12 and 14..16 (stage 13 is f at the end). */
static const struct row A[NSTAGE] = {
	[1] = { 1, { 0 }, { 5.26001519587677318785587544488e-2 } },
	[2] = { 2, { 0, 1 }, { 1.97250569845378994544595329183e-2,
	                       5.91751709536136983633785987549e-2 } },
	[3] = { 2, { 0, 2 }, { 2.95875854768068491816892993775e-2,
	                       8.87627564304205475450678981324e-2 } },
	[4] = { 3, { 0, 2, 3 }, { 2.41365134159266685502369798665e-1,
	                          -8.84549479328286085344864962717e-1,
	                          9.24834003261792003115737966543e-1 } },
	[5] = { 3, { 0, 3, 4 }, { 3.7037037037037037037037037037e-2,
	                          1.70828608729473871279604482173e-1,
	                          1.25467687566822425016691814123e-1 } },
	[6] = { 4, { 0, 3, 4, 5 }, { 3.7109375e-2,
	                             1.70252211019544039314978060272e-1,
	                             6.02165389804559606850219397283e-2,
	                             -1.7578125e-2 } },
	[7] = { 5, { 0, 3, 4, 5, 6 }, { 3.70920001185047927108779319836e-2,
	                                1.70383925712239993810214054705e-1,
	                                1.07262030446373284651809199168e-1,
	                                -1.53194377486244017527936158236e-2,
	                                8.27378916381402288758473766002e-3 } },
	[8] = { 6, { 0, 3, 4, 5, 6, 7 }, { 6.24110958716075717114429577812e-1,
	                                   -3.36089262944694129406857109825e0,
	                                   -8.68219346841726006818189891453e-1,
	                                   2.75920996994467083049415600797e1,
	                                   2.01540675504778934086186788979e1,
	                                   -4.34898841810699588477366255144e1 } },
	[9] = { 7, { 0, 3, 4, 5, 6, 7, 8 }, { 4.77662536438264365890433908527e-1,
	                                      -2.48811461997166764192642586468e0,
	                                      -5.90290826836842996371446475743e-1,
	                                      2.12300514481811942347288949897e1,
	                                      1.52792336328824235832596922938e1,
	                                      -3.32882109689848629194453265587e1,
	                                      -2.03312017085086261358222928593e-2 } },
	[10] = { 8, { 0, 3, 4, 5, 6, 7, 8, 9 }, { -9.3714243008598732571704021658e-1,
	                                          5.18637242884406370830023853209e0,
	                                          1.09143734899672957818500254654e0,
	                                          -8.14978701074692612513997267357e0,
	                                          -1.85200656599969598641566180701e1,
	                                          2.27394870993505042818970056734e1,
	                                          2.49360555267965238987089396762e0,
	                                          -3.0467644718982195003823669022e0 } },
	[11] = { 9, { 0, 3, 4, 5, 6, 7, 8, 9, 10 }, { 2.27331014751653820792359768449e0,
	                                              -1.05344954667372501984066689879e1,
	                                              -2.00087205822486249909675718444e0,
	                                              -1.79589318631187989172765950534e1,
	                                              2.79488845294199600508499808837e1,
	                                              -2.85899827713502369474065508674e0,
	                                              -8.87285693353062954433549289258e0,
	                                              1.23605671757943030647266201528e1,
	                                              6.43392746015763530355970484046e-1 } },
	[13] = { 8, { 0, 6, 7, 8, 9, 10, 11, 12 }, { 5.61675022830479523392909219681e-2,
	                                             2.53500210216624811088794765333e-1,
	                                             -2.46239037470802489917441475441e-1,
	                                             -1.24191423263816360469010140626e-1,
	                                             1.5329179827876569731206322685e-1,
	                                             8.20105229563468988491666602057e-3,
	                                             7.56789766054569976138603589584e-3,
	                                             -8.298e-3 } },
	[14] = { 8, { 0, 5, 6, 7, 10, 11, 12, 13 }, { 3.18346481635021405060768473261e-2,
	                                              2.83009096723667755288322961402e-2,
	                                              5.35419883074385676223797384372e-2,
	                                              -5.49237485713909884646569340306e-2,
	                                              -1.08347328697249322858509316994e-4,
	                                              3.82571090835658412954920192323e-4,
	                                              -3.40465008687404560802977114492e-4,
	                                              1.41312443674632500278074618366e-1 } },
	[15] = { 8, { 0, 5, 6, 7, 8, 12, 13, 14 }, { -4.28896301583791923408573538692e-1,
	                                             -4.69762141536116384314449447206e0,
	                                             7.68342119606259904184240953878e0,
	                                             4.06898981839711007970213554331e0,
	                                             3.56727187455281109270669543021e-1,
	                                             -1.39902416515901462129418009734e-3,
	                                             2.9475147891527723389556272149e0,
	                                             -9.15095847217987001081870187138e0 } },
};

/* Weights of the 8th-order solution (stages 1, 6..12). */
static const struct row B8 = { 8, { 0, 5, 6, 7, 8, 9, 10, 11 }, {
	5.42937341165687622380535766363e-2, 4.45031289275240888144113950566e0,
	1.89151789931450038304281599044e0, -5.8012039600105847814672114227e0,
	3.1116436695781989440891606237e-1, -1.52160949662516078556178806805e-1,
	2.01365400804030348374776537501e-1, 4.47106157277725905176885569043e-2 } };

/* The 5th-order error weights (stages 1, 6..12). */
static const struct row E5 = { 8, { 0, 5, 6, 7, 8, 9, 10, 11 }, {
	0.1312004499419488073250102996e-01, -0.1225156446376204440720569753e+01,
	-0.4957589496572501915214079952e+00, 0.1664377182454986536961530415e+01,
	-0.3503288487499736816886487290e+00, 0.3341791187130174790297318841e+00,
	0.8192320648511571246570742613e-01, -0.2235530786388629525884427845e-01 } };

/* Weights d4..d7 of the continuous extension (stages 1, 6..16). */
static const double D[4][12] = {
	{ -0.84289382761090128651353491142e+01, 0.56671495351937776962531783590e+00,
	  -0.30689499459498916912797304727e+01, 0.23846676565120698287728149680e+01,
	  0.21170345824450282767155149946e+01, -0.87139158377797299206789907490e+00,
	  0.22404374302607882758541771650e+01, 0.63157877876946881815570249290e+00,
	  -0.88990336451333310820698117400e-01, 0.18148505520854727256656404962e+02,
	  -0.91946323924783554000451984436e+01, -0.44360363875948939664310572000e+01 },
	{ 0.10427508642579134603413151009e+02, 0.24228349177525818288430175319e+03,
	  0.16520045171727028198505394887e+03, -0.37454675472269020279518312152e+03,
	  -0.22113666853125306036270938578e+02, 0.77334326684722638389603898808e+01,
	  -0.30674084731089398182061213626e+02, -0.93321305264302278729567221706e+01,
	  0.15697238121770843886131091075e+02, -0.31139403219565177677282850411e+02,
	  -0.93529243588444783865713862664e+01, 0.35816841486394083752465898540e+02 },
	{ 0.19985053242002433820987653617e+02, -0.38703730874935176555105901742e+03,
	  -0.18917813819516756882830838328e+03, 0.52780815920542364900561016686e+03,
	  -0.11573902539959630126141871134e+02, 0.68812326946963000169666922661e+01,
	  -0.10006050966910838403183860980e+01, 0.77771377980534432092869265740e+00,
	  -0.27782057523535084065932004339e+01, -0.60196695231264120758267380846e+02,
	  0.84320405506677161018159903784e+02, 0.11992291136182789328035130030e+02 },
	{ -0.25693933462703749003312586129e+02, -0.15418974869023643374053993627e+03,
	  -0.23152937917604549567536039109e+03, 0.35763911791061412378285349910e+03,
	  0.93405324183624310003907691704e+02, -0.37458323136451633156875139351e+02,
	  0.10409964950896230045147246184e+03, 0.29840293426660503123344363579e+02,
	  -0.43533456590011143754432175058e+02, 0.96324553959188282948394950600e+02,
	  -0.39177261675615439165231486172e+02, -0.14972683625798562581422125276e+03 },
};
/* The stages the columns of D weigh. */
static const int DJ[12] = { 0, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15 };

struct dop853 {
	double *mem;        /* first: the block of every vector below (step_common.h) */
	size_t dim;
	double *k[NSTAGE];  /* the stages, dim values each */
	double *y0;         /* the last step's start */
	double *y1;         /* its end */
	double *ytmp;
	double *r[8];       /* the dense output's coefficients */
	double t0, h;       /* the last step */
	int have_step;      /* a step was made since the last reset */
	int have_dense;     /* r[] is of that step */
	int fsal;           /* k[12] is f at (tf, yf = y1) */
	double tf;
	const gsl_odeiv2_system *sys;
};

/*
 * out = sum_m a_m k_{j_m} (y == NULL), or out = y + h sum_m a_m k_{j_m}:
 * one pass over the components with the row's own terms (1 to 9) summed
 * left to right in registers, as GSL's rk8pd writes its stages out.
 */
#define TERMS1 a[0] * p[0][i]
#define TERMS2 TERMS1 + a[1] * p[1][i]
#define TERMS3 TERMS2 + a[2] * p[2][i]
#define TERMS4 TERMS3 + a[3] * p[3][i]
#define TERMS5 TERMS4 + a[4] * p[4][i]
#define TERMS6 TERMS5 + a[5] * p[5][i]
#define TERMS7 TERMS6 + a[6] * p[6][i]
#define TERMS8 TERMS7 + a[7] * p[7][i]
#define TERMS9 TERMS8 + a[8] * p[8][i]
#define PASS(terms)                                          \
	do {                                                 \
		if (y != NULL)                               \
			for (i = 0; i < dim; i++)            \
				out[i] = y[i] + h * (terms); \
		else                                         \
			for (i = 0; i < dim; i++)            \
				out[i] = terms;              \
	} while (0)

static void
lincomb(const struct dop853 *st, const struct row *r, const double *y, double h, double *out)
{
	const size_t dim = st->dim;
	const double *p[9];
	double a[9];
	size_t i;

	for (int m = 0; m < r->n; m++) {
		p[m] = st->k[r->j[m]];
		a[m] = r->a[m];
	}
	switch (r->n) {
	case 1: PASS(TERMS1); break;
	case 2: PASS(TERMS2); break;
	case 3: PASS(TERMS3); break;
	case 4: PASS(TERMS4); break;
	case 5: PASS(TERMS5); break;
	case 6: PASS(TERMS6); break;
	case 7: PASS(TERMS7); break;
	case 8: PASS(TERMS8); break;
	default: PASS(TERMS9); break;
	}
}

/* out = y + h sum_m a_m k_{j_m}. */
static void
combine(const struct dop853 *st, const double *y, double h, const struct row *r, double *out)
{
	lincomb(st, r, y, h, out);
}

static int
eval(const gsl_odeiv2_system *sys, double t, const double *y, double *f)
{
	return sys->function(t, y, f, sys->params);
}

static void *
dop853_alloc(size_t dim)
{
	struct dop853 *st = step_state_alloc(sizeof *st, NSTAGE + 3 + 8, dim);
	int i;

	if (st == NULL)
		return NULL;
	st->dim = dim;
	for (i = 0; i < NSTAGE; i++)
		st->k[i] = st->mem + (size_t)i * dim;
	st->y0 = st->mem + (size_t)NSTAGE * dim;
	st->y1 = st->y0 + dim;
	st->ytmp = st->y1 + dim;
	for (i = 0; i < 8; i++)
		st->r[i] = st->ytmp + (size_t)(i + 1) * dim;
	return st;
}

static int
dop853_apply(void *state, size_t dim, double t, double h, double y[], double yerr[],
             const double dydt_in[], double dydt_out[], const gsl_odeiv2_system *sys)
{
	struct dop853 *st = state;
	size_t i;
	int s, rc;

	st->have_step = st->have_dense = 0;
	memcpy(st->y0, y, dim * sizeof *y);
	/* stage 1: given, kept from the last step (first same as last), or evaluated */
	if (dydt_in != NULL) {
		memcpy(st->k[0], dydt_in, dim * sizeof *y);
	} else if (st->fsal && st->sys == sys && st->tf == t && !memcmp(st->y1, y, dim * sizeof *y)) {
		memcpy(st->k[0], st->k[12], dim * sizeof *y);
	} else if ((rc = eval(sys, t, y, st->k[0])) != GSL_SUCCESS) {
		st->fsal = 0;
		return rc;
	}
	st->fsal = 0;
	st->sys = sys;
	for (s = 1; s < 12; s++) {
		combine(st, st->y0, h, &A[s], st->ytmp);
		if ((rc = eval(sys, s == 11 ? t + h : t + C[s] * h, st->ytmp, st->k[s])) != GSL_SUCCESS)
			return rc;
	}
	/*
	 * In one pass: the 8th-order increment b8, the solution, and the
	 * estimate from e5 (B8 and E5 weigh stages 1, 6..12; each sum left to
	 * right, as lincomb would).
	 */
	{
		double *const *k = st->k;

		for (i = 0; i < dim; i++) {
			double b8 = B8.a[0] * k[0][i] + B8.a[1] * k[5][i] + B8.a[2] * k[6][i] +
			            B8.a[3] * k[7][i] + B8.a[4] * k[8][i] + B8.a[5] * k[9][i] +
			            B8.a[6] * k[10][i] + B8.a[7] * k[11][i];
			double e5 = E5.a[0] * k[0][i] + E5.a[1] * k[5][i] + E5.a[2] * k[6][i] +
			            E5.a[3] * k[7][i] + E5.a[4] * k[8][i] + E5.a[5] * k[9][i] +
			            E5.a[6] * k[10][i] + E5.a[7] * k[11][i];

			st->y1[i] = st->y0[i] + h * b8;
			yerr[i] = fabs(h * e5);
		}
	}
	/* stage 13: f at the end, the next step's first stage */
	if ((rc = eval(sys, t + h, st->y1, st->k[12])) != GSL_SUCCESS)
		return rc;
	memcpy(y, st->y1, dim * sizeof *y);
	if (dydt_out != NULL)
		memcpy(dydt_out, st->k[12], dim * sizeof *y);
	st->t0 = t;
	st->h = h;
	st->tf = t + h;
	st->fsal = 1;
	st->have_step = 1;
	return GSL_SUCCESS;
}

/* Stages 14-16 and the coefficients r1..r8 of the last step. */
static int
prepare_dense(struct dop853 *st)
{
	const double h = st->h;
	size_t i;
	int s, rc, q, m;

	for (s = 13; s < 16; s++) {
		combine(st, st->y0, h, &A[s], st->ytmp);
		if ((rc = eval(st->sys, st->t0 + C[s] * h, st->ytmp, st->k[s])) != GSL_SUCCESS)
			return rc;
	}
	for (i = 0; i < st->dim; i++) {
		double dy = st->y1[i] - st->y0[i], bspl = h * st->k[0][i] - dy;

		st->r[0][i] = st->y0[i];
		st->r[1][i] = dy;
		st->r[2][i] = bspl;
		st->r[3][i] = dy - h * st->k[12][i] - bspl;
		for (q = 0; q < 4; q++) {
			double acc = 0.0;

			for (m = 0; m < 12; m++)
				acc += D[q][m] * st->k[DJ[m]][i];
			st->r[4 + q][i] = h * acc;
		}
	}
	st->have_dense = 1;
	return GSL_SUCCESS;
}

int
hb_dop853_dense(gsl_odeiv2_step *step, double t, double y[])
{
	struct dop853 *st;
	double s, s1;
	size_t i;
	int rc;

	if (step == NULL || step->type != hb_step_dop853)
		return GSL_EINVAL;
	st = step->state;
	if (!st->have_step)
		return GSL_EINVAL;
	if (!st->have_dense && (rc = prepare_dense(st)) != GSL_SUCCESS)
		return rc;
	s = (t - st->t0) / st->h;
	s1 = 1.0 - s;
	for (i = 0; i < st->dim; i++) {
		double *const *r = st->r;

		y[i] = r[0][i] + s * (r[1][i] + s1 * (r[2][i] + s * (r[3][i] + s1 * (r[4][i] +
		       s * (r[5][i] + s1 * (r[6][i] + s * r[7][i]))))));
	}
	return GSL_SUCCESS;
}

int
hb_dop853_last(const gsl_odeiv2_step *step, double *t0, double *h)
{
	const struct dop853 *st;

	if (step == NULL || step->type != hb_step_dop853)
		return -1;
	st = step->state;
	if (!st->have_step)
		return -1;
	*t0 = st->t0;
	*h = st->h;
	return 0;
}

static int
dop853_reset(void *state, size_t dim)
{
	struct dop853 *st = state;

	(void)dim;
	st->have_step = st->have_dense = st->fsal = 0;
	return GSL_SUCCESS;
}

STEP_TYPE(dop853_type, "dop853", 0, 1, dop853_alloc, dop853_apply, dop853_reset, step_order8);

const gsl_odeiv2_step_type *const hb_step_dop853 = &dop853_type;
