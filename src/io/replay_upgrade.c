/* replay_upgrade.c — older replay formats into the current one (pg_replay_upgrade).
 *
 * One step per format change, applied in order, so a file of any older version climbs
 * to the current one; a new format version adds its step to `upgrade_step`. Each step
 * rewrites the header only: the scene, the records and their hashes do not move
 * relative to each other, so they are copied as they are and only the header hash and
 * the file checksum are computed again. The old file's own hashes are checked first,
 * so damage is never sealed as a sound file. Integer-only, no allocation. */
#include "pogon/replay_file.h"
#include "replay_file_internal.h"
#include "text.h"

/* Format 1: the format 2 header without numeric_config (docs/formats.md keeps both);
 * formats 3 and 4 have format 2's header. */
enum {
    V1_HEADER_HASH = 32, /* bytes 0..31 */
    V1_HEADER_SIZE = 40,
    V2_NUMERIC_CONFIG = 20,
    V2_HEADER_HASH = 36,
    V2_HEADER_SIZE = 44
};
PG__STATIC_ASSERT(V2_HEADER_SIZE == PG_REPLAY_HEADER_SIZE, upgrade_writes_the_current_header);

static uint32_t get_u16(const uint8_t *p) { return (uint32_t)p[0] | ((uint32_t)p[1] << 8); }
static uint64_t get_u64(const uint8_t *p)
{
    uint64_t v = 0;
    int i;
    for (i = 7; i >= 0; --i) v = v << 8 | p[i];
    return v;
}
static void put_u16(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)(v & 0xFFu);
    p[1] = (uint8_t)((v >> 8) & 0xFFu);
}
static void put_u32(uint8_t *p, uint32_t v)
{
    put_u16(p, v & 0xFFFFu);
    put_u16(p + 2, v >> 16);
}
static void put_u64(uint8_t *p, uint64_t v)
{
    put_u32(p, (uint32_t)(v & 0xFFFFFFFFu));
    put_u32(p + 4, (uint32_t)(v >> 32));
}
static void copy_bytes(uint8_t *dst, const uint8_t *src, size_t n)
{
    size_t i;
    for (i = 0; i < n; ++i) dst[i] = src[i];
}

static pg_result fail(pg_replay_error *e, pg_result r, size_t offset, const char *field, const char *text,
                      uint64_t value, const char *tail)
{
    if (e != NULL) {
        pg__text m = pg__text_in(e->message, sizeof e->message);
        e->offset = offset;
        e->region = offset < V1_HEADER_SIZE ? "header" : "file";
        e->field = field;
        e->frame = -1;
        e->command = -1;
        pg__text_put(&m, text);
        pg__text_u64(&m, value);
        pg__text_put(&m, tail);
    }
    return r;
}

/* Format 1 -> 2: numeric_config (unknown to format 1) goes in after the flags. */
static pg_result upgrade_1_to_2(const uint8_t *in, size_t size, uint32_t numeric_config, uint8_t *out,
                                pg_replay_error *e)
{
    if (size < (size_t)V1_HEADER_SIZE + 8u + PG_REPLAY_TRAILER_SIZE)
        return fail(e, PG_ERR_INVALID_ARGUMENT, size, "header", "the file ends at byte ", size,
                    ", before a format 1 file's header, scene hash and end record: it is truncated");
    if (pg_hash_bytes(PG_HASH_SEED, in, V1_HEADER_HASH) != get_u64(in + V1_HEADER_HASH))
        return fail(e, PG_ERR_INVALID_ARGUMENT, V1_HEADER_HASH, "header_hash",
                    "header hash mismatch (format 1 header, bytes 0..", V1_HEADER_HASH - 1, "): the file is damaged");
    if (pg_hash_bytes(PG_HASH_SEED, in, size - 8u) != get_u64(in + size - 8u))
        return fail(e, PG_ERR_INVALID_ARGUMENT, size - 8u, "checksum", "file checksum mismatch at byte ", size - 8u,
                    ": the file is damaged");
    copy_bytes(out, in, V2_NUMERIC_CONFIG);
    put_u16(out + 8, 2u);
    put_u32(out + V2_NUMERIC_CONFIG, numeric_config);
    copy_bytes(out + V2_NUMERIC_CONFIG + 4, in + V2_NUMERIC_CONFIG, V1_HEADER_HASH - V2_NUMERIC_CONFIG);
    put_u64(out + V2_HEADER_HASH, pg_hash_bytes(PG_HASH_SEED, out, V2_HEADER_HASH));
    copy_bytes(out + V2_HEADER_SIZE, in + V1_HEADER_SIZE, size - V1_HEADER_SIZE - 8u);
    put_u64(out + size + 4u - 8u, pg_hash_bytes(PG_HASH_SEED, out, size + 4u - 8u));
    return PG_OK;
}

/* Format 2 -> 3 -> 4: format 3 brought the joint commands (kinds 24..33), format 4 chain
 * segments in add_shape commands (geometry kind 4, its neighbours after its vertices).
 * Every format 2 or 3 record reads the same in format 4: only the header's version
 * changes, so its hash and the checksum do. Runs on `out` in place, after the old file's
 * own hashes were checked. */
