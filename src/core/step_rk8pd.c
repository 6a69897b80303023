/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * step_rk8pd.c - Prince and Dormand's 8(7) pair as a GSL odeiv2 step type
 * that rounds as GSL's rk8pd (see step_rk8pd.h).
 *
 * Coefficients: P. J. Prince and J. R. Dormand, "High order embedded
 * Runge-Kutta formulae", J. Comp. Appl. Math. 7 (1981) 67-75, written as
 * GSL 2.7's ode-initval2/rk8pd.c writes them (the same quotients of
 * integers, so the same doubles).
 *
 * Bit for bit: every stage is y + h (sum of its terms, left to right) with
 * GSL's terms, zero weights left out where GSL leaves them out and kept
 * where it keeps them (b13's last, 0 x k12, which makes a NaN or the sign
 * of a zero as GSL's does); the 8th-order sum is formed once and used both
 * for y and for the estimate h (ksum7 - ksum8), as GSL forms it twice with
 * the same operations.  The components go through each operation two or
 * four at a time, in packed doubles (GCC's vector extension: SSE2, or AVX
 * where the processor has it, chosen when the step is allocated): a
 * packed product or sum rounds each lane as the scalar one does.  No
 * a * b + c is contracted into an fma (ISO C mode, -ffp-contract=off, and
 * the AVX copy is built for AVX alone, not FMA), as GSL's own x86-64 build
 * contracts none.  tests/test_step_rk8pd.c compares every double of both
 * copies with gsl_odeiv2_step_rk8pd's.
 *
 * What it saves against GSL's generic loops: the stages are in one
 * buffer, padded to whole vectors and aligned, so a stage is a few packed
 * operations per term (AVX: a product with the stage read from memory and
 * a sum); each dimension of the engine's layouts (3 to 12) has its own
 * copy with every address a constant offset and the loops unrolled; the
 * 8th-order sum is formed once; dydt_in and y are copied in as GSL copies
 * them, and y is changed only once f at the end is known (where GSL
 * restores it).  On the paper's studies: GSL's rk8pd_apply took 183-233
 * instructions per evaluation of f, this one 52-53 with AVX
 * (tests/bench/REPORT.md, "The engine at its limit").
 */
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "step_common.h"
#include "step_rk8pd.h"

/* GSL's Prince-Dormand constants (ode-initval2/rk8pd.c), under its names. */

static const double Abar[] = {
	14005451.0 / 335480064.0,
	0.0,
	0.0,
	0.0,
	0.0,
	-59238493.0 / 1068277825.0,
	181606767.0 / 758867731.0,
	561292985.0 / 797845732.0,
	-1041891430.0 / 1371343529.0,
	760417239.0 / 1151165299.0,
	118820643.0 / 751138087.0,
	-528747749.0 / 2220607170.0,
	1.0 / 4.0,
};

static const double A[] = {
	13451932.0 / 455176623.0,
	0.0,
	0.0,
	0.0,
	0.0,
	-808719846.0 / 976000145.0,
	1757004468.0 / 5645159321.0,
	656045339.0 / 265891186.0,
	-3867574721.0 / 1518517206.0,
	465885868.0 / 322736535.0,
	53011238.0 / 667516719.0,
	2.0 / 45.0,
};

static const double ah[] = {
	1.0 / 18.0,
	1.0 / 12.0,
	1.0 / 8.0,
	5.0 / 16.0,
	3.0 / 8.0,
	59.0 / 400.0,
	93.0 / 200.0,
	5490023248.0 / 9719169821.0,
	13.0 / 20.0,
	1201146811.0 / 1299019798.0,
};

static const double b21 = 1.0 / 18.0;
static const double b3[] = { 1.0 / 48.0, 1.0 / 16.0 };
static const double b4[] = { 1.0 / 32.0, 0.0, 3.0 / 32.0 };
static const double b5[] = { 5.0 / 16.0, 0.0, -75.0 / 64.0, 75.0 / 64.0 };
static const double b6[] = { 3.0 / 80.0, 0.0, 0.0, 3.0 / 16.0, 3.0 / 20.0 };
static const double b7[] = {
	29443841.0 / 614563906.0, 0.0, 0.0, 77736538.0 / 692538347.0, -28693883.0 / 1125000000.0,
	23124283.0 / 1800000000.0,
};
static const double b8[] = {
	16016141.0 / 946692911.0, 0.0, 0.0, 61564180.0 / 158732637.0, 22789713.0 / 633445777.0,
	545815736.0 / 2771057229.0, -180193667.0 / 1043307555.0,
};
static const double b9[] = {
	39632708.0 / 573591083.0, 0.0, 0.0, -433636366.0 / 683701615.0, -421739975.0 / 2616292301.0,
	100302831.0 / 723423059.0, 790204164.0 / 839813087.0, 800635310.0 / 3783071287.0,
};
static const double b10[] = {
	246121993.0 / 1340847787.0, 0.0, 0.0, -37695042795.0 / 15268766246.0,
	-309121744.0 / 1061227803.0, -12992083.0 / 490766935.0, 6005943493.0 / 2108947869.0,
	393006217.0 / 1396673457.0, 123872331.0 / 1001029789.0,
};
static const double b11[] = {
	-1028468189.0 / 846180014.0, 0.0, 0.0, 8478235783.0 / 508512852.0,
	1311729495.0 / 1432422823.0, -10304129995.0 / 1701304382.0, -48777925059.0 / 3047939560.0,
	15336726248.0 / 1032824649.0, -45442868181.0 / 3398467696.0, 3065993473.0 / 597172653.0,
};
static const double b12[] = {
	185892177.0 / 718116043.0, 0.0, 0.0, -3185094517.0 / 667107341.0,
	-477755414.0 / 1098053517.0, -703635378.0 / 230739211.0, 5731566787.0 / 1027545527.0,
	5232866602.0 / 850066563.0, -4093664535.0 / 808688257.0, 3962137247.0 / 1805957418.0,
	65686358.0 / 487910083.0,
};
static const double b13[] = {
	403863854.0 / 491063109.0, 0.0, 0.0, -5068492393.0 / 434740067.0,
	-411421997.0 / 543043805.0, 652783627.0 / 914296604.0, 11173962825.0 / 925320556.0,
	-13158990841.0 / 6184727034.0, 3936647629.0 / 1978049680.0, -160528059.0 / 685178525.0,
	248638103.0 / 1413531060.0, 0.0,
};

/*
 * The lanes: two doubles (SSE2, any x86-64; GCC's generic vectors
 * elsewhere) or four (AVX, where the processor has it).  The stages live
 * in the step's own buffers, each padded with zeros to a whole number of
 * vectors and aligned to one, so that no component is left over and
 * every load is aligned.
 */
typedef double v2d __attribute__((vector_size(16)));
#if defined(__x86_64__) && defined(__GNUC__)
#define HAVE_AVX 1
typedef double v4d __attribute__((vector_size(32)));
#define AVX __attribute__((target("avx")))
#else
#define HAVE_AVX 0
#endif

struct rk8pd;
typedef int stepfn(struct rk8pd *st, double t, double h, double y[], double yerr[],
                   const double dydt_in[], double dydt_out[], const gsl_odeiv2_system *sys);

/* One block of 17 vectors of pad values each (the padding zero), in this order: */
struct rk8pd {
	double *mem;  /* first: the block of every vector below (step_common.h) */
	size_t dim;
	size_t pad;   /* dim rounded up to the lanes */
	stepfn *step; /* the copy for this dimension and these lanes */
	double *y0;   /* y at the step's start */
	double *k;    /* the 13 stages k1..k13 */
	double *ytmp; /* a stage's trial state */
	double *yend; /* the step's end */
	double *err;  /* its error estimate */
};

/* GSL's stages (ode-initval2/rk8pd.c): the trial state of stage n, the sum left to right. */
#define Y2 AT(y0) + b21 * h * K(1)
#define Y3 AT(y0) + h * (b3[0] * K(1) + b3[1] * K(2))
#define Y4 AT(y0) + h * (b4[0] * K(1) + b4[2] * K(3))
#define Y5 AT(y0) + h * (b5[0] * K(1) + b5[2] * K(3) + b5[3] * K(4))
#define Y6 AT(y0) + h * (b6[0] * K(1) + b6[3] * K(4) + b6[4] * K(5))
#define Y7 AT(y0) + h * (b7[0] * K(1) + b7[3] * K(4) + b7[4] * K(5) + b7[5] * K(6))
#define Y8 AT(y0) + h * (b8[0] * K(1) + b8[3] * K(4) + b8[4] * K(5) + b8[5] * K(6) + b8[6] * K(7))
#define Y9                                                                                      \
	AT(y0) + h * (b9[0] * K(1) + b9[3] * K(4) + b9[4] * K(5) + b9[5] * K(6) + b9[6] * K(7) + \
	              b9[7] * K(8))
#define Y10                                                                                        \
	AT(y0) + h * (b10[0] * K(1) + b10[3] * K(4) + b10[4] * K(5) + b10[5] * K(6) + b10[6] * K(7) + \
	              b10[7] * K(8) + b10[8] * K(9))
#define Y11                                                                                        \
	AT(y0) + h * (b11[0] * K(1) + b11[3] * K(4) + b11[4] * K(5) + b11[5] * K(6) + b11[6] * K(7) + \
	              b11[7] * K(8) + b11[8] * K(9) + b11[9] * K(10))
#define Y12                                                                                        \
	AT(y0) + h * (b12[0] * K(1) + b12[3] * K(4) + b12[4] * K(5) + b12[5] * K(6) + b12[6] * K(7) + \
	              b12[7] * K(8) + b12[8] * K(9) + b12[9] * K(10) + b12[10] * K(11))
#define Y13                                                                                        \
	AT(y0) + h * (b13[0] * K(1) + b13[3] * K(4) + b13[4] * K(5) + b13[5] * K(6) + b13[6] * K(7) + \
	              b13[7] * K(8) + b13[8] * K(9) + b13[9] * K(10) + b13[10] * K(11) +              \
	              b13[11] * K(12))
/* the 8th- and 7th-order sums */
#define KSUM8                                                                                   \
	(Abar[0] * K(1) + Abar[5] * K(6) + Abar[6] * K(7) + Abar[7] * K(8) + Abar[8] * K(9) +   \
	 Abar[9] * K(10) + Abar[10] * K(11) + Abar[11] * K(12) + Abar[12] * K(13))
#define KSUM7                                                                                  \
	(A[0] * K(1) + A[5] * K(6) + A[6] * K(7) + A[7] * K(8) + A[8] * K(9) + A[9] * K(10) + \
	 A[10] * K(11) + A[11] * K(12))

/*
 * One step with the vectors T (a typedef of the function that expands
 * it), dim and pad constants where it is inlined.  AT(p) is the vector of
 * p at component i, K(n) that of stage n; PASS sets out = expr over the
 * vectors; scalars in an expression are broadcast to every lane.
 */
#define AT(p) (*(const T *)((p) + i))
#define K(n) AT(k + ((n) - 1) * pad)
#define PASS(out, expr)                                       \
	do {                                                  \
		_Pragma("GCC unroll 4")                       \
		for (size_t i = 0; i < pad; i += sizeof(T) / sizeof(double)) \
			*(T *)((out) + i) = (expr);           \
	} while (0)
#define EVAL(tt, u, f)                                                                \
	do {                                                                          \
		if ((rc = sys->function((tt), (u), (f), sys->params)) != GSL_SUCCESS) \
			return rc;                                                    \
	} while (0)
#define STEP_BODY                                                                         \
	double *const y0 = st->y0, *const k = st->k, *const ytmp = st->ytmp;              \
	double *const yend = st->yend, *const err = st->err;                              \
	int rc;                                                                           \
                                                                                          \
	memcpy(y0, y, dim * sizeof *y);                                                   \
	if (dydt_in != NULL)                                                              \
		memcpy(k, dydt_in, dim * sizeof *y);                                      \
	else                                                                              \
		EVAL(t, y, k);                                                            \
	PASS(ytmp, Y2);                                                                   \
	EVAL(t + ah[0] * h, ytmp, k + pad);                                               \
	PASS(ytmp, Y3);                                                                   \
	EVAL(t + ah[1] * h, ytmp, k + 2 * pad);                                           \
	PASS(ytmp, Y4);                                                                   \
	EVAL(t + ah[2] * h, ytmp, k + 3 * pad);                                           \
	PASS(ytmp, Y5);                                                                   \
	EVAL(t + ah[3] * h, ytmp, k + 4 * pad);                                           \
	PASS(ytmp, Y6);                                                                   \
	EVAL(t + ah[4] * h, ytmp, k + 5 * pad);                                           \
	PASS(ytmp, Y7);                                                                   \
	EVAL(t + ah[5] * h, ytmp, k + 6 * pad);                                           \
	PASS(ytmp, Y8);                                                                   \
	EVAL(t + ah[6] * h, ytmp, k + 7 * pad);                                           \
	PASS(ytmp, Y9);                                                                   \
	EVAL(t + ah[7] * h, ytmp, k + 8 * pad);                                           \
	PASS(ytmp, Y10);                                                                  \
	EVAL(t + ah[8] * h, ytmp, k + 9 * pad);                                           \
	PASS(ytmp, Y11);                                                                  \
	EVAL(t + ah[9] * h, ytmp, k + 10 * pad);                                          \
	PASS(ytmp, Y12);                                                                  \
	EVAL(t + h, ytmp, k + 11 * pad);                                                  \
	PASS(ytmp, Y13);                                                                  \
	EVAL(t + h, ytmp, k + 12 * pad);                                                  \
	/* the end and the estimate from one 8th-order sum (GSL forms it twice, alike) */ \
	_Pragma("GCC unroll 4")                                                           \
	for (size_t i = 0; i < pad; i += sizeof(T) / sizeof(double)) {                    \
		const T s8 = KSUM8;                                                       \
                                                                                          \
		*(T *)(yend + i) = AT(y0) + h * s8;                                       \
		*(T *)(err + i) = h * (KSUM7 - s8);                                       \
	}                                                                                 \
	/* y is changed only once f at the end is known (as GSL restores it) */           \
	if (dydt_out != NULL)                                                             \
		EVAL(t + h, yend, dydt_out);                                              \
	memcpy(y, yend, dim * sizeof *y);                                                 \
	memcpy(yerr, err, dim * sizeof *y);                                               \
	return GSL_SUCCESS

/* STEPS(lanes, attributes): the copy for each dimension 3..12 and one for any */
#define ONE(lanes, attr, n)                                                                    \
	static attr int step##lanes##_##n(struct rk8pd *st, double t, double h, double y[],    \
	                                  double yerr[], const double dydt_in[], double dydt_out[], \
	                                  const gsl_odeiv2_system *sys)                       \
	{                                                                                      \
		typedef LANES##lanes T;                                                        \
		const size_t dim = n, pad = (n + lanes - 1) / lanes * lanes;                   \
		STEP_BODY;                                                                     \
	}
