/* work_area.h (internal) — the one check the file readers make of a work area a caller
 * lends them (the `_in` calls of pogon/scene_file.h and pogon/replay_file.h), and the
 * one way their messages say what it lacks. */
#ifndef POGON_SRC_WORK_AREA_H
#define POGON_SRC_WORK_AREA_H
#include <stddef.h>
#include <stdint.h>

#include "text.h"

/* NULL when `work` holds `need` bytes aligned to 8 (the readers keep int64 values, whose
 * alignment is 8 on every target pogon supports, AAPCS included); else what it lacks. */
static inline const char *pg__work_area_problem(const void *work, size_t size, size_t need)
{
    return work == NULL ? "work is NULL" : ((uintptr_t)work & 7u) != 0 ? "work is not aligned to 8 bytes"
         : size < need ? "work is too small" : NULL;
}

/* After the problem: ": the READER needs SIZE_CALL = NEED bytes aligned to 8 (given SIZE)". */
static inline void pg__work_area_explain(pg__text *m, const char *reader, const char *size_call, size_t need, const void *work,
                                         size_t size)
{
    pg__text_put(m, ": the ");
    pg__text_put(m, reader);
    pg__text_put(m, " needs ");
    pg__text_put(m, size_call);
    pg__text_put(m, " = ");
    pg__text_u64(m, need);
    pg__text_put(m, " bytes aligned to 8 (given ");
    pg__text_u64(m, work == NULL ? 0u : size);
    pg__text_put(m, ")");
}

#endif
