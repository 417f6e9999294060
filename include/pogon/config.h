/* pogon/config.h — compile-time switches.
 *
 * Define these before building the library (CMake cache options of the same name set
 * them for you). Each one trades accuracy or features for time and size; the
 * accuracy-versus-time report measures them.
 */
#ifndef POGON_CONFIG_H
#define POGON_CONFIG_H

/* Entries per full turn of the sine table, as a power of two: 8 (256 entries, 1 KiB)
 * to 14 (16384 entries, 64 KiB). Sine and cosine interpolate linearly between entries;
 * the interpolation error is about (2 pi / 2^bits)^2 / 8: 4.7e-6 at 10 bits, which is
 * below half a Q16.16 step, and 2.9e-7 at 12 bits. */
#ifndef PG_TRIG_TABLE_BITS
#define PG_TRIG_TABLE_BITS 10
#endif
#if PG_TRIG_TABLE_BITS < 8 || PG_TRIG_TABLE_BITS > 14
#error "PG_TRIG_TABLE_BITS must be between 8 and 14"
#endif

#endif
