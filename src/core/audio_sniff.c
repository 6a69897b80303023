/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * audio_sniff.c - which sound format a file holds, from its first bytes
 * (see hb_audio_format in onset.h): a recording is recognised by its
 * content, whatever its name, and read by aubio's source reader (FFmpeg's
 * libavformat in Debian's libaubio5), which opens every format below.
 */
#include <string.h>

#include "hybounce/onset.h"

static int
at(const unsigned char *b, size_t n, size_t off, const char *magic)
{
	size_t l = strlen(magic);

	return n >= off + l && memcmp(b + off, magic, l) == 0;
}

const char *
hb_audio_format(const void *head, size_t n)
{
	const unsigned char *b = head;

	if (b == NULL)
		return NULL;
	if ((at(b, n, 0, "RIFF") || at(b, n, 0, "RF64")) && at(b, n, 8, "WAVE"))
		return "WAV";
	if (at(b, n, 0, "riff") && n >= 16 && b[4] == 0x2e && b[5] == 0x91)
		return "Wave64";
	if (at(b, n, 0, "fLaC"))
		return "FLAC";
	if (at(b, n, 0, "OggS"))
		return at(b, n, 28, "\x01vorbis") ? "Ogg Vorbis" : at(b, n, 28, "OpusHead")
		       ? "Ogg Opus" : at(b, n, 28, "\x7f" "FLAC") ? "Ogg FLAC" : "Ogg";
	if (at(b, n, 4, "ftyp"))
		return "MP4/M4A";
	if (at(b, n, 0, "FORM") && (at(b, n, 8, "AIFF") || at(b, n, 8, "AIFC")))
		return "AIFF";
	if (at(b, n, 0, "caff"))
		return "CAF";
	if (at(b, n, 0, "ID3"))
		return "MP3 (ID3)";
	/* an MPEG audio frame (layer I-III: MP3), or an ADTS frame (layer 0: AAC) */
	if (n >= 2 && b[0] == 0xff && (b[1] & 0xe0) == 0xe0)
		return (b[1] & 0x06) == 0 ? ((b[1] & 0xf0) == 0xf0 ? "AAC (ADTS)" : NULL) : "MP3";
	return NULL;
}
