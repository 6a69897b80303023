/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_limits.c - the model's limits in a chain (docs/chains.md section 6),
 * checked at every accepted step of the clusters and, where one is passed,
 * located in the step: each interface in contact within run.max_indent of
 * the smaller radius of its bodies (its indentation |x_c| or its overlap
 * -x, the larger), and no two bodies that are not neighbours overlapping
 * (possible only across two interfaces in contact one above the other).
 * The instant a limit is passed is found as the clusters' events are, on
 * re-steps from the step's start (hbs_locate_fn), to a few ulps of t.
 */
#include "sim_impl.h"
#include "cnum.h"

/* Which limit: interface k's indentation (bit 1), or the bodies across k and k + 1 (bit 2). */
struct limit {
	int k, bit;
	double R;               /* the radius the indentation is measured against (bit 1) */
	double h;               /* where in the step it is passed */
};

/* Interface k's indentation at a scaled state of the clusters: |x_c| or its overlap -x, the larger. */
static double
depth(const struct hb_sim *s, int k, const double *u)
{
	const struct iface *I = &s->ifc[k];
	double xc = u[I->off] * s->scale[I->off];

	return fmax(fabs(xc), -(I->xe + xc));
}

/* The gap across interfaces k and k + 1 (both in contact): between bodies lo of k and hi of k + 1. */
static double
gap_across(const struct hb_sim *s, int k, const double *u)
{
	const struct iface *I = &s->ifc[k], *J = &s->ifc[k + 1];
	const double *sc = s->scale;

	return (I->xe + u[I->off] * sc[I->off]) + (J->xe + u[J->off] * sc[J->off]) + 2.0 * s->body[I->hi].l;
}

/* The limit's margin at a scaled state (>= 0 within it, < 0 passed): the root finder's function. */
static double
margin(struct hb_sim *s, double t, const double *u, const void *arg)
{
	const struct limit *L = arg;

	(void)t;
	return L->bit == 1 ? s->sc.run.max_indent * L->R - depth(s, L->k, u) : gap_across(s, L->k, u);
}

/*
 * Where in the step (t0, u0) -> (t, u) the limit is passed: the step's
 * start if it was already passed there, else its crossing located on
 * re-steps (the step's end where the re-steps do not see it, at the level
 * of round-off).  0, or hbs_fail's status.
 */
static int
locate_limit(struct hb_sim *s, struct limit *L)
{
	double hend = s->t - s->t0, fa = margin(s, s->t0, s->u0, L), hb;
	int it, rc;

	L->h = 0.0;
	if (!(fa >= 0.0) || !(hend > 0.0))
		return 0;
	if ((rc = hbs_locate_fn(s, margin, L, hend, fa, &hb, &it)))
		return rc;
	L->h = isfinite(hb) ? hb : hend;
	return 0;
}

/*
 * The limit L passed (why in words, at its located instant): under
 * run.chain_limits = stop the run ends there (HB_EINVAL; the state is
 * that of the located instant, what was computed before it kept); under
 * warn the first is noted and each is counted, and the run goes on from
 * the step's end.
 */
static int
limit_passed(struct hb_sim *s, const struct limit *L)
{
	struct iface *I = &s->ifc[L->k];
	int top = L->bit == 2 ? s->ifc[L->k + 1].hi : I->hi; /* the upper body named */
	double tl = s->t0 + L->h, t1 = s->t, *ul = s->ut;
	char why[400], who[64];

	I->over |= L->bit;
	if (hbs_restep_n(s, L->h, ul, s->cur->L.dim) != GSL_SUCCESS)
		return hbs_fail(s, HB_ENUMERIC, "a re-step to locate a limit failed");
	if (I->lo < 0)
		snprintf(who, sizeof who, "the floor and body %d", top + 1);
	else
		snprintf(who, sizeof who, "bodies %d and %d", I->lo + 1, top + 1);
	if (L->bit == 1) {
		double d = depth(s, L->k, ul); /* the indentation at the located instant */

		cnum_snprintf(why, sizeof why, "interface %d (%s) is indented by %.6g m at t = %.12g s, "
		              "%.3g of %s %.6g m, past run.max_indent = %g (located; %.6g m at the "
		              "step's end, t = %.12g s): the model assumes small indentations",
		              s->k0 + L->k, who, d, tl, d / L->R,
		              I->lo < 0 ? "the body's radius" : "the smaller radius", L->R,
		              s->sc.run.max_indent, depth(s, L->k, s->u), t1);
	} else {
		cnum_snprintf(why, sizeof why, "%s, not neighbours, begin to overlap at t = %.12g s "
		              "(located; by %.6g m at the step's end, t = %.12g s): the model lets only "
		              "neighbours touch", who, tl, -gap_across(s, L->k, s->u), t1);
	}
	if (s->sc.run.chain_limits != HB_CHAIN_LIMITS_WARN) {
		/* the run ends at the located instant */
		memcpy(s->u, ul, (size_t)s->cx.dim * sizeof *ul);
		hbs_cluster_unpack(s, tl, s->u);
		return hbs_fail_iface(s, I, HB_EINVAL, why);
	}
	if (s->nlim++ == 0)
		snprintf(s->limnote, sizeof s->limnote, "%s", why);
	return 0;
}

/*
 * The limits at the end of the step just accepted (the clusters' state
 * unpacked there): each one newly passed in this contact is located, and
 * they are taken earliest first (the lowest k, the indentation first, on
 * a tie).  Linear in the interfaces in contact.
 */
int
hbs_cluster_limits(struct hb_sim *s)
{
	const struct clusters *c = &s->cx;
	const double f = s->sc.run.max_indent;
	struct limit first;
	int p, rc, have;

	do {
		have = 0;
		for (p = 0; p < c->nact; p++) {
			int k = c->act[p];
			const struct iface *I = &s->ifc[k];
			double Rhi = s->body[I->hi].l, R = I->lo < 0 ? Rhi : fmin(Rhi, s->body[I->lo].l);
			struct limit cand[2];
			int nc = 0, i;

			if (!(I->over & 1) && R > 0 && depth(s, k, s->u) > f * R)
				cand[nc++] = (struct limit){ k, 1, R, 0.0 };
			if (!(I->over & 2) && p + 1 < c->nact && c->act[p + 1] == k + 1 && gap_across(s, k, s->u) < 0)
				cand[nc++] = (struct limit){ k, 2, R, 0.0 };
			for (i = 0; i < nc; i++) {
				if ((rc = locate_limit(s, &cand[i])))
					return rc;
				if (!have || cand[i].h < first.h) {
					first = cand[i];
					have = 1;
				}
			}
		}
		if (have && (rc = limit_passed(s, &first)))
			return rc;
	} while (have);
	return 0;
}

const char *
hb_sim_limits(const struct hb_sim *s, long *count)
{
	if (count != NULL)
		*count = s->nlim;
	return s->limnote;
}
