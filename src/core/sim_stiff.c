/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_stiff.c - stiffness detection, per interface in contact, for both
 * systems the driver steps (the pair's, and a chain's clusters,
 * sim_cluster_stiff.c): h |lambda| over the decaying eigenvalues of each
 * interface's own contact flow against the stepper's stability radius,
 * and the verdict that makes a run stiff (see sim.c for the method).
 */
#include "sim_impl.h"

/*
 * The radius of an explicit stepper's region of absolute stability along
 * the negative real axis (h |lambda| at its boundary), roughly the same
 * along the rays a damped oscillation lies on: DOP853's 6.1 is Hairer's
 * (the threshold of dop853.f's own stiffness test); rk8pd's 13-stage
 * Prince-Dormand 8(7) about 5.3; rkf45 and rkck about 3.
 */
static double
stability_radius(int stepper)
{
	switch (stepper) {
	case HB_STEPPER_DOP853: return 6.1;
	case HB_STEPPER_RK8PD: return 5.3;
	case HB_STEPPER_VERN98: return 4.4; /* |R(z)| = 1 at 4.4-4.5 from 100 to 180 degrees */
	default: return 3.0;
	}
}

/* A check is a hit when h |lambda| is beyond this share of the stability radius. */
#define STIFF_FRACTION 0.5

/*
 * Whether this accepted step (in contact) checks the stiffness: every
 * 32nd step of an explicit stepper; a check counts as one evaluation of
 * the flow's Jacobian.
 */
int
hbs_stiff_begin(struct hb_sim *s)
{
	if (!hbs_explicit_stepper(s->stepper[1]) || (s->st.steps & 31) != 0)
		return 0;
	s->st.jac++;
	return 1;
}

/*
 * The largest modulus of the decaying eigenvalues (Re lambda <= 0) of
 * interface I's own contact flow at its current state: the Jacobian of
 * (x_c, v, z) with x_c' = v, v' = -Phi minv + (its neighbours' forces,
 * held), z' = Psi, minv the inverse of its effective mass (the quadratures
 * W, J_Fc, J_Fe, E_e and the centre of mass add only zero eigenvalues),
 * in the integrator's scaled variables (sc: the scales of x_c, v, z...,
 * powers of 2: the same eigenvalues, and QR converges in fewer sweeps on
 * the scaled matrix than on the raw one, whose entries span many decades).
 * The modes that decay limit an explicit step by their modulus, not by
 * their real part alone: an oscillatory mode -83 +- 1674i (study 1's
 * sinking) holds the step at h |lambda| near the stability boundary
 * although h max(-Re lambda) is 0.24.  Into *rho (the larger of it and
 * *rho); -1 where it cannot be computed (a partial not finite: GSL's QR
 * iteration does not converge on such a matrix, and says so through its
 * process-wide error handler): no check on this step; or hbs_fail's status.
 */
int
hbs_iface_rho(struct hb_sim *s, const struct iface *I, double minv, const double *sc, double *rho)
{
	int nz = I->law->n_z, nd = 2 + nz, i, k;
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
	/*
	 * rows and columns: v, x_c, z..., the order the pair's check had (on
	 * study 2's contacts GSL's QR takes about twice the instructions with
	 * x_c first); the law's columns are x_c, z..., v
	 */
	I->law->jac(I->par, I->ext, I->xc, nz ? I->z : NULL, I->v, dphi, nz ? dpsi : NULL);
	gsl_matrix_set_zero(s->Jdyn);
	gsl_matrix_set(s->Jdyn, 1, 0, sc[1] / sc[0]);
	for (k = 0; k < nd; k++) {
		int lc = k == 0 ? nz + 1 : k == 1 ? 0 : k - 1; /* law column of matrix column k */
		double sk = sc[k == 0 ? 1 : k == 1 ? 0 : k];   /* its scale */

		if (!isfinite(dphi[lc]))
			return -1;
		gsl_matrix_set(s->Jdyn, 0, (size_t)k, -dphi[lc] * minv * sk / sc[1]);
		for (i = 0; i < nz; i++) {
			double a = dpsi[i * (nz + 2) + lc];

			if (!isfinite(a))
				return -1;
			gsl_matrix_set(s->Jdyn, (size_t)(2 + i), (size_t)k, a * sk / sc[2 + i]);
		}
	}
	if (gsl_eigen_nonsymm(s->Jdyn, s->lambda, s->eig) != GSL_SUCCESS)
		return -1;
	for (i = 0; i < nd; i++) {
		gsl_complex l = gsl_vector_complex_get(s->lambda, (size_t)i);

		if (GSL_REAL(l) <= 0.0)
			*rho = fmax(*rho, gsl_complex_abs(l));
	}
	return 0;
}

/*
 * The verdict on a check, hr = h |lambda| of the step (the fastest
 * interface's): an explicit method's step is accurate long before it is
 * unstable, so hr beyond half the stepper's stability radius means the
 * stepper is held back by stability: a stiff flow, real or oscillatory,
 * where an implicit stepper takes far fewer steps.  Eight hits in a row
 * make the run stiff; with run.stepper = auto the contacts go over to
 * bsimp from then on: 1 when they do now (the caller rebuilds its
 * integrator), else 0.
 */
int
hbs_stiff_verdict(struct hb_sim *s, double hr)
{
	s->st.stiff_checks++;
	s->st.stiff_hrho = fmax(s->st.stiff_hrho, hr);
	if (!(hr > STIFF_FRACTION * stability_radius(s->stepper[1]))) {
		s->stiff_row = 0;
		return 0;
	}
	s->st.stiff_hits++;
	if (++s->stiff_row < 8 || s->st.stiff)
		return 0;
	s->st.stiff = 1;
	s->st.stiff_t = s->t;
	if (s->sc.run.stepper != HB_STEPPER_AUTO)
		return 0;
	s->stepper[1] = HB_STEPPER_BSIMP;
	s->st.switched = 1;
	return 1;
}

/* The pair's check after an accepted step in contact (its one interface, s->I). */
int
hbs_stiffness(struct hb_sim *s)
{
	double rho = 0.0;
	int rc;

	if (!s->cur->q || !hbs_stiff_begin(s))
		return 0;
	if ((rc = hbs_iface_rho(s, s->I, 1.0 / s->I->m, &s->scale[s->cur->L.ixc], &rho)) != 0)
		return rc < 0 ? 0 : rc;
	if (!hbs_stiff_verdict(s, s->H * rho))
		return 0;
	if (hbs_phase_alloc(s, &s->ph[1], 1))
		return hbs_fail(s, HB_ENOMEM, "out of memory for the integrator");
	s->cur = &s->ph[1];
	gsl_odeiv2_driver_reset(s->cur->d);
	return 0;
}
