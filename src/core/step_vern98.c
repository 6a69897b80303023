/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * step_vern98.c - Verner's "most efficient" 9(8) pair as a GSL odeiv2 step
 * type (see step_vern98.h).
 *
 * Coefficients: J. H. Verner, "Explicit Runge-Kutta pairs with lower
 * stage-order", Numerical Algorithms 65 (2014) 555-577, the efficient
 * 16-stage 9(8) pair, in the 40-digit decimal table of Verner's own data
 * (people.math.sfu.ca/~jverner/) as it is reproduced in open-source codes
 * (Julia's OrdinaryDiffEq Vern9 tableau; PyODEPack's verner98e.h and
 * several others agree digit for digit on the entries compared).  Only the
 * 16 stages of the pair are used here, not the 10 more of Verner's
 * interpolant.
 *
 * Checked: in 50-digit arithmetic the weights b satisfy every one of the
 * 719 order conditions (rooted trees) up to order 9 to 3e-40, and the
 * embedded weights b + e every one up to order 8 (but not all of order 9,
 * residual 1.4e-5), so the pair is of order 9 with an 8th-order embedded
 * solution; the rows sum to the nodes c to 2e-39.  tests/test_vern98.c
 * measures the orders in double precision (global error ~ h^9, the
 * estimate of one step ~ h^9).
 *
 * The error estimate, per component (GSL's controls take a vector):
 *     err_i = h |sum_j e_j k_ji|,  e = b(8th order) - b(9th order),
 * the local error of the 8th-order solution while the step advances with
 * the 9th (local extrapolation, as rk8pd and dop853 do).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "step_common.h"
#include "step_vern98.h"

enum { NSTAGE = 16, MAXTERM = 10 };

/* A sparse row: the stages (index from 0) it uses and their weights. */
struct row {
	int n;
	int j[MAXTERM];
	double a[MAXTERM];
};

/* Nodes c_i of the stages 1..16 (index i - 1); stages 15 and 16 are at t + h. */
static const double C[NSTAGE] = {
	0.0,
	0.03462,
	0.09702435063878044594828361677100617517633,
	0.1455365259581706689224254251565092627645,
	0.561,
	0.2290079115904850126662751771814700052182,
	0.5449920884095149873337248228185299947818,
	0.645,
	0.48375,
	0.06757,
	0.25,
	0.6590650618730998549405331618649220295334,
	0.8206,
	0.9012,
	1.0,
	1.0,
};

/* Rows of the Butcher matrix, stages 2..16 (index from 0: the stages a row uses, their weights). */
static const struct row A[NSTAGE] = {
	[1] = { 1, { 0 }, {
		0.03462,
	} },
	[2] = { 2, { 0, 1 }, {
		-0.0389335438857287327017042687229284478532,
		0.1359578945245091786499878854939346230295,
	} },
	[3] = { 2, { 0, 2 }, {
		0.03638413148954266723060635628912731569111,
		0.1091523944686280016918190688673819470733,
	} },
	[4] = { 3, { 0, 2, 3 }, {
		2.025763914393969636805657604282571047511,
		-7.638023836496292020387602153091964592952,
		6.173259922102322383581944548809393545442,
	} },
	[5] = { 3, { 0, 3, 4 }, {
		0.05112275589406060872792270881648288397197,
		0.1770823794555021537929910813839068684087,
		0.00080277624092225014536138698108025283759,
	} },
	[6] = { 4, { 0, 3, 4, 5 }, {
		0.1316006357975216279279871693164256985334,
		-0.2957276252669636417685183174672273730699,
		0.0878137803564295237421124704053886667082,
		0.6213052975225274774321435005639430026100,
	} },
	[7] = { 3, { 0, 5, 6 }, {
		0.07166666666666666666666666666666666666667,
		0.3305533578915319409260346730051472207728,
		0.2427799754418013924072986603281861125606,
	} },
	[8] = { 4, { 0, 5, 6, 7 }, {
		0.071806640625,
		0.3294380283228177160744825466257672816401,
		0.1165190029271822839255174533742327183599,
		-0.034013671875,
	} },
	[9] = { 5, { 0, 5, 6, 7, 8 }, {
		0.04836757646340646986611287718844085773549,
		0.03928989925676163974333190042057047002852,
		0.1054740945890344608263649267140088017604,
		-0.02143865284648312665982642293830533996214,
		-0.1041229174627194437759832813847147895623,
	} },
	[10] = { 6, { 0, 5, 6, 7, 8, 9 }, {
		-0.02664561487201478635337289243849737340534,
		0.03333333333333333333333333333333333333333,
		-0.1631072244872467239162704487554706387141,
		0.03396081684127761199487954930015522928244,
		0.1572319413814626097110769806810024118077,
		0.2152267478031879552303534778794770376960,
	} },
	[11] = { 7, { 0, 5, 6, 7, 8, 9, 10 }, {
		0.03689009248708622334786359863227633989718,
		-0.1465181576725542928653609891758501156785,
		0.2242577768172024345345469822625833796001,
		0.02294405717066072637090897902753790803034,
		-0.0035850052905728761357394424889330334334,
		0.08669223316444385506869203619044453906053,
		0.4383840651968337846196219974168630120572,
	} },
	[12] = { 8, { 0, 5, 6, 7, 8, 9, 10, 11 }, {
		-0.4866012215113340846662212357570395295088,
		-6.304602650282852990657772792012007122988,
		-0.281245618289472564778284183790118418111,
		-2.679019236219849057687906597489223155566,
		0.518815663924157511565311164615012522024,
		1.365353187603341710683633635235238678626,
		5.885091088503946585721274891680604830712,
		2.802808786272062889819965117517532194812,
	} },
	[13] = { 9, { 0, 5, 6, 7, 8, 9, 10, 11, 12 }, {
		0.4185367457753471441471025246471931649633,
		6.724547581906459363100870806514855026676,
		-0.425444280164611790606983409697113064616,
		3.343279153001265577811816947557982637749,
		0.617081663117537759528421117507709784737,
		-0.929966123939932833937749523988800852013,
		-6.099948804751010722472962837945508844846,
		-3.002206187889399044804158084895173690015,
		0.2553202529443445472336424602988558373637,
	} },
	[14] = { 10, { 0, 5, 6, 7, 8, 9, 10, 11, 12, 13 }, {
		-0.779374086122884664644623040843840506343,
		-13.93734253810777678786523664804936051203,
		1.252048853379357320949735183924200895136,
		-14.69150040801686878191527989293072091588,
		-0.494705058533141685655191992136962873577,
		2.242974909146236657906984549543692874755,
		13.36789380382864375813864978592679139881,
		14.39665048665068644512236935340272139005,
		-0.7975813331776800379127866056663258667437,
		0.4409353709534277758753793068298041158235,
	} },
	[15] = { 9, { 0, 5, 6, 7, 8, 9, 10, 11, 12 }, {
		2.058051337466886442151242368989994043993,
		22.35793772796803295519317565842520212899,
		0.90949810997556332745009198137971890783,
		35.89110098240264104710550686568482456493,
		-3.442515027624453437985000403608480262211,
		-4.865481358036368826566013387928704014496,
		-18.90980381354342625688427480879773032857,
		-34.26354448030451782929251177395134170515,
		1.264756521695642578827783499806516664686,
	} },
};

/* The weights of the 9th-order solution (stages 1, 8..15). */
static const struct row B9 = { 9, { 0, 7, 8, 9, 10, 11, 12, 13, 14 }, {
	0.01461197685842315252051541915018784713459,
	-0.3915211862331339089410228267288242030810,
	0.2310932500289506415909675644868993669908,
	0.1274766769992852382560589467488989175618,
	0.2246434176204157731566981937082069688984,
	0.5684352689748512932705226972873692126743,
	0.05825871557215827200814768021863420902155,
	0.1364317403482215641609022744494239843327,
	0.03057013983082797397721005067920369646664,
} };

/* The 8th-order solution's weights less the 9th's (stages 1, 8..16): the error estimate. */
static const struct row E8 = { 10, { 0, 7, 8, 9, 10, 11, 12, 13, 14, 15 }, {
	0.005357988290444578334669665030800840430050,
	2.583020491182463963471769926039661727945,
	-0.1425225315468662612826303441690357783613,
	-0.01342065351268867600756328623975571429440,
	0.02867296291409493339975957974875822883630,
	-2.624999655215792304429522291883350513167,
	0.2825509643291537215078618092038201722614,
	-0.1364317403482215641609022744494239843327,
	-0.03057013983082797397721005067920369646664,
	0.04834231373823958314376726739772871714902,
} };

struct vern98 {
	double *mem;           /* first: the block of every vector below (step_common.h) */
	size_t dim;
	double *k[NSTAGE + 1]; /* the stages, dim values each; k[16]: f at the end */
	double *y0;            /* the last step's start */
	double *y1;            /* its end */
	double *ytmp;
	double t0, tf;         /* the last step's start and end */
	int have_k0;           /* k[0] is f at (t0, y0) */
	int fsal;              /* k[16] is f at (tf, y1) */
	const gsl_odeiv2_system *sys;
};

/*
 * out = y + h sum_m a_m k_{j_m}: one pass over the components with the
 * row's own terms (1 to 10) summed left to right in registers.
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
#define TERMS10 TERMS9 + a[9] * p[9][i]
#define PASS(terms)                              \
	do {                                     \
		for (i = 0; i < dim; i++)        \
			out[i] = y[i] + h * (terms); \
	} while (0)

/*
 * Inlined into each stage with its row a constant, so that the number of
 * terms, the stages and the weights are known where the loop is compiled.
 */
static inline __attribute__((always_inline)) void
combine(const struct vern98 *st, const double *y, double h, const struct row *r, double *out)
{
	const size_t dim = st->dim;
	const double *p[MAXTERM];
	double a[MAXTERM];
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
	case 9: PASS(TERMS9); break;
	default: PASS(TERMS10); break;
	}
}

