/* SPDX-License-Identifier: GPL-3.0-or-later */
/*
 * cnum_g17.c - a double as printf's "%.17g" writes it in the C locale,
 * without printf (see cnum.h: cnum_g17).
 *
 * The digits: Grisu's counted mode (Florian Loitsch, "Printing
 * floating-point numbers quickly and accurately with integers", PLDI 2010;
 * the mode is double-conversion's FastDtoa with FAST_DTOA_PRECISION).  v is
 * scaled by a cached power of ten into [2^-60, 2^-32) units as a 64-bit
 * significand w known to within one unit, and 17 digits are cut from w.
 * The digits are then those of the exact value correctly rounded, as glibc
 * gives them, whenever the remainder lies clearly on one side of half the
 * last digit's unit with the one-unit error either way; otherwise (a tie
 * such as 2^-25, or a remainder within the error of the half) it says so
 * and printf writes the number instead.  About one number in 200 of random
 * bits falls back; every answer is either proved by that test or printf's.
 *
 * The layout is %g's: with X the decimal exponent of the first digit,
 * fixed notation when -4 <= X < 17, else d.ddde[+-]XX; trailing zeros and a
 * bare point removed; zero is 0 or -0.  Infinities and NaN go to printf.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "cnum.h"

/* 10^k for k = -348, -340, ..., 340: a 64-bit significand f (top bit set),
 * rounded to nearest, and e with 10^k ~ f * 2^e (tools: exact rational
 * arithmetic; the table is double-conversion's). */
