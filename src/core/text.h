/* text.h (internal) — error messages built without snprintf: the library calls none of
 * the C library's formatted output (it may run where there is none), so every message
 * with a number in it is assembled here. Text is appended to a caller's buffer, which
 * always stays NUL-terminated; what does not fit is cut off, never overrun. A text with
 * no buffer (NULL, capacity 0) takes everything and keeps nothing, for callers that did
 * not ask for the message. */
#ifndef POGON_SRC_TEXT_H
#define POGON_SRC_TEXT_H
#include <stddef.h>
#include <stdint.h>

#include "pogon/fixed.h"
#include "wide.h" /* pg__mag64 */

typedef struct pg__text { char *buf; size_t cap, len; } pg__text;

/* An empty text in buf[0..cap); buf NULL or cap 0: a text that keeps nothing. */
static inline pg__text pg__text_in(char *buf, size_t cap)
{
    pg__text t;
    t.buf = buf;
    t.cap = buf != NULL ? cap : 0;
    t.len = 0;
    if (t.cap > 0) buf[0] = '\0';
    return t;
}

static inline void pg__text_char(pg__text *t, char c)
{
    if (t->cap == 0) return;
    if (t->len + 1 < t->cap) t->buf[t->len++] = c;
    t->buf[t->len] = '\0';
}

/* s may be NULL (nothing is appended). */
static inline void pg__text_put(pg__text *t, const char *s)
{
    if (t->cap == 0) return;
    while (s != NULL && *s != '\0' && t->len + 1 < t->cap) t->buf[t->len++] = *s++;
    t->buf[t->len] = '\0';
}

static inline void pg__text_u64(pg__text *t, uint64_t v)
{
    char digits[20];
    int n = 0;
    do {
        digits[n++] = (char)('0' + (int)(v % 10u));
        v /= 10u;
    } while (v != 0u);
    while (n > 0) pg__text_char(t, digits[--n]);
}

/* INT64_MIN included (pg__mag64). */
static inline void pg__text_i64(pg__text *t, int64_t v)
{
    if (v < 0) pg__text_char(t, '-');
    pg__text_u64(t, pg__mag64(v));
}

/* 0x and 16 lowercase hex digits. */
static inline void pg__text_hex(pg__text *t, uint64_t v)
{
    static const char digits[] = "0123456789abcdef";
    int shift;
    pg__text_put(t, "0x");
    for (shift = 60; shift >= 0; shift -= 4) pg__text_char(t, digits[(v >> shift) & 0xFu]);
}

/* A Q16.16 value as pg_fix_format writes it ("-12.375"). */
static inline void pg__text_fix(pg__text *t, pg_fix v)
{
    char num[PG_FIX_FORMAT_MAX];
    pg_fix_format(v, num, sizeof num);
    pg__text_put(t, num);
}
#endif
