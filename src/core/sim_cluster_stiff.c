/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_cluster_stiff.c - a chain's clusters of contacts: the Jacobian of
 * their ODE (for bsimp), and the stiffness check of an explicit stepper
 * (docs/chains.md section 8, point 6; the check per interface is
 * sim_stiff.c's, as for the pair; sim_cluster.c for the clusters' flow).
 */
#include "sim_impl.h"
#include "sim_cluster_law.h"
#include "sim_iface.h"

/* The clusters' Jacobian, scaled: an entry scaled and added (hbs_iface_jac_block's put). */
struct cjset {
	double *dfdu;
	int n;
	const double *sc, *is;
};

static void
cjset(void *ctx, int row, int col, double val)
{
	struct cjset *j = ctx;

	j->dfdu[row * j->n + col] += val * j->sc[col] * j->is[row];
}

/*
 * The Jacobian of hbs_cluster_rhs in scaled variables: per interface in
 * contact the law's partials of Phi (columns x_c, z..., v) in its own
 * rows and in the v rows of its neighbours in contact, and of Psi in its z
 * rows.  Dense, dim x dim (the clusters' blocks are tridiagonal in k).
 */
int
hbs_cluster_jacobian(double t, const double u[], double *dfdu, double dfdt[], void *params)
{
	struct hb_sim *s = params;
	const struct clusters *c = &s->cx;
	const double *sc = s->scale, *is = s->iscale;
	const int n = c->dim;
	int p, i, k;

	(void)t;
	s->st.jac++;
	memset(dfdu, 0, (size_t)n * (size_t)n * sizeof *dfdu);
	memset(dfdt, 0, (size_t)n * sizeof *dfdt);
	for (p = 0; p < c->nact; p++)
		hbs_cluster_law(&s->ifc[c->act[p]], u, sc, 1);
#define SET(r, col, val) (dfdu[(r) * n + (col)] += (val) * sc[col] * is[r])
	for (p = 0; p < c->nact; p++) {
		int kk = c->act[p];
		const struct iface *I = &s->ifc[kk];
		int o = I->off, nz = I->law->n_z;
		struct jrows r = { o, o + 1, o + 2, o + 2 + nz, o + 3 + nz };
		struct cjset js = { dfdu, n, sc, is };

		hbs_iface_jac_block(I, &r, u[o + 1] * sc[o + 1], I->tphi, I->tdphi, I->tdpsi, I->ilo + I->ihi, 1.0,
		                    cjset, &js);
		/* the neighbours' forces in this interface's v row */
		for (int d = -1; d <= 1; d += 2) {
			const struct iface *J;
			int oj, nzj, cj[HB_LAW_MAX_Z + 2];
			double w;

			if (kk + d < 0 || kk + d >= s->nif || s->ifc[kk + d].off < 0)
				continue;
			J = &s->ifc[kk + d];
			w = d < 0 ? I->ilo : I->ihi;
			oj = J->off;
			nzj = J->law->n_z;
			cj[0] = oj;
			for (i = 0; i < nzj; i++)
				cj[1 + i] = oj + 2 + i;
			cj[nzj + 1] = oj + 1;
			for (k = 0; k < nzj + 2; k++)
				SET(o + 1, cj[k], J->tdphi[k] * w);
		}
	}
#undef SET
	return GSL_SUCCESS;
}

/*
 * The stiffness of the clusters after an accepted step (sim_stiff.c, per
 * interface in contact): each interface's own flow (x_c, v, z under its
 * effective mass, its neighbours' forces held), the fastest interface
 * setting h |lambda|.  With run.stepper = auto the clusters go over to
 * bsimp; the next interval's ODE is built for it from this state.  Linear
 * in the interfaces in contact (a 2 + n_z eigenproblem each).
 */
int
hbs_cluster_stiffness(struct hb_sim *s)
{
	struct clusters *c = &s->cx;
	double rho = 0.0;
	int p, rc;

	if (c->nact == 0 || !hbs_stiff_begin(s))
		return 0;
	for (p = 0; p < c->nact; p++) {
		const struct iface *I = &s->ifc[c->act[p]];

		if ((rc = hbs_iface_rho(s, I, I->ilo + I->ihi, &s->scale[I->off], &rho)) != 0)
			return rc < 0 ? 0 : rc;
	}
	if (hbs_stiff_verdict(s, s->H * rho))
		s->setup = 1;
	return 0;
}