static const struct {
	uint64_t f;
	int16_t e, k;
} cached[] = {
	{ 0xfa8fd5a0081c0288ULL, -1220, -348 }, { 0xbaaee17fa23ebf76ULL, -1193, -340 },
	{ 0x8b16fb203055ac76ULL, -1166, -332 }, { 0xcf42894a5dce35eaULL, -1140, -324 },
	{ 0x9a6bb0aa55653b2dULL, -1113, -316 }, { 0xe61acf033d1a45dfULL, -1087, -308 },
	{ 0xab70fe17c79ac6caULL, -1060, -300 }, { 0xff77b1fcbebcdc4fULL, -1034, -292 },
	{ 0xbe5691ef416bd60cULL, -1007, -284 }, { 0x8dd01fad907ffc3cULL, -980, -276 },
	{ 0xd3515c2831559a83ULL, -954, -268 }, { 0x9d71ac8fada6c9b5ULL, -927, -260 },
	{ 0xea9c227723ee8bcbULL, -901, -252 }, { 0xaecc49914078536dULL, -874, -244 },
	{ 0x823c12795db6ce57ULL, -847, -236 }, { 0xc21094364dfb5637ULL, -821, -228 },
	{ 0x9096ea6f3848984fULL, -794, -220 }, { 0xd77485cb25823ac7ULL, -768, -212 },
	{ 0xa086cfcd97bf97f4ULL, -741, -204 }, { 0xef340a98172aace5ULL, -715, -196 },
	{ 0xb23867fb2a35b28eULL, -688, -188 }, { 0x84c8d4dfd2c63f3bULL, -661, -180 },
	{ 0xc5dd44271ad3cdbaULL, -635, -172 }, { 0x936b9fcebb25c996ULL, -608, -164 },
	{ 0xdbac6c247d62a584ULL, -582, -156 }, { 0xa3ab66580d5fdaf6ULL, -555, -148 },
	{ 0xf3e2f893dec3f126ULL, -529, -140 }, { 0xb5b5ada8aaff80b8ULL, -502, -132 },
	{ 0x87625f056c7c4a8bULL, -475, -124 }, { 0xc9bcff6034c13053ULL, -449, -116 },
	{ 0x964e858c91ba2655ULL, -422, -108 }, { 0xdff9772470297ebdULL, -396, -100 },
	{ 0xa6dfbd9fb8e5b88fULL, -369, -92 }, { 0xf8a95fcf88747d94ULL, -343, -84 },
	{ 0xb94470938fa89bcfULL, -316, -76 }, { 0x8a08f0f8bf0f156bULL, -289, -68 },
	{ 0xcdb02555653131b6ULL, -263, -60 }, { 0x993fe2c6d07b7facULL, -236, -52 },
	{ 0xe45c10c42a2b3b06ULL, -210, -44 }, { 0xaa242499697392d3ULL, -183, -36 },
	{ 0xfd87b5f28300ca0eULL, -157, -28 }, { 0xbce5086492111aebULL, -130, -20 },
	{ 0x8cbccc096f5088ccULL, -103, -12 }, { 0xd1b71758e219652cULL, -77, -4 },
	{ 0x9c40000000000000ULL, -50, 4 }, { 0xe8d4a51000000000ULL, -24, 12 },
	{ 0xad78ebc5ac620000ULL, 3, 20 }, { 0x813f3978f8940984ULL, 30, 28 },
	{ 0xc097ce7bc90715b3ULL, 56, 36 }, { 0x8f7e32ce7bea5c70ULL, 83, 44 },
	{ 0xd5d238a4abe98068ULL, 109, 52 }, { 0x9f4f2726179a2245ULL, 136, 60 },
	{ 0xed63a231d4c4fb27ULL, 162, 68 }, { 0xb0de65388cc8ada8ULL, 189, 76 },
	{ 0x83c7088e1aab65dbULL, 216, 84 }, { 0xc45d1df942711d9aULL, 242, 92 },
	{ 0x924d692ca61be758ULL, 269, 100 }, { 0xda01ee641a708deaULL, 295, 108 },
	{ 0xa26da3999aef774aULL, 322, 116 }, { 0xf209787bb47d6b85ULL, 348, 124 },
	{ 0xb454e4a179dd1877ULL, 375, 132 }, { 0x865b86925b9bc5c2ULL, 402, 140 },
	{ 0xc83553c5c8965d3dULL, 428, 148 }, { 0x952ab45cfa97a0b3ULL, 455, 156 },
	{ 0xde469fbd99a05fe3ULL, 481, 164 }, { 0xa59bc234db398c25ULL, 508, 172 },
	{ 0xf6c69a72a3989f5cULL, 534, 180 }, { 0xb7dcbf5354e9beceULL, 561, 188 },
	{ 0x88fcf317f22241e2ULL, 588, 196 }, { 0xcc20ce9bd35c78a5ULL, 614, 204 },
	{ 0x98165af37b2153dfULL, 641, 212 }, { 0xe2a0b5dc971f303aULL, 667, 220 },
	{ 0xa8d9d1535ce3b396ULL, 694, 228 }, { 0xfb9b7cd9a4a7443cULL, 720, 236 },
	{ 0xbb764c4ca7a44410ULL, 747, 244 }, { 0x8bab8eefb6409c1aULL, 774, 252 },
	{ 0xd01fef10a657842cULL, 800, 260 }, { 0x9b10a4e5e9913129ULL, 827, 268 },
	{ 0xe7109bfba19c0c9dULL, 853, 276 }, { 0xac2820d9623bf429ULL, 880, 284 },
	{ 0x80444b5e7aa7cf85ULL, 907, 292 }, { 0xbf21e44003acdd2dULL, 933, 300 },
	{ 0x8e679c2f5e44ff8fULL, 960, 308 }, { 0xd433179d9c8cb841ULL, 986, 316 },
	{ 0x9e19db92b4e31ba9ULL, 1013, 324 }, { 0xeb96bf6ebadf77d9ULL, 1039, 332 },
	{ 0xaf87023b9bf0ee6bULL, 1066, 340 },
};

enum { DIGITS = 17, MIN_E = -60 };

static const uint64_t pow10_64[] = {
	1ULL, 10ULL, 100ULL, 1000ULL, 10000ULL, 100000ULL, 1000000ULL, 10000000ULL,
	100000000ULL, 1000000000ULL, 10000000000ULL, 100000000000ULL, 1000000000000ULL,
	10000000000000ULL, 100000000000000ULL, 1000000000000000ULL, 10000000000000000ULL,
	100000000000000000ULL,
};

static const char pairs[] =
	"00010203040506070809101112131415161718192021222324252627282930313233343536373839"
	"40414243444546474849505152535455565758596061626364656667686970717273747576777879"
	"8081828384858687888990919293949596979899";

/*
 * The 17 digits of v > 0 (finite, not zero) correctly rounded, as the
 * integer *N in [10^16, 10^17), and the decimal exponent X of the first
 * digit (v ~ N x 10^(X - 16)); 0, or -1 when the rounding cannot be proved
 * from the scaled value.
 */