static void restamp_version(uint8_t *out, size_t size)
{
    put_u16(out + 8, PG_REPLAY_FORMAT_VERSION);
    put_u64(out + V2_HEADER_HASH, pg_hash_bytes(PG_HASH_SEED, out, V2_HEADER_HASH));
    put_u64(out + size - 8u, pg_hash_bytes(PG_HASH_SEED, out, size - 8u));
}

static int v2_hashes_sound(const uint8_t *in, size_t size)
{
    return size >= (size_t)V2_HEADER_SIZE + 8u + PG_REPLAY_TRAILER_SIZE &&
           pg_hash_bytes(PG_HASH_SEED, in, V2_HEADER_HASH) == get_u64(in + V2_HEADER_HASH) &&
           pg_hash_bytes(PG_HASH_SEED, in, size - 8u) == get_u64(in + size - 8u);
}

/* The header part of pg_replay_upgrade: `out` holds the file in this build's format, with
 * its size and the old file's format version in w (upgrade_size, upgrade_version); PG_OK,
 * or the refusal (out_size as pg_replay_upgrade sets it). Its frame stays beside, not
 * under, the reader's chain. */
#if defined(__GNUC__) || defined(__clang__)
__attribute__((noinline))
#endif
static pg_result convert(const uint8_t *data, size_t size, uint32_t numeric_config, uint8_t *out, size_t capacity,
                         size_t *out_size, pg_replay_error *error, pg__replay_work *w)
{
    uint32_t version;
    size_t need, i;
    pg_result r;
    if (out_size != NULL) *out_size = 0;
    if (data == NULL || out == NULL) return PG_ERR_NULL;
    for (i = 0; i < 8; ++i)
        if (i >= size || data[i] != (uint8_t)PG_REPLAY_MAGIC[i])
            return fail(error, PG_ERR_INVALID_ARGUMENT, i, "magic", "not a pogon replay file (byte ", i,
                        " differs from \"PGREPLAY\")");
    if (size < 10u) return fail(error, PG_ERR_INVALID_ARGUMENT, size, "format_version", "the file ends at byte ", size, "");
    version = get_u16(data + 8);
    if (version == 0u || version > PG_REPLAY_FORMAT_VERSION)
        return fail(error, PG_ERR_INCOMPATIBLE, 8, "format_version", "format version ", version,
                    version == 0u ? " does not exist: the header is corrupt" : " is newer than this build's: nothing to upgrade");
    need = version == 1u ? size + 4u : size;
    if (out_size != NULL) *out_size = need;
    if (capacity < need) return PG_ERR_MEMORY;
    if (version == 1u) {
        r = upgrade_1_to_2(data, size, numeric_config, out, error);
        if (r != PG_OK) {
            if (out_size != NULL) *out_size = 0;
            return r;
        }
    } else {
        if (version < PG_REPLAY_FORMAT_VERSION && !v2_hashes_sound(data, size)) {
            if (out_size != NULL) *out_size = 0;
            return fail(error, PG_ERR_INVALID_ARGUMENT, V2_HEADER_HASH, "header_hash", "header hash or file checksum mismatch in a format ",
                        version, " file (header bytes 0..35, checksum in the last 8 bytes): the file is damaged");
        }
        copy_bytes(out, data, size);
    }
    if (version < PG_REPLAY_FORMAT_VERSION) restamp_version(out, need);
    w->upgrade_size = need;
    w->upgrade_version = version;
    return PG_OK;
}

pg_result pg_replay_upgrade_in(const uint8_t *data, size_t size, uint32_t numeric_config, uint8_t *out, size_t capacity,
                               size_t *out_size, pg_replay_error *error, void *work, size_t work_size)
{
    pg__replay_work *w = pg__replay_work_in(work, work_size, error);
    pg_result r;
    if (w == NULL) return PG_ERR_INVALID_ARGUMENT;
    r = convert(data, size, numeric_config, out, capacity, out_size, error, w);
    if (r != PG_OK) return r;
    /* the rest of the file (scene, records, block hashes), as the current reader sees it */
    r = pg__replay_read(out, w->upgrade_size, &w->upgrade_info, &w->upgrade_error, w);
    if (r == PG_ERR_INVALID_ARGUMENT || r == PG_ERR_NULL) {
        if (error != NULL) {
            *error = w->upgrade_error;
            if (w->upgrade_version == 1u && error->offset >= (size_t)V2_HEADER_SIZE) error->offset -= 4u; /* the old file's offset */
        }
        if (out_size != NULL) *out_size = 0;
        return r;
    }
    return PG_OK; /* PG_ERR_INCOMPATIBLE here is only another numeric configuration: the caller's stamp */
}

pg_result pg_replay_upgrade(const uint8_t *data, size_t size, uint32_t numeric_config, uint8_t *out, size_t capacity,
                            size_t *out_size, pg_replay_error *error)
{
    uint64_t work[PG_REPLAY_WORK_BYTES / 8u];
    return pg_replay_upgrade_in(data, size, numeric_config, out, capacity, out_size, error, work, sizeof work);
}
