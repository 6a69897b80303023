/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_stiff.c - the stiffness check: h |lambda| over the decaying eigenvalues of the
 * contact flow's Jacobian against the stepper's stability radius (see sim.c for the method).
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
 * Stiffness of the contact flow after an accepted step of an explicit
 * stepper: h |lambda| over the decaying eigenvalues (Re lambda <= 0) of the
 * Jacobian of the dynamic components (the quadratures W, J_Fc, J_Fe, E_e
 * add only zero eigenvalues).  An explicit method's step is accurate long
 * before it is unstable, so h |lambda| beyond half the stepper's stability
 * radius means the stepper is held back by stability: a stiff flow, real
 * or oscillatory, where an implicit stepper takes far fewer steps.
 * Checked every 32nd step; eight hits in a row make the contact stiff, and
 * with run.stepper = auto the contacts go over to bsimp from then on.
 */
int
hbs_stiffness(struct hb_sim *s)
{
	struct phase *p = s->cur;
	const struct layout *L = &p->L;
	double J[MAXDIM * MAXDIM], dfdt[MAXDIM], rho = 0.0, hr;
	int idx[MAXDIM], nd = 0, i, k;

	if (!p->q || !hbs_explicit_stepper(s->stepper[1]) || (s->st.steps & 31) != 0)
		return 0;
	if (L->ix >= 0) idx[nd++] = L->ix;
	idx[nd++] = L->iv;
	idx[nd++] = L->ixc;
	for (i = 0; i < s->I->law->n_z; i++)
		idx[nd++] = L->iz + i;
	if (L->ixm >= 0) {
		idx[nd++] = L->ixm;
		idx[nd++] = L->ivm;
	}
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
	hbs_jacobian(s->t, s->u, J, dfdt, p);
	for (i = 0; i < nd; i++)
		for (k = 0; k < nd; k++) {
			double a = J[idx[i] * L->dim + idx[k]];

			/* GSL's QR iteration does not converge on a matrix that is
			 * not finite, and says so through its process-wide error
			 * handler: no check on this step */
			if (!isfinite(a))
				return 0;
			gsl_matrix_set(s->Jdyn, (size_t)i, (size_t)k, a);
		}
	if (gsl_eigen_nonsymm(s->Jdyn, s->lambda, s->eig) != GSL_SUCCESS)
		return 0;
	/*
	 * The modes that decay (Re lambda <= 0) limit an explicit step by
	 * their modulus, not by their real part alone: an oscillatory mode
	 * -83 +- 1674i (study 1's sinking) holds the step at h |lambda| near the
	 * stability boundary although h max(-Re lambda) is 0.24.
	 */
	for (i = 0; i < nd; i++) {
		gsl_complex l = gsl_vector_complex_get(s->lambda, (size_t)i);

		if (GSL_REAL(l) <= 0.0)
			rho = fmax(rho, gsl_complex_abs(l));
	}
	hr = s->H * rho;
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
	if (s->sc.run.stepper == HB_STEPPER_AUTO) {
		s->stepper[1] = HB_STEPPER_BSIMP;
		s->st.switched = 1;
		if (hbs_phase_alloc(s, &s->ph[1], 1))
			return hbs_fail(s, HB_ENOMEM, "out of memory for the integrator");
		s->cur = &s->ph[1];
		gsl_odeiv2_driver_reset(s->cur->d);
	}
	return 0;
}