static int
eval(const gsl_odeiv2_system *sys, double t, const double *y, double *f)
{
	return sys->function(t, y, f, sys->params);
}

static void *
vern98_alloc(size_t dim)
{
	struct vern98 *st = step_state_alloc(sizeof *st, NSTAGE + 1 + 3, dim);
	int i;

	if (st == NULL)
		return NULL;
	st->dim = dim;
	for (i = 0; i <= NSTAGE; i++)
		st->k[i] = st->mem + (size_t)i * dim;
	st->y0 = st->mem + (size_t)(NSTAGE + 1) * dim;
	st->y1 = st->y0 + dim;
	st->ytmp = st->y1 + dim;
	return st;
}

static int
vern98_apply(void *state, size_t dim, double t, double h, double y[], double yerr[],
             const double dydt_in[], double dydt_out[], const gsl_odeiv2_system *sys)
{
	struct vern98 *st = state;
	const size_t bytes = dim * sizeof *y;
	double *const *k = st->k;
	size_t i;
	int rc;

	/*
	 * stage 1: given; the last step's end (first same as last); the last
	 * step's own first stage when that step is taken again shorter (after
	 * a rejection); or evaluated
	 */
	if (dydt_in != NULL) {
		memcpy(k[0], dydt_in, bytes);
	} else if (st->fsal && st->sys == sys && st->tf == t && !memcmp(st->y1, y, bytes)) {
		memcpy(k[0], k[NSTAGE], bytes);
	} else if (st->have_k0 && st->sys == sys && st->t0 == t && !memcmp(st->y0, y, bytes)) {
		/* k[0] is still f(t, y) */
	} else if ((rc = eval(sys, t, y, k[0])) != GSL_SUCCESS) {
		st->have_k0 = st->fsal = 0;
		return rc;
	}
	memcpy(st->y0, y, bytes);
	st->t0 = t;
	st->sys = sys;
	st->have_k0 = 1;
	st->fsal = 0;
	/* stages 2..16, written out (see combine) */
#define STAGE(s)                                                                          \
	do {                                                                              \
		combine(st, st->y0, h, &A[s], st->ytmp);                                  \
		if ((rc = eval(sys, (s) >= 14 ? t + h : t + C[s] * h, st->ytmp, k[s])) != \
		    GSL_SUCCESS)                                                          \
			return rc;                                                        \
	} while (0)
	STAGE(1); STAGE(2); STAGE(3); STAGE(4); STAGE(5);
	STAGE(6); STAGE(7); STAGE(8); STAGE(9); STAGE(10);
	STAGE(11); STAGE(12); STAGE(13); STAGE(14); STAGE(15);
#undef STAGE
	/* In one pass: the 9th-order solution and the estimate (sums left to right). */
	for (i = 0; i < dim; i++) {
		double b9 = B9.a[0] * k[0][i] + B9.a[1] * k[7][i] + B9.a[2] * k[8][i] +
		            B9.a[3] * k[9][i] + B9.a[4] * k[10][i] + B9.a[5] * k[11][i] +
		            B9.a[6] * k[12][i] + B9.a[7] * k[13][i] + B9.a[8] * k[14][i];
		double e8 = E8.a[0] * k[0][i] + E8.a[1] * k[7][i] + E8.a[2] * k[8][i] +
		            E8.a[3] * k[9][i] + E8.a[4] * k[10][i] + E8.a[5] * k[11][i] +
		            E8.a[6] * k[12][i] + E8.a[7] * k[13][i] + E8.a[8] * k[14][i] +
		            E8.a[9] * k[15][i];

		st->y1[i] = st->y0[i] + h * b9;
		yerr[i] = fabs(h * e8);
	}
	/* f at the end, the next step's first stage */
	if ((rc = eval(sys, t + h, st->y1, k[NSTAGE])) != GSL_SUCCESS)
		return rc;
	memcpy(y, st->y1, bytes);
	if (dydt_out != NULL)
		memcpy(dydt_out, k[NSTAGE], bytes);
	st->tf = t + h;
	st->fsal = 1;
	return GSL_SUCCESS;
}

static int
vern98_reset(void *state, size_t dim)
{
	struct vern98 *st = state;

	(void)dim;
	st->have_k0 = st->fsal = 0;
	return GSL_SUCCESS;
}

void
hb_vern98_tableau(double a[16][16], double c[16], double b[16], double e[16])
{
	memset(a, 0, 16 * sizeof a[0]);
	memset(b, 0, 16 * sizeof b[0]);
	memset(e, 0, 16 * sizeof e[0]);
	for (int i = 0; i < NSTAGE; i++) {
		c[i] = C[i];
		for (int m = 0; m < A[i].n; m++)
			a[i][A[i].j[m]] = A[i].a[m];
	}
	for (int m = 0; m < B9.n; m++)
		b[B9.j[m]] = B9.a[m];
	for (int m = 0; m < E8.n; m++)
		e[E8.j[m]] = E8.a[m];
}

STEP_TYPE(vern98_type, "vern98", 0, 1, vern98_alloc, vern98_apply, vern98_reset, step_order9);

const gsl_odeiv2_step_type *const hb_step_vern98 = &vern98_type;
