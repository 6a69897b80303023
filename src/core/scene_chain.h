/*
 * A chain scene's bodies and interfaces, one at a time (docs/chains.md
 * section 7): what the engine binds a chain from.  The scene stores a
 * uniform chain compactly ([chain], [body1], [law], [striker]); these
 * functions resolve, for one body or one interface, the value that applies
 * to it (an override where the scene has one, the chain's otherwise), so
 * that the engine never reads the scene's layout of a chain itself.
 */
#ifndef HB_SCENE_CHAIN_H
#define HB_SCENE_CHAIN_H

#include "hybounce/scene.h"
#include "hybounce/status.h"

struct scene_chain_body {
	double m;   /* mass, kg */
	double R;   /* half-length along the axis (radius), m; 0 when unknown */
	double F;   /* applied force, constant (gravity m g included, signed along the axis), N */
	double v0;  /* initial velocity, m/s */
	double gap; /* initial gap below the body (to the body below, or the floor), m */
};

struct scene_chain_iface {
	const struct hb_law_type *law;
	double par[HB_LAW_MAX_PARAMS]; /* the law's parameters, in its table order, as they
	                                * apply to this interface (derived for its pair of bodies) */
	int ext;           /* rule R1: 1 adhesive continuation, 0 clamped */
};

/* Everything a body of a chain is given as (its overrides applied). */
struct scene_chain_bodyx {
	double E, nu;     /* Pa, 1: its material, when has_material */
	double rho;       /* kg/m^3; 0 when not given */
	double R;         /* m */
	double mass;      /* kg: given, or 4/3 pi R^3 rho; NAN when neither */
	double F;         /* the applied constant force other than gravity, N */
	double v0, gap;   /* initial velocity, m/s; gap below the body, m */
	int has_material; /* E and nu known */
	int mass_given;   /* the mass typed rather than derived */
	int half;         /* 1: E or nu overridden without the other and no material to complete it */
	int both;         /* 1: rho and mass both overridden */
};

/*
 * Body i (0-based) as the scene gives it: body1's values, then the
 * overrides body.I.* and initial.body.I.* (I = i + 1).  HB_EINVAL for a bad i.
 */
int scene_chain_body_full(const struct hb_scene *sc, int i, struct scene_chain_bodyx *out);

/*
 * Interface k's law, parameters and extension as the scene gives them, and
 * *derivable set to 1 when its stiffness follows from its pair's materials
 * (then par holds the derived value).  *floorless set to 1 when interface 0
 * has a floor (body2) with no material while the scene's k is derived: its
 * stiffness is then neither derived nor typed.
 */
int scene_chain_iface_full(const struct hb_scene *sc, int k, struct scene_chain_iface *out,
                           int *derivable, int *floorless);

/* Body i (0 = body 1, the lowest; n - 1 the striker) of a chain scene. */
int scene_chain_body(const struct hb_scene *sc, int i, struct scene_chain_body *out);

/* Interface k (0 = the floor's, below body 1; k joins bodies k and k + 1). */
int scene_chain_iface(const struct hb_scene *sc, int k, struct scene_chain_iface *out);

#endif
