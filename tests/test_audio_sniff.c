/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * test_audio_sniff.c - hb_audio_format: a recording's format from its first
 * bytes, whatever its name; text and short or empty heads are none.
 */
#include <criterion/criterion.h>
#include <string.h>

#include "hybounce/onset.h"

static const char *
fmt(const char *head, size_t n)
{
	return hb_audio_format(head, n);
}

Test(audio_sniff, formats_by_their_first_bytes)
{
	char ogg[48] = "OggS";

	cr_assert_str_eq(fmt("RIFF\x24\x08\0\0WAVEfmt ", 16), "WAV");
	cr_assert_str_eq(fmt("RF64\xff\xff\xff\xffWAVEds64", 16), "WAV");
	cr_assert_str_eq(fmt("fLaC\0\0\0\x22", 8), "FLAC");
	memcpy(ogg + 28, "\x01vorbis", 7);
	cr_assert_str_eq(fmt(ogg, sizeof ogg), "Ogg Vorbis");
	memcpy(ogg + 28, "OpusHead", 8);
	cr_assert_str_eq(fmt(ogg, sizeof ogg), "Ogg Opus");
	cr_assert_str_eq(fmt("\0\0\0\x20" "ftypM4A \0\0\0\0", 16), "MP4/M4A");
	cr_assert_str_eq(fmt("FORM\0\0\0\0AIFFCOMM", 16), "AIFF");
	cr_assert_str_eq(fmt("ID3\x04\0\0\0\0\0\0", 10), "MP3 (ID3)");
	cr_assert_str_eq(fmt("\xff\xfb\x50\xc4", 4), "MP3");
	cr_assert_str_eq(fmt("\xff\xf1\x50\x80", 4), "AAC (ADTS)");
}

Test(audio_sniff, text_and_short_heads_are_none)
{
	cr_assert_null(fmt("t_e\n0.1\n0.2\n", 12));
	cr_assert_null(fmt("\xef\xbb\xbft_e\n", 7));
	cr_assert_null(fmt("RIFF\0\0\0\0AVI LIST", 16));
	cr_assert_null(fmt("RIFF", 4));
	cr_assert_null(fmt("", 0));
	cr_assert_null(hb_audio_format(NULL, 16));
	cr_assert_null(fmt("\xff\xe0", 2)); /* a sync word, layer 0, no ADTS */
}
