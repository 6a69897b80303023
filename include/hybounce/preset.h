/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * preset.h - scenes in INI files (read with inih).
 *
 *     [scene]    name, description, law, extension (adhesive | none)
 *     [body1]    name, E, nu, rho, R   or   mass
 *     [body2]    likewise; R = inf and no rho (or mass = inf): a fixed obstacle
 *     [law]      the law's parameters (k only when it is not derived)
 *     [loads]    g, F1, F2, ramp (yes/no), F_e0, T_e, T_s
 *     [initial]  x0, v0, x_m0, v_m0
 *     [run]      T, J, stepper, rtol, atol, h_max, max_samples, chatter, reductions
 *
 * Values may carry units with SI prefixes ("20 mm", "200 GPa").  Errors
 * come back as "FILE:LINE: [section] key: message; accepted: ...".
 */
#ifndef HB_PRESET_H
#define HB_PRESET_H
#include "export.h"
HB_BEGIN_DECLS

#include <stddef.h>
#include "scene.h"

/*
 * Loads a preset into *sc (starting from hb_scene_defaults), validates it and
 * derives.  On error *sc is unspecified, HB_EINVAL or HB_EIO is returned
 * and msg holds "FILE:LINE: ...".
 */
int
hb_preset_load(const char *path, struct hb_scene *sc, char *msg, size_t n);

/* The same from a string; `name` stands for the file name in messages. */
int
hb_preset_load_string(const char *text, const char *name, struct hb_scene *sc,
                   char *msg, size_t n);

/*
 * Opens a preset for a run, as both front ends do: loads the file at path,
 * applies each "KEY=VALUE" of sets in order (blanks around the key and the
 * value are ignored: " run.T = 1 ms" is run.T = 1 ms), then validates the
 * scene.  Returns 0, or HB_EINVAL / HB_EIO with msg holding
 * "FILE:LINE: ...", "--set ARG: KEY: ...; accepted: ..." or
 * "PATH: KEY: ...; accepted: ...".
 */
int
hb_preset_open(const char *path, const char *const *sets, int nsets, struct hb_scene *sc,
            char *msg, size_t n);

/*
 * The one way every front end (--batch, the explorer, sweep, fit) opens a
 * scene: finds the preset NAME (hb_preset_resolve; its path goes into path,
 * pn bytes), then hb_preset_open with the --set texts.  Returns 0, or
 * HB_EINVAL / HB_EIO with msg holding "preset 'NAME': ..." when it is not
 * found, else hb_preset_open's message.
 */
int
hb_preset_open_named(const char *name, const char *const *sets, int nsets, struct hb_scene *sc,
                     char *path, size_t pn, char *msg, size_t n);

/*
 * hb_preset_open_named that also hands back the preset's text as read (the
 * file is read once: a pipe or a FIFO works), for a front end that reads
 * more than the scene from it (sweep's "; sweep: --vary" lines).  On 0,
 * *text is the caller's to free(); on an error it is left alone.
 */
int
hb_preset_open_text(const char *name, const char *const *sets, int nsets, struct hb_scene *sc,
                    char *path, size_t pn, char **text, char *msg, size_t n);

/*
 * Writes the scene as a preset that reproduces it exactly (%.17g values),
 * to a temporary name in the same folder and renamed.  Returns 0, or HB_EIO
 * with "PATH: strerror" in msg; an existing file is left intact on failure.
 */
int
hb_preset_save(const char *path, const struct hb_scene *sc, char *msg, size_t n);

/* The same into a caller buffer; returns the length needed (like snprintf). */
size_t
hb_preset_format(const struct hb_scene *sc, char *buf, size_t n);

/*
 * A run as a preset that reproduces it (into buf, like hb_preset_format):
 * its scene; for a run with branches (sim.h: hb_sim_branch) the scene it
 * began with and a [branch N] section per branch: where it continues from
 * (t, j), the state there as a check, and the keys that changed.  Where
 * the file cannot reproduce the run (hb_sim_unrecorded, or a branch that
 * does not read back to its values), its first line says so.
 */
struct hb_sim;
size_t
hb_preset_format_run(const struct hb_sim *s, char *buf, size_t n);

/*
 * hb_preset_open_named for a preset that may hold [branch N] sections (the
 * other openers refuse them): *br (malloc'd, NULL when none; free it) gets
 * the branches, each scene being the one before it (with the --set texts)
 * and the branch's keys.  A host replays them with hb_sim_new and
 * hb_sim_branch_at, as hybounce --batch and the explorer do.
 */
struct hb_branch;
int
hb_preset_open_branched(const char *name, const char *const *sets, int nsets, struct hb_scene *sc,
                        struct hb_branch **br, size_t *nbr, char *path, size_t pn, char *msg,
                        size_t n);

/*
 * Finds a preset by name or path: an existing path is used as is;
 * otherwise NAME or NAME.preset in the preset folders (see
 * hb_preset_dirs()).  Writes the path into out.  Returns 0 or HB_EINVAL with a
 * message listing where it looked.
 */
int
hb_preset_resolve(const char *name, char *out, size_t n, char *msg, size_t mn);

/*
 * The folders searched for presets, in order: $HYBOUNCE_PRESETS (colon
 * separated), ./presets, the install folder (PREFIX/share/hybounce/presets),
 * then beside the running program: BIN/../presets (the source tree's
 * build/hybounce) and BIN/../share/hybounce/presets (an installation moved
 * elsewhere), those that exist.
 * NULL-terminated, in storage of the calling thread, valid until a later call
 * of that thread sees HYBOUNCE_PRESETS changed.
 */
const char *const *
hb_preset_dirs(void);

struct hb_preset_info {
	char path[512];
	char name[64];          /* file name without .preset */
	char title[96];         /* [scene] name */
	char description[256];
};

/*
 * Lists the presets in the folders (first occurrence of each name wins),
 * sorted by name.  *out is malloc'd (free it); returns the count, or -1 on
 * no memory.
 */
int
hb_preset_list(struct hb_preset_info **out);

HB_END_DECLS

#endif
