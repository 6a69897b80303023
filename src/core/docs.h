/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * docs.h - reference texts generated from the engine's tables, for the
 * man page and the README (private: tools/gendoc.c writes them between
 * the GENERATED-BEGIN / GENERATED-END markers).  Each returns the length
 * needed, like snprintf.
 */
#ifndef HYBOUNCE_DOCS_H
#define HYBOUNCE_DOCS_H

#include <stddef.h>

/* The keys of a preset, with each law's parameters (mdoc list items). */
size_t
scene_keys_mdoc(char *buf, size_t n);

/* The columns of --collisions: an mdoc list, and a Markdown table. */
size_t
collision_columns_mdoc(char *buf, size_t n);
size_t
collision_columns_markdown(char *buf, size_t n);

/* The run observables (observables.h): mdoc list items, and a Markdown table. */
size_t
run_observables_mdoc(char *buf, size_t n);
size_t
run_observables_markdown(char *buf, size_t n);

#endif