#define LANES2 v2d
#define LANES4 v4d
#define STEPS(lanes, attr)                                                                     \
	ONE(lanes, attr, 3)                                                                    \
	ONE(lanes, attr, 4)                                                                    \
	ONE(lanes, attr, 5)                                                                    \
	ONE(lanes, attr, 6)                                                                    \
	ONE(lanes, attr, 7)                                                                    \
	ONE(lanes, attr, 8)                                                                    \
	ONE(lanes, attr, 9)                                                                    \
	ONE(lanes, attr, 10)                                                                   \
	ONE(lanes, attr, 11)                                                                   \
	ONE(lanes, attr, 12)                                                                   \
	static attr int step##lanes##_any(struct rk8pd *st, double t, double h, double y[],    \
	                                  double yerr[], const double dydt_in[], double dydt_out[], \
	                                  const gsl_odeiv2_system *sys)                       \
	{                                                                                      \
		typedef LANES##lanes T;                                                        \
		const size_t dim = st->dim, pad = st->pad;                                     \
		STEP_BODY;                                                                     \
	}                                                                                      \
	static stepfn *const steps##lanes[] = {                                                \
		step##lanes##_any, step##lanes##_any, step##lanes##_any, step##lanes##_3,      \
		step##lanes##_4, step##lanes##_5, step##lanes##_6, step##lanes##_7,            \
		step##lanes##_8, step##lanes##_9, step##lanes##_10, step##lanes##_11,          \
		step##lanes##_12,                                                              \
	};

