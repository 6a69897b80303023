/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * fuzz.h - what the libFuzzer harnesses share: the input as a C string.
 *
 * Each harness is built with clang -fsanitize=fuzzer,address,undefined,
 * float-cast-overflow against the engine's sources (Makefile: make fuzz,
 * and the bounded smoke of make check, tests/cli/fuzz.sh).  A finding is a
 * crash, a sanitizer report, a leak, a timeout, or an abort() where a
 * harness states a property (fuzz_roundtrip: save -> load = scene).
 */
#ifndef HYBOUNCE_FUZZ_H
#define HYBOUNCE_FUZZ_H

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>

/* A malloc'd NUL-terminated copy of the input (NULs inside end it early). */
static inline char *
fuzz_string(const uint8_t *data, size_t size)
{
	char *s = malloc(size + 1);

	if (s == NULL)
		abort();
	memcpy(s, data, size);
	s[size] = '\0';
	return s;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

/*
 * The library leaves GSL's error handler as the process set it (GSL's
 * default aborts); a harness, like the hybounce program, has GSL's errors
 * returned as statuses, so that only the engine's own failures are findings.
 */
int LLVMFuzzerInitialize(int *argc, char ***argv);
int
LLVMFuzzerInitialize(int *argc, char ***argv)
{
	(void)argc;
	(void)argv;
	gsl_set_error_handler_off();
	return 0;
}

#endif
