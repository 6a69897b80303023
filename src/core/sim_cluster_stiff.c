/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_cluster_stiff.c - a chain's clusters of contacts: the Jacobian of
 * their ODE (for bsimp), and the stiffness check of an explicit stepper,
 * per interface in contact (docs/chains.md section 8, point 6; see
 * sim_stiff.c for the pair's and sim_cluster.c for the clusters' flow).
 */
#include "sim_impl.h"

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
	const double *sc = c->scale, *is = c->iscale;
	const int n = c->dim;
	int p, i, k;

	(void)t;
	s->st.jac++;
	memset(dfdu, 0, (size_t)n * (size_t)n * sizeof *dfdu);
	memset(dfdt, 0, (size_t)n * sizeof *dfdt);
	for (p = 0; p < c->nact; p++) {
		struct iface *I = &s->ifc[c->act[p]];
		int o = I->off, nz = I->law->n_z;
		double z[HB_LAW_MAX_Z];

		for (i = 0; i < nz; i++)
			z[i] = u[o + 2 + i] * sc[o + 2 + i];
		I->law->jac(I->par, I->ext, u[o] * sc[o], nz ? z : NULL, u[o + 1] * sc[o + 1], I->tdphi,
		            nz ? I->tdpsi : NULL);
		I->tphi = I->law->phi(I->par, I->ext, u[o] * sc[o], nz ? z : NULL, u[o + 1] * sc[o + 1]);
	}
#define SET(r, col, val) (dfdu[(r) * n + (col)] += (val) * sc[col] * is[r])
	for (p = 0; p < c->nact; p++) {
		int kk = c->act[p];
		const struct iface *I = &s->ifc[kk];
		int o = I->off, nz = I->law->n_z, col[HB_LAW_MAX_Z + 2];
		double v = u[o + 1] * sc[o + 1];

		col[0] = o;
		for (i = 0; i < nz; i++)
			col[1 + i] = o + 2 + i;
		col[nz + 1] = o + 1;
		SET(o, o + 1, 1.0);
		for (k = 0; k < nz + 2; k++) {
			SET(o + 1, col[k], -I->tdphi[k] * (I->ilo + I->ihi));
			for (i = 0; i < nz; i++)
				SET(o + 2 + i, col[k], I->tdpsi[i * (nz + 2) + k]);
			SET(o + 2 + nz, col[k], I->tdphi[k] * v);
			SET(o + 3 + nz, col[k], -I->tdphi[k]);
		}
		SET(o + 2 + nz, o + 1, I->tphi);
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

/* The stability radius of an explicit stepper along the negative real axis (sim_stiff.c). */
static double
radius(int stepper)
{
	return stepper == HB_STEPPER_DOP853 ? 6.1 : stepper == HB_STEPPER_RK8PD ? 5.3 : 3.0;
}

/*
 * The stiffness of the clusters after an accepted step of an explicit
 * stepper, every 32nd step: h |lambda| over the decaying eigenvalues of
 * each interface's own flow (x_c, v, z under its effective mass, its
 * neighbours' forces held), the fastest interface setting it, against
 * half the stepper's stability radius, as sim_stiff.c does for the pair.
 * Eight hits in a row make the run stiff; with run.stepper = auto the
 * clusters go over to bsimp from then on.  Linear in the interfaces in
 * contact (a 2 + n_z eigenproblem each).
 */
int
hbs_cluster_stiffness(struct hb_sim *s)
{
	struct clusters *c = &s->cx;
	double rho = 0.0, hr;
	int p, i, k;

	if (!hbs_explicit_stepper(s->stepper[1]) || (s->st.steps & 31) != 0 || c->nact == 0)
		return 0;
	for (p = 0; p < c->nact; p++) {
		struct iface *I = &s->ifc[c->act[p]];
		int nz = I->law->n_z, nd = 2 + nz;
		double dphi[HB_LAW_MAX_Z + 2], dpsi[HB_LAW_MAX_Z * (HB_LAW_MAX_Z + 2)];

		if (s->Jdyn == NULL || s->Jdyn->size1 != (size_t)nd) {
			if (s->eig) gsl_eigen_nonsymm_free(s->eig);
			if (s->Jdyn) gsl_matrix_free(s->Jdyn);
			if (s->lambda) gsl_vector_complex_free(s->lambda);
			s->eig = gsl_eigen_nonsymm_alloc((size_t)nd);
			s->Jdyn = gsl_matrix_alloc((size_t)nd, (size_t)nd);
			s->lambda = gsl_vector_complex_alloc((size_t)nd);
			if (s->eig == NULL || s->Jdyn == NULL || s->lambda == NULL)
				return hbs_fail(s, HB_ENOMEM, "out of memory");
		}
		/* rows and columns: x_c, v, z...; the law's columns are x_c, z..., v */
		I->law->jac(I->par, I->ext, I->xc, nz ? I->z : NULL, I->v, dphi, nz ? dpsi : NULL);
		gsl_matrix_set_zero(s->Jdyn);
		gsl_matrix_set(s->Jdyn, 0, 1, 1.0);
		for (k = 0; k < nd; k++) {
			int lc = k == 0 ? 0 : k == 1 ? nz + 1 : k - 1; /* law column of matrix column k */

			if (!isfinite(dphi[lc]))
				return 0;
			gsl_matrix_set(s->Jdyn, 1, (size_t)k, -dphi[lc] * (I->ilo + I->ihi));
			for (i = 0; i < nz; i++) {
				double a = dpsi[i * (nz + 2) + lc];

				if (!isfinite(a))
					return 0;
				gsl_matrix_set(s->Jdyn, (size_t)(2 + i), (size_t)k, a);
			}
		}
		if (gsl_eigen_nonsymm(s->Jdyn, s->lambda, s->eig) != GSL_SUCCESS)
			return 0;
		for (i = 0; i < nd; i++) {
			gsl_complex l = gsl_vector_complex_get(s->lambda, (size_t)i);

			if (GSL_REAL(l) <= 0.0)
				rho = fmax(rho, gsl_complex_abs(l));
		}
	}
	hr = c->H * rho;
	s->st.stiff_checks++;
	s->st.stiff_hrho = fmax(s->st.stiff_hrho, hr);
	if (!(hr > 0.5 * radius(s->stepper[1]))) {
		s->stiff_row = 0;
		return 0;
	}
	s->st.stiff_hits++;
	if (++s->stiff_row < 8 || s->st.stiff)
		return 0;
	s->st.stiff = 1;
	s->st.stiff_t = s->t;
	if (s->sc.run.stepper == HB_STEPPER_AUTO) {
		s->stepper[1] = HB_STEPPER_BSIMP;
		s->st.switched = 1;
		s->setup = 1; /* the next interval's ODE is built for bsimp from this state */
	}
	return 0;
}