STEPS(2, )
#if HAVE_AVX
STEPS(4, AVX)
#endif

#undef AT
#undef K
#undef PASS
#undef EVAL

/* lanes: 4 (AVX where the processor has it) or 2; 0: the widest there is */
static void *
alloc_lanes(size_t dim, int lanes)
{
	struct rk8pd *st = calloc(1, sizeof *st);
	size_t pad, bytes;

	if (st == NULL || dim == 0)
		goto fail;
#if HAVE_AVX
	if (lanes == 0)
		lanes = __builtin_cpu_supports("avx") ? 4 : 2;
#else
	lanes = 2;
#endif
	pad = (dim + (size_t)lanes - 1) / (size_t)lanes * (size_t)lanes;
	st->dim = dim;
	st->pad = pad;
	/* the 17 vectors, aligned to 32 bytes (aligned_alloc takes a size of whole 32s) */
	bytes = (17 * pad * sizeof(double) + 31) / 32 * 32;
	st->mem = st->y0 = aligned_alloc(32, bytes);
	if (st->y0 == NULL)
		goto fail;
	memset(st->y0, 0, bytes);
	st->k = st->y0 + pad;
	st->ytmp = st->k + 13 * pad;
	st->yend = st->ytmp + pad;
	st->err = st->yend + pad;
#if HAVE_AVX
	if (lanes == 4)
		st->step = dim < sizeof steps4 / sizeof steps4[0] ? steps4[dim] : step4_any;
	else
#endif
		st->step = dim < sizeof steps2 / sizeof steps2[0] ? steps2[dim] : step2_any;
	return st;
fail:
	free(st);
	return NULL;
}

