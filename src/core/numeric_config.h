/* numeric_config.h (internal) — the numeric configuration in words, for the messages of
 * the file readers (replay_file.c, state.c). pg_numeric_config() and
 * pg_numeric_config_describe() are public (pogon/pogon.h). */
#ifndef POGON_SRC_NUMERIC_CONFIG_H
#define POGON_SRC_NUMERIC_CONFIG_H
#include <stdint.h>

#include "text.h"

/* Append `config` in words ("a 12-bit sine table") to t. */
void pg__numeric_config_put(pg__text *t, uint32_t config);

#endif
