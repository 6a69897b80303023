/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_work.c - the arrays of a flow interval's ODE that the driver steps
 * and locates on (sim.c, sim_locate.c, sim_restep.c): the state, its
 * scales, the step's ends and re-steps, the watched functions' values and
 * kinds.  One block, sized for the pair's ODE (MAXDIM components, MAXFUN
 * functions) when a simulator is made, and grown for a chain's clusters
 * when an interval needs more (sim_cluster_step.c).
 */
#include "sim_impl.h"

enum { NU = 15, NF = 9, NI = 6 }; /* arrays of dim.u doubles, of dim.f doubles, of dim.f ints */

void
hbs_work_free(struct hb_sim *s)
{
	free(s->dim.buf);
	free(s->dim.ibuf);
	s->dim.buf = NULL;
	s->dim.ibuf = NULL;
	s->dim.u = s->dim.f = s->dim.ncache = 0;
}

/*
 * Room for an ODE of nu components and nf watched functions: 0, or
 * HB_ENOMEM (the arrays as they were).  Growing forgets their contents
 * (a new interval fills them) and the watched values kept.  The pair's
 * (nu = MAXDIM, nf = MAXFUN) are exactly that long, whatever a chain
 * before it grew them to, with its scales in the simulator (pscale,
 * piscale), where its right-hand side reads them (sim_rhs.c).
 */
int
hbs_work_reserve(struct hb_sim *s, int nu, int nf)
{
	const int pair = nu == MAXDIM && nf == MAXFUN;
	int u = s->dim.u > 0 && !pair ? s->dim.u : MAXDIM, f = s->dim.f > 0 && !pair ? s->dim.f : MAXFUN, nc;
	double *b, **du[] = { &s->u, &s->u0, &s->u1, &s->ut, &s->f0, &s->f1, &s->scale, &s->iscale,
	                      &s->w.u, &s->yerr, &s->ua, &s->ub, &s->uc };
	double **df[] = { &s->gmax, &s->w.f, &s->lf0, &s->lf1, &s->lfa, &s->lfb, &s->w.r, &s->lr0, &s->lr1 };
	int *ib, **di[] = { &s->w.kind, &s->lkind, &s->lka, &s->cand, &s->cand0 };
	size_t i, off = 0;

	_Static_assert(sizeof du / sizeof du[0] <= NU, "NU");
	_Static_assert(sizeof df / sizeof df[0] <= NF, "NF");
	_Static_assert(sizeof di / sizeof di[0] <= NI, "NI");
	if (s->dim.buf != NULL && (pair ? s->dim.u == MAXDIM && s->dim.f == MAXFUN
	                                : nu <= s->dim.u && nf <= s->dim.f))
		return 0;
	while (u < nu)
		u *= 2;
	while (f < nf)
		f *= 2;
	/* the pair's location re-steps a step's interval many times; a chain's state is long */
	nc = u <= MAXDIM ? CACHE : CCACHE;
	b = malloc(((size_t)u * (NU + (size_t)nc) + (size_t)f * NF + (size_t)nc) * sizeof *b);
	ib = malloc((size_t)f * NI * sizeof *ib);
	if (b == NULL || ib == NULL) {
		free(b);
		free(ib);
		return HB_ENOMEM;
	}
	hbs_work_free(s);
	s->dim.buf = b;
	s->dim.ibuf = ib;
	s->dim.u = u;
	s->dim.f = f;
	s->dim.ncache = nc;
	for (i = 0; i < sizeof du / sizeof du[0]; i++, off += (size_t)u)
		*du[i] = b + off;
	for (i = 0; i < sizeof df / sizeof df[0]; i++, off += (size_t)f)
		*df[i] = b + off;
	s->cache_h = b + off;
	s->cache_u = b + off + (size_t)nc;
	for (i = 0; i < sizeof di / sizeof di[0]; i++)
		*di[i] = ib + i * (size_t)f;
	if (u == MAXDIM) { /* the pair's scales, in the simulator (sim_rhs.c) */
		s->scale = s->pscale;
		s->iscale = s->piscale;
	}
	/* scales of 1 (the pair's unused components), no watched values kept */
	for (i = 0; i < (size_t)u; i++)
		s->scale[i] = s->iscale[i] = 1.0;
	memset(s->u, 0, (size_t)u * sizeof *s->u);
	s->w.valid = 0;
	s->ncache = s->cache_next = 0;
	return 0;
}