static void *
rk8pd_alloc(size_t dim)
{
	return alloc_lanes(dim, 0);
}

static void *
rk8pd2_alloc(size_t dim)
{
	return alloc_lanes(dim, 2);
}

static int
rk8pd_apply(void *state, size_t dim, double t, double h, double y[], double yerr[],
            const double dydt_in[], double dydt_out[], const gsl_odeiv2_system *sys)
{
	struct rk8pd *st = state;

	(void)dim;
	return st->step(st, t, h, y, yerr, dydt_in, dydt_out, sys);
}

/* can use dydt_in, gives exact dydt_out: as GSL's rk8pd; nothing is kept from one step to the next */
STEP_TYPE(rk8pd_type, "rk8pd", 1, 1, rk8pd_alloc, rk8pd_apply, step_reset_none, step_order8);
STEP_TYPE(rk8pd2_type, "rk8pd", 1, 1, rk8pd2_alloc, rk8pd_apply, step_reset_none, step_order8);

const gsl_odeiv2_step_type *const hb_step_rk8pd = &rk8pd_type;
const gsl_odeiv2_step_type *const hb_step_rk8pd_2lanes = &rk8pd2_type;

const double *
hb_rk8pd_end(const gsl_odeiv2_step *st)
{
	if (st->type != hb_step_rk8pd && st->type != hb_step_rk8pd_2lanes)
		return NULL;
	return ((const struct rk8pd *)st->state)->yend;
}