static int
digits17(double v, uint64_t *N, int *X)
{
	uint64_t bits, f, one, rest, unit, n;
	int e, lz, mk, D, S, r;
	unsigned __int128 p;

	memcpy(&bits, &v, sizeof bits);
	f = bits & ((1ULL << 52) - 1);
	e = (int)((bits >> 52) & 0x7ff);
	if (e != 0) {
		f |= 1ULL << 52;
		e -= 1075;
	} else {
		e = -1074;
	}
	lz = __builtin_clzll(f);
	f <<= lz;
	e -= lz;
	{
		/* the cached power 10^mk that brings w's binary exponent into
		 * [-60, -32]: k = ceil(m log10 2), m = MIN_E - e - 1 (|m| < 1200,
		 * where floor(m log10 2) = (m x 78913) >> 18) */
		int m = MIN_E - e - 1;
		int kk = m == 0 ? 0 : ((m * 78913) >> 18) + 1;
		int idx = (348 + kk - 1) / 8 + 1;

		p = (unsigned __int128)f * cached[idx].f;
		f = (uint64_t)(p >> 64) + (((uint64_t)p >> 63) & 1);   /* rounded */
		e = e + cached[idx].e + 64;
		mk = cached[idx].k;
	}
	/*
	 * w = f x 2^e is within one unit (2^e) of v x 10^mk, and its integral
	 * part f >> S, S = -e in [32, 60], has D digits (1 to 10: f's top bit
	 * is set).  N0 = floor(w x 10^r), r = 17 - D, with the remainder rest
	 * in units of one = 2^S and the error unit = 10^r: the exact value is
	 * within (N0 + (rest - unit) / one, N0 + (rest + unit) / one).
	 */
	S = -e;
	{
		uint64_t in = f >> S;

		D = 1;
		while (D < 10 && in >= pow10_64[D])
			D++;
	}
	r = DIGITS - D;
	p = (unsigned __int128)f * pow10_64[r];
	n = (uint64_t)(p >> S);
	one = 1ULL << S;
	rest = (uint64_t)p & (one - 1);
	unit = pow10_64[r];
	if (2 * (rest + unit) <= one) {
		/* below the half by more than the error: the cut stands */
	} else if (rest > unit && 2 * (rest - unit) >= one) {
		/* above it by more than the error: round up */
		if (++n == pow10_64[DIGITS]) {
			n = pow10_64[DIGITS - 1];
			D++;
		}
	} else {
		return -1;
	}
	*N = n;
	*X = D - 1 - mk;
	return 0;
}

size_t
cnum_g17(char *buf, double v)
{
	char d[DIGITS + 1], *p = buf;
	uint64_t N;
	int X, last;

	if (v == 0) {
		if (signbit(v))
			*p++ = '-';
		*p++ = '0';
		*p = '\0';
		return (size_t)(p - buf);
	}
	if (!isfinite(v) || digits17(fabs(v), &N, &X) != 0)
		return (size_t)cnum_snprintf(buf, CNUM_G17_MAX, "%.17g", v);
	/* N's 17 digits into d, two at a time from the right */
	for (int i = DIGITS - 1; i > 0; i -= 2) {
		memcpy(d + i - 1, pairs + 2 * (N % 100), 2);
		N /= 100;
	}
	d[0] = (char)('0' + N);
	if (signbit(v))
		*p++ = '-';
	for (last = DIGITS - 1; last > 0 && d[last] == '0'; last--)
		;
	if (X < -4 || X >= DIGITS) {
		int a = X < 0 ? -X : X;

		*p++ = d[0];
		if (last > 0) {
			*p++ = '.';
			memcpy(p, d + 1, (size_t)last);
			p += last;
		}
		*p++ = 'e';
		*p++ = X < 0 ? '-' : '+';
		if (a >= 100)
			*p++ = (char)('0' + a / 100);
		*p++ = (char)('0' + a / 10 % 10);
		*p++ = (char)('0' + a % 10);
	} else if (X >= 0) {
		memcpy(p, d, (size_t)X + 1);
		p += X + 1;
		if (last > X) {
			*p++ = '.';
			memcpy(p, d + X + 1, (size_t)(last - X));
			p += last - X;
		}
	} else {
		*p++ = '0';
		*p++ = '.';
		for (int i = -1; i > X; i--)
			*p++ = '0';
		memcpy(p, d, (size_t)last + 1);
		p += last + 1;
	}
	*p = '\0';
	return (size_t)(p - buf);
}

size_t
cnum_long(char *buf, long v)
{
	char t[24];
	unsigned long u = v < 0 ? 0UL - (unsigned long)v : (unsigned long)v;
	size_t n = 0, k = 0;

	do {
		t[n++] = (char)('0' + u % 10);
		u /= 10;
	} while (u != 0);
	if (v < 0)
		buf[k++] = '-';
	while (n > 0)
		buf[k++] = t[--n];
	buf[k] = '\0';
	return k;
}
