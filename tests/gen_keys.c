/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * gen_keys.c - prints the explorer's key lists, one per mode, from the
 * modes' key tables (the registry tui_modes, src/tui/modes.c): "man" the
 * mdoc lists of man/hybounce.1's EXPLORER KEYS, "md" the Markdown tables
 * of the README's Explorer section.  `make keys-doc` splices both into
 * their files between the KEYS-BEGIN and KEYS-END markers;
 * tests/test_tui_keys.c checks that they agree.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "keys.h"

int
main(int argc, char **argv)
{
	size_t n;
	char *buf;
	int md = argc > 1 && strcmp(argv[1], "md") == 0;

	if (argc != 2 || (!md && strcmp(argv[1], "man") != 0)) {
		fputs("usage: gen-keys man|md\n", stderr);
		return 2;
	}
	n = (md ? keys_markdown(tui_modes, NULL, 0) : keys_man(tui_modes, NULL, 0)) + 1;
	buf = malloc(n);
	if (buf == NULL)
		return 1;
	if (md)
		keys_markdown(tui_modes, buf, n);
	else
		keys_man(tui_modes, buf, n);
	fputs(buf, stdout);
	free(buf);
	return ferror(stdout) || fflush(stdout) != 0;
}
