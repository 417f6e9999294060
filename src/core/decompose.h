/* decompose.h (internal) — a simple polygon split into convex pieces (pure geometry,
 * no world): what pg_geometry_decompose and pg_make_concave share. */
#ifndef POGON_SRC_DECOMPOSE_H
#define POGON_SRC_DECOMPOSE_H
#include "pogon/pogon.h"
#include "text.h"

/* A convex piece: indices into the caller's vertex array, counter-clockwise. Indices
 * rather than coordinates keep the whole decomposition at about 600 bytes. */
typedef struct pg__piece {
    uint8_t count;
    uint8_t index[PG_MAX_VERTICES];
} pg__piece;

typedef struct pg__decomposition {
    int32_t count;
    pg__piece pieces[PG_CONCAVE_MAX_PIECES];
} pg__decomposition;

/* Split vertices[0..n) (docs/concave.md). PG_OK, or the refusal's code with its reason
 * (naming the vertex or edge at fault) appended to *why. */
pg_result pg__decompose(const pg_vec2 *vertices, int32_t n, pg__decomposition *out, pg__text *why);

/* The polygon geometry of one piece (checked by pg__decompose: always accepted). */
void pg__piece_geometry(const pg_vec2 *vertices, const pg__piece *piece, pg_geometry *out);

#endif
