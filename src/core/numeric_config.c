/* numeric_config.c — the compile-time switches that change results (config.h,
 * PG_NUMERIC_CONFIG) as one value, and in words for messages.
 *
 * Each switch is a row of `fields`: its bits and how to say its value. A switch added to
 * PG_NUMERIC_CONFIG adds a row here; bits no row covers are named as unknown, so a
 * file from a build with a switch this one lacks is still refused with a message. */
#include "numeric_config.h"
#include "pogon/pogon.h"

typedef struct field {
    uint32_t shift, mask;
    void (*put)(pg__text *t, uint32_t value); /* the value in words, with its article */
} field;

static void put_trig_bits(pg__text *t, uint32_t bits)
{
    pg__text_put(t, bits == 8u || bits == 11u ? "an " : "a ");
    pg__text_u64(t, bits);
    pg__text_put(t, "-bit sine table");
}

static const field fields[] = {
    {PG_NUMCFG_TRIG_BITS_SHIFT, PG_NUMCFG_TRIG_BITS_MASK, put_trig_bits},
};
#define FIELD_COUNT (sizeof fields / sizeof fields[0])

uint32_t pg_numeric_config(void) { return (uint32_t)PG_NUMERIC_CONFIG; }

void pg__numeric_config_put(pg__text *t, uint32_t config)
{
    uint32_t known = 0;
    size_t i;
    for (i = 0; i < FIELD_COUNT; ++i) {
        if (i > 0) pg__text_put(t, ", ");
        fields[i].put(t, (config >> fields[i].shift) & fields[i].mask);
        known |= fields[i].mask << fields[i].shift;
    }
    if ((config & ~known) != 0) {
        pg__text_put(t, ", unknown switches ");
        pg__text_hex(t, config & ~known);
    }
}

size_t pg_numeric_config_describe(uint32_t config, char *buffer, size_t capacity)
{
    char whole[256]; /* every field fits: the text's length, whatever the caller's capacity */
    pg__text all = pg__text_in(whole, sizeof whole), t = pg__text_in(buffer, capacity);
    pg__numeric_config_put(&all, config);
    pg__numeric_config_put(&t, config);
    return all.len;
}
