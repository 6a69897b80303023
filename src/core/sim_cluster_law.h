/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * sim_cluster_law.h - one interface's law evaluated at the clusters'
 * scaled state, shared by their right-hand side (sim_cluster.c) and their
 * Jacobian (sim_cluster_stiff.c); inline, since the right-hand side is hot.
 * Private to the engine.
 */
#ifndef HYBOUNCE_SIM_CLUSTER_LAW_H
#define HYBOUNCE_SIM_CLUSTER_LAW_H

#include "sim_impl.h"

/*
 * The law of interface I (in contact) at the clusters' scaled state u
 * (scales sc): its block (x_c, v, z) unscaled, Phi into I->tphi and, with
 * jac, Phi's and psi's derivatives first (I->tdphi, I->tdpsi).
 */
static inline void
hbs_cluster_law(struct iface *I, const double *u, const double *sc, int jac)
{
	int o = I->off, nz = I->law->n_z, i;
	double z[HB_LAW_MAX_Z];

	for (i = 0; i < nz; i++)
		z[i] = u[o + 2 + i] * sc[o + 2 + i];
	if (jac)
		I->law->jac(I->par, I->ext, u[o] * sc[o], nz ? z : NULL, u[o + 1] * sc[o + 1], I->tdphi,
		            nz ? I->tdpsi : NULL);
	I->tphi = I->law->phi(I->par, I->ext, u[o] * sc[o], nz ? z : NULL, u[o + 1] * sc[o + 1]);
}

#endif
