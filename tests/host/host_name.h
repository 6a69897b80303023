/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * host_name.h - HOST_NAME(f): a host program's own function f(void) that
 * stops the program with its name when called (names.c, public.c: the
 * library's calls must not reach a host's function of the same name).
 */
#ifndef HYBOUNCE_HOST_NAME_H
#define HYBOUNCE_HOST_NAME_H

#include <stdio.h>
#include <stdlib.h>

static void
trap(const char *name)
{
	fprintf(stderr, "host: the library called the host's %s\n", name);
	abort();
}

#define HOST_NAME(f) \
	void f(void); \
	void f(void) { trap(#f); }

#endif
