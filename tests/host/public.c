/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * public.c - a host program's own functions named as public functions of
 * libhybounce that the library calls itself (tests/cli/host.sh): the host
 * may define them (its own calls then reach its own), but the library's
 * calls must stay inside the library (libhybounce.so is linked with
 * -Bsymbolic-functions: Makefile).  The host program calls none of them.
 */
#include "host_name.h"

HOST_NAME(hb_atomic_add)
HOST_NAME(hb_atomic_begin)
HOST_NAME(hb_atomic_commit)
HOST_NAME(hb_status_set)
HOST_NAME(hb_scene_validate)
HOST_NAME(hb_preset_format)
