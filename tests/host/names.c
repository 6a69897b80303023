/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * names.c - a host program's own functions and objects named as 30 of
 * libhybounce's internal ones (tests/cli/host.sh), with bodies that have
 * nothing to do with them: if the library's calls reached any of them, the
 * run would stop here with the name.  The library must keep calling its
 * own (hidden and, in libhybounce.a, local: Makefile).
 */
#include "host_name.h"

HOST_NAME(arc_new)
HOST_NAME(arc_free)
HOST_NAME(arc_push)
HOST_NAME(arc_push_jump)
HOST_NAME(arc_set_max)
HOST_NAME(arc_truncate)
HOST_NAME(csv_put_field)
HOST_NAME(csv_put_num)
HOST_NAME(textbuf_printf)
HOST_NAME(hbs_fail)
HOST_NAME(hbs_finish_T)
HOST_NAME(hbs_flight_closed)
HOST_NAME(hbs_jacobian)
HOST_NAME(hbs_jump)
HOST_NAME(hbs_pack)
HOST_NAME(hbs_phase_alloc)
HOST_NAME(hbs_phase_free)
HOST_NAME(hbs_push_sample)
HOST_NAME(hbs_scales)
HOST_NAME(hbs_unpack)
HOST_NAME(hbs_watch)
HOST_NAME(hbs_after_step)
HOST_NAME(preset_ini_begin)
HOST_NAME(preset_ini_end)
HOST_NAME(scene_key_resolve)
HOST_NAME(scene_keydef_find)
HOST_NAME(scene_error_set)
HOST_NAME(law_kinks_xc)

/* two objects, of other types than the library's tables */
const char scene_keydefs[] = "the host's scene_keydefs";
long scene_nkeydefs = -1;
