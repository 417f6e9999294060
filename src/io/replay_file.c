/* replay_file.c — replay files (docs/formats.md, "Replay files"): writer, validating
 * reader and player. Integer-only, no allocation, no libc; every read is bounds-checked
 * against the size the caller gave. */
#include "pogon/replay_file.h"
#include "pogon/scene_file.h"
#include "replay_file_internal.h"
#include "numeric_config.h"
#include "text.h"
#include "work_area.h"
#include "world_internal.h" /* pg__fail: pg_replay_apply_frame's messages */

/* A function whose frame must not be merged into its caller's (gcc inlines a static
 * function called once): see check_file. */
#if defined(__GNUC__) || defined(__clang__)
#define PG__OWN_FRAME static __attribute__((noinline))
#else
#define PG__OWN_FRAME static
#endif
/* The opposite: a function that adds no frame to the scene reader's chain below it
 * (the stack budget of docs/embedded.md), wherever it is called from. */
#if defined(__GNUC__) || defined(__clang__)
#define PG__NO_FRAME static inline __attribute__((always_inline))
#else
#define PG__NO_FRAME static inline
#endif

/* ---- little-endian fields ------------------------------------------------------------ */
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
static uint32_t get_u16(const uint8_t *p) { return (uint32_t)p[0] | ((uint32_t)p[1] << 8); }
static uint32_t get_u32(const uint8_t *p) { return get_u16(p) | (get_u16(p + 2) << 16); }
static uint64_t get_u64(const uint8_t *p) { return (uint64_t)get_u32(p) | ((uint64_t)get_u32(p + 4) << 32); }

static void copy_bytes(uint8_t *dst, const void *src, size_t n)
{
    const uint8_t *s = (const uint8_t *)src;
    size_t i;
    for (i = 0; i < n; ++i) dst[i] = s[i];
}

static uint64_t hash_range(const uint8_t *data, size_t begin, size_t end)
{
    return pg_hash_bytes(PG_HASH_SEED, data + begin, end - begin);
}

/* ---- error messages (text.h) ---------------------------------------------------------- */
typedef pg__text msg;

/* Fill *e (when not NULL) and return the message builder for details. */
static msg set_error(pg_replay_error *e, size_t offset, const char *region, const char *field, int64_t frame,
                     int64_t command, const char *text)
{
    msg m;
    if (e == NULL) {
        m = pg__text_in(NULL, 0); /* nobody asked: the details go nowhere */
    } else {
        e->offset = offset;
        e->region = region;
        e->field = field;
        e->frame = frame;
        e->command = command;
        m = pg__text_in(e->message, sizeof e->message);
    }
    pg__text_put(&m, text);
    return m;
}

/* pg_world_hash's rule: FNV-1a of the section hashes as stored (u64 little-endian). */
static uint64_t hash_of_sections(const uint8_t *sections, uint32_t count)
{
    return pg_hash_bytes(PG_HASH_SEED, sections, (size_t)count * 8u);
}

static void clear_error(pg_replay_error *e)
{
    if (e != NULL) {
        msg m = set_error(e, 0, "", "", -1, -1, "");
        (void)m;
    }
}

/* "stored X, computed Y" after a hash mismatch. */
static pg_result hash_error(pg_replay_error *e, size_t offset, const char *region, const char *field, int64_t frame,
                            const char *what, uint64_t stored, uint64_t computed)
{
    msg m = set_error(e, offset, region, field, frame, -1, what);
    pg__text_put(&m, ": stored ");
    pg__text_hex(&m, stored);
    pg__text_put(&m, ", computed ");
    pg__text_hex(&m, computed);
    return PG_ERR_INVALID_ARGUMENT;
}

static pg_result value_error(pg_replay_error *e, size_t offset, const char *region, const char *field, int64_t frame,
                             const char *what, uint64_t value, const char *tail)
{
    msg m = set_error(e, offset, region, field, frame, -1, what);
    pg__text_u64(&m, value);
    pg__text_put(&m, tail);
    return PG_ERR_INVALID_ARGUMENT;
}

static pg_result truncated(pg_replay_error *e, size_t size, const char *region, const char *field, int64_t frame,
                           size_t need_end)
{
    msg m = set_error(e, size, region, field, frame, -1, "file ends at byte ");
    pg__text_u64(&m, size);
    pg__text_put(&m, " inside this field (it needs ");
    pg__text_u64(&m, need_end);
    pg__text_put(&m, " bytes): the file is truncated");
    return PG_ERR_INVALID_ARGUMENT;
}

/* ---- layout ----------------------------------------------------------------------------- */
enum {
    OFF_MAGIC = 0,
    OFF_FORMAT = 8,
    OFF_ENGINE_MAJOR = 10,
    OFF_ENGINE_MINOR = 12,
    OFF_ENGINE_PATCH = 14,
    OFF_FLAGS = 16,
    OFF_NUMERIC_CONFIG = 20,
    OFF_INTERVAL = 24,
    OFF_SECTIONS = 28,
    OFF_SCENE_SIZE = 32,
    OFF_HEADER_HASH = 36,
    OFF_SCENE_TEXT = 44
};
PG__STATIC_ASSERT(OFF_SCENE_TEXT == PG_REPLAY_HEADER_SIZE, replay_header_size);
/* checkpoint record: tag u8, frame u32, hash u64, sections u64 x S, block hash u64 */
static size_t checkpoint_size(uint32_t sections) { return 1u + 4u + 8u + 8u * (size_t)sections + 8u; }

/* ---- writer ------------------------------------------------------------------------------ */
pg_result pg_replay_writer_begin(pg_replay_writer *w, uint8_t *buffer, size_t capacity, const char *scene_text,
                                 size_t scene_size, uint32_t checkpoint_interval)
{
    size_t need;
    uint8_t *p;
    if (w == NULL || buffer == NULL || (scene_text == NULL && scene_size != 0)) return PG_ERR_NULL;
    if (checkpoint_interval == 0 || scene_size > 0xFFFFFFFFu - 64u) return PG_ERR_INVALID_ARGUMENT;
    need = (size_t)OFF_SCENE_TEXT + scene_size + 8u;
    w->buffer = buffer;
    w->capacity = capacity;
    w->size = 0;
    w->block_start = 0;
    w->checkpoint_interval = checkpoint_interval;
    w->frame_count = 0;
    w->checkpoint_count = 0;
    w->finished = 0;
    if (capacity < need) return PG_ERR_MEMORY;
    p = buffer;
    copy_bytes(p + OFF_MAGIC, PG_REPLAY_MAGIC, 8);
    put_u16(p + OFF_FORMAT, PG_REPLAY_FORMAT_VERSION);
    put_u16(p + OFF_ENGINE_MAJOR, POGON_VERSION_MAJOR);
    put_u16(p + OFF_ENGINE_MINOR, POGON_VERSION_MINOR);
    put_u16(p + OFF_ENGINE_PATCH, POGON_VERSION_PATCH);
    put_u32(p + OFF_FLAGS, 0);
    put_u32(p + OFF_NUMERIC_CONFIG, pg_numeric_config());
    put_u32(p + OFF_INTERVAL, checkpoint_interval);
    put_u32(p + OFF_SECTIONS, PG_SECTION_COUNT);
    put_u32(p + OFF_SCENE_SIZE, (uint32_t)scene_size);
    put_u64(p + OFF_HEADER_HASH, hash_range(p, 0, OFF_HEADER_HASH));
    if (scene_size != 0) copy_bytes(p + OFF_SCENE_TEXT, scene_text, scene_size);
    put_u64(p + OFF_SCENE_TEXT + scene_size, hash_range(p, OFF_SCENE_TEXT, OFF_SCENE_TEXT + scene_size));
    w->size = need;
    w->block_start = need;
    return PG_OK;
}

pg_result pg_replay_writer_set_buffer(pg_replay_writer *w, uint8_t *buffer, size_t capacity)
{
    if (w == NULL || buffer == NULL) return PG_ERR_NULL;
    if (capacity < w->size) return PG_ERR_INVALID_ARGUMENT;
    w->buffer = buffer;
    w->capacity = capacity;
    return PG_OK;
}

int pg_replay_writer_checkpoint_due(const pg_replay_writer *w)
{
    if (w == NULL || w->finished || w->checkpoint_interval == 0) return 0;
    return w->frame_count % w->checkpoint_interval == 0u &&
           w->checkpoint_count <= w->frame_count / w->checkpoint_interval;
}

pg_result pg_replay_writer_add_frame(pg_replay_writer *w, const pg_command *commands, uint32_t count)
{
    size_t pos, i;
    if (w == NULL || w->buffer == NULL || (commands == NULL && count != 0)) return PG_ERR_NULL;
    if (w->finished || pg_replay_writer_checkpoint_due(w) || count > PG_REPLAY_MAX_FRAME_COMMANDS ||
        w->frame_count == 0xFFFFFFFFu)
        return PG_ERR_INVALID_ARGUMENT;
    if (w->capacity - w->size < 3u) return PG_ERR_MEMORY;
    pos = w->size;
    w->buffer[pos] = (uint8_t)PG_REPLAY_TAG_FRAME;
    put_u16(w->buffer + pos + 1, count);
    pos += 3;
    for (i = 0; i < count; ++i) {
        uint8_t tmp[PG_COMMAND_ENCODED_MAX];
        size_t n = pg_command_encode(&commands[i], tmp, sizeof tmp);
        if (n == 0) return PG_ERR_INVALID_ARGUMENT; /* nothing committed: w->size unchanged */
        if (w->capacity - pos < n) return PG_ERR_MEMORY;
        copy_bytes(w->buffer + pos, tmp, n);
        pos += n;
    }
    w->size = pos;
    w->frame_count++;
    return PG_OK;
}

pg_result pg_replay_writer_add_checkpoint(pg_replay_writer *w, uint64_t hash, const uint64_t sections[PG_SECTION_COUNT])
{
    size_t pos, need = checkpoint_size(PG_SECTION_COUNT);
    unsigned s;
    if (w == NULL || w->buffer == NULL || sections == NULL) return PG_ERR_NULL;
    if (!pg_replay_writer_checkpoint_due(w)) return PG_ERR_INVALID_ARGUMENT;
    {   /* the state hash must be the hash of the section hashes, as the reader checks */
        uint8_t le[8 * PG_SECTION_COUNT];
        for (s = 0; s < PG_SECTION_COUNT; ++s) put_u64(le + (size_t)8u * s, sections[s]);
        if (hash != hash_of_sections(le, PG_SECTION_COUNT)) return PG_ERR_INVALID_ARGUMENT;
    }
    if (w->capacity - w->size < need) return PG_ERR_MEMORY;
    pos = w->size;
    w->buffer[pos] = (uint8_t)PG_REPLAY_TAG_CHECKPOINT;
    put_u32(w->buffer + pos + 1, w->frame_count);
    put_u64(w->buffer + pos + 5, hash);
    for (s = 0; s < PG_SECTION_COUNT; ++s) put_u64(w->buffer + pos + 13 + (size_t)8u * s, sections[s]);
    pos += need - 8u;
    put_u64(w->buffer + pos, hash_range(w->buffer, w->block_start, pos));
    pos += 8u;
    w->size = pos;
    w->block_start = pos;
    w->checkpoint_count++;
    return PG_OK;
}

pg_result pg_replay_writer_add_checkpoint_world(pg_replay_writer *w, const pg_world *world)
{
    uint64_t sections[PG_SECTION_COUNT];
    if (world == NULL) return PG_ERR_NULL;
    pg_world_section_hashes(world, sections);
    return pg_replay_writer_add_checkpoint(w, pg_world_hash(world), sections);
}

pg_result pg_replay_writer_finish(pg_replay_writer *w, uint64_t final_hash, size_t *size)
{
    size_t pos;
    if (w == NULL || w->buffer == NULL) return PG_ERR_NULL;
    if (w->finished || pg_replay_writer_checkpoint_due(w)) return PG_ERR_INVALID_ARGUMENT;
    if (w->capacity - w->size < PG_REPLAY_TRAILER_SIZE) return PG_ERR_MEMORY;
    pos = w->size;
    w->buffer[pos] = (uint8_t)PG_REPLAY_TAG_END;
    put_u32(w->buffer + pos + 1, w->frame_count);
    put_u64(w->buffer + pos + 5, final_hash);
    put_u64(w->buffer + pos + 13, hash_range(w->buffer, w->block_start, pos + 13));
    put_u64(w->buffer + pos + 21, hash_range(w->buffer, 0, pos + 21));
    w->size = pos + PG_REPLAY_TRAILER_SIZE;
    w->finished = 1;
    if (size != NULL) *size = w->size;
    return PG_OK;
}

/* ---- reader ------------------------------------------------------------------------------ */
/* Byte offset within the scene text of a scene error's line and column (from 1). */
static size_t scene_error_offset(const pg_replay_info *info, const pg_scene_error *se)
{
    size_t pos = 0;
    uint32_t line = 1;
    if (se->line == 0) return 0;
    while (line < se->line && pos < info->scene_size) {
        if (info->scene_text[pos] == '\n') line++;
        pos++;
    }
    if (se->column > 1) {
        size_t col = se->column - 1u;
        pos = col <= info->scene_size - pos ? pos + col : info->scene_size;
    }
    return pos;
}

/* ---- the work area ------------------------------------------------------------------------ */
/* The replay part's size rounded up to 8, where the scene reader's work area starts. */
#define REPLAY_OWN_BYTES ((sizeof(pg__replay_work) + 7u) & ~(size_t)7u)
PG__STATIC_ASSERT(REPLAY_OWN_BYTES + PG_SCENE_WORK_BYTES <= PG_REPLAY_WORK_BYTES, replay_work_fits);

size_t pg_replay_work_size(void) { return REPLAY_OWN_BYTES + pg_scene_work_size(); }

pg__replay_work *pg__replay_work_in(void *work, size_t work_size, pg_replay_error *error)
{
    const char *why = pg__work_area_problem(work, work_size, pg_replay_work_size());
    msg m;
    if (why == NULL) return (pg__replay_work *)work;
    m = set_error(error, 0, "work", "work_size", -1, -1, why);
    pg__work_area_explain(&m, "replay reader", "pg_replay_work_size()", pg_replay_work_size(), work, work_size);
    return NULL;
}

/* The scene reader's part of the work area. */
static void *scene_work(pg__replay_work *w) { return (uint8_t *)w + REPLAY_OWN_BYTES; }

/* *e from the scene reader's error: "WHAT: its message" at its offset in the file. */
PG__OWN_FRAME pg_result scene_error(const pg_replay_info *info, const pg_scene_error *se, pg_replay_error *e,
                                    const char *what)
{
    size_t off = scene_error_offset(info, se);
    msg m = set_error(e, info->scene_offset + off, "scene", "text", -1, -1, what);
    pg__text_put(&m, se->message);
    return PG_ERR_INVALID_ARGUMENT;
}

/* Check the scene text with the scene parser; errors name the file offset. */
PG__NO_FRAME pg_result check_scene(const pg_replay_info *info, pg_world_def *def, pg_replay_error *e, pg__replay_work *w)
{
    pg_result r = pg_scene_read_def_in(info->scene_text, info->scene_size, def, &w->scene_error, scene_work(w),
                                       pg_scene_work_size());
    return r != PG_OK ? scene_error(info, &w->scene_error, e, "scene text does not parse: ") : PG_OK;
}

/* PG_OK when `recorded` is this build's numeric configuration; otherwise
 * PG_ERR_INCOMPATIBLE and a message naming both. */
PG__OWN_FRAME pg_result numeric_config_error(uint32_t recorded, pg_replay_error *e)
{
    msg m;
    if (recorded == pg_numeric_config()) return PG_OK;
    m = set_error(e, OFF_NUMERIC_CONFIG, "header", "numeric_config", -1, -1, "recorded with ");
    pg__numeric_config_put(&m, recorded);
    pg__text_put(&m, "; this build has ");
    pg__numeric_config_put(&m, pg_numeric_config());
    pg__text_put(&m, " (config.h): replay it with a build configured like the recorder");
    return PG_ERR_INCOMPATIBLE;
}

/* Everything pg_replay_read checks but the scene, into *in (the work area's): the header,
 * the records and every hash. Its frame (commands decoded, counters) stays beside, not
 * under, the scene reader's chain. */
PG__OWN_FRAME pg_result check_file(const uint8_t *data, size_t size, pg_replay_info *info, pg_replay_info *in,
                                   pg_replay_error *error)
{
    size_t pos, block_start, scene_size, records_end, i;
    uint32_t n, sections, frame = 0, checkpoints = 0;
    uint64_t stored, computed;
    pg_result r;

    {
        uint8_t *z = (uint8_t *)info;
        for (i = 0; i < sizeof *info; ++i) z[i] = 0;
        z = (uint8_t *)in;
        for (i = 0; i < sizeof *in; ++i) z[i] = 0;
    }
    in->size = size;

    /* header */
    for (i = 0; i < 8; ++i) {
        if (i >= size) return truncated(error, size, "header", "magic", -1, 8);
        if (data[i] != (uint8_t)PG_REPLAY_MAGIC[i]) {
            set_error(error, i, "header", "magic", -1, -1,
                      "not a pogon replay file: it must start with the 8 bytes \"PGREPLAY\"");
            return PG_ERR_INVALID_ARGUMENT;
        }
    }
    if (size < OFF_FORMAT + 2u) return truncated(error, size, "header", "format_version", -1, OFF_FORMAT + 2u);
    in->format_version = get_u16(data + OFF_FORMAT);
    info->format_version = in->format_version;
    info->size = size;
    if (in->format_version != PG_REPLAY_FORMAT_VERSION) {
        msg m = set_error(error, OFF_FORMAT, "header", "format_version", -1, -1, "format version ");
        pg__text_u64(&m, in->format_version);
        if (in->format_version == 0) {
            pg__text_put(&m, " does not exist: the header is corrupt");
            return PG_ERR_INVALID_ARGUMENT;
        }
        if (in->format_version < PG_REPLAY_FORMAT_VERSION) {
            pg__text_put(&m, " is older than this build's ");
            pg__text_u64(&m, PG_REPLAY_FORMAT_VERSION);
            pg__text_put(&m, ": convert it with `pogon-replay upgrade IN OUT` (pg_replay_upgrade)");
        } else {
            pg__text_put(&m, " is newer than this build's ");
            pg__text_u64(&m, PG_REPLAY_FORMAT_VERSION);
            pg__text_put(&m, ": read it with the pogon that wrote it, or a later one");
        }
        return PG_ERR_INCOMPATIBLE;
    }
    if (size < PG_REPLAY_HEADER_SIZE) return truncated(error, size, "header", "header", -1, PG_REPLAY_HEADER_SIZE);
    in->engine_major = get_u16(data + OFF_ENGINE_MAJOR);
    in->engine_minor = get_u16(data + OFF_ENGINE_MINOR);
    in->engine_patch = get_u16(data + OFF_ENGINE_PATCH);
    in->flags = get_u32(data + OFF_FLAGS);
    in->numeric_config = get_u32(data + OFF_NUMERIC_CONFIG);
    in->checkpoint_interval = get_u32(data + OFF_INTERVAL);
    in->section_count = get_u32(data + OFF_SECTIONS);
    if (in->flags != 0)
        return value_error(error, OFF_FLAGS, "header", "flags", -1, "flags ", in->flags,
                           " are not defined in this format version (must be 0)");
    if (in->checkpoint_interval == 0)
        return value_error(error, OFF_INTERVAL, "header", "checkpoint_interval", -1, "checkpoint interval ", 0,
                           " is invalid (must be at least 1)");
    if (in->section_count == 0 || in->section_count > PG_REPLAY_MAX_SECTIONS)
        return value_error(error, OFF_SECTIONS, "header", "section_count", -1, "section count ", in->section_count,
                           " is out of range 1..16");
    stored = get_u64(data + OFF_HEADER_HASH);
    computed = hash_range(data, 0, OFF_HEADER_HASH);
    if (stored != computed)
        return hash_error(error, OFF_HEADER_HASH, "header", "header_hash", -1, "header hash mismatch (bytes 0..35)",
                          stored, computed);

    /* the file ends with the fixed-size end record */
    if (size < (size_t)OFF_SCENE_TEXT + 8u + PG_REPLAY_TRAILER_SIZE)
        return truncated(error, size, "scene", "scene", -1, (size_t)OFF_SCENE_TEXT + 8u + PG_REPLAY_TRAILER_SIZE);
    records_end = size - PG_REPLAY_TRAILER_SIZE;

    /* scene */
    scene_size = get_u32(data + OFF_SCENE_SIZE);
    if (scene_size > records_end - OFF_SCENE_TEXT - 8u) {
        msg m = set_error(error, OFF_SCENE_SIZE, "header", "scene_size", -1, -1, "scene size ");
        pg__text_u64(&m, scene_size);
        pg__text_put(&m, " runs past the end of the file (at most ");
        pg__text_u64(&m, records_end - OFF_SCENE_TEXT - 8u);
        pg__text_put(&m, " bytes fit): the file is truncated or the size is corrupt");
        return PG_ERR_INVALID_ARGUMENT;
    }
    in->scene_text = (const char *)(data + OFF_SCENE_TEXT);
    in->scene_size = scene_size;
    in->scene_offset = OFF_SCENE_TEXT;
    pos = OFF_SCENE_TEXT + scene_size;
    stored = get_u64(data + pos);
    computed = hash_range(data, OFF_SCENE_TEXT, pos);
    if (stored != computed) {
        msg m = set_error(error, pos, "scene", "scene_hash", -1, -1, "scene hash mismatch (scene text, bytes ");
        pg__text_u64(&m, OFF_SCENE_TEXT);
        pg__text_put(&m, "..");
        pg__text_u64(&m, pos - 1u);
        pg__text_put(&m, "): stored ");
        pg__text_hex(&m, stored);
        pg__text_put(&m, ", computed ");
        pg__text_hex(&m, computed);
        return PG_ERR_INVALID_ARGUMENT;
    }
    pos += 8u;
    in->records_offset = pos;
    block_start = pos;
    sections = in->section_count;

    /* records: C(0) F... C(N) F... ... E */
    for (;;) {
        int due = frame % in->checkpoint_interval == 0u && checkpoints <= frame / in->checkpoint_interval;
        uint8_t tag;
        if (pos >= records_end) {
            /* the end record must start exactly at records_end */
            if (due) {
                msg m = set_error(error, pos, "checkpoint", "tag", (int64_t)frame, -1, "checkpoint ");
                pg__text_u64(&m, checkpoints);
                pg__text_put(&m, " at frame ");
                pg__text_u64(&m, frame);
                pg__text_put(&m, " is missing: the end record follows");
                return PG_ERR_INVALID_ARGUMENT;
            }
            break;
        }
        tag = data[pos];
        if (due) {
            size_t cs = checkpoint_size(sections);
            if (tag != PG_REPLAY_TAG_CHECKPOINT) {
                msg m = set_error(error, pos, "checkpoint", "tag", (int64_t)frame, -1, "expected checkpoint ");
                pg__text_u64(&m, checkpoints);
                pg__text_put(&m, " (tag 'C') at frame ");
                pg__text_u64(&m, frame);
                pg__text_put(&m, ", found byte ");
                pg__text_u64(&m, tag);
                return PG_ERR_INVALID_ARGUMENT;
            }
            if (records_end - pos < cs) return truncated(error, records_end, "checkpoint", "checkpoint", (int64_t)frame, pos + cs);
            n = get_u32(data + pos + 1);
            if (n != frame)
                return value_error(error, pos + 1, "checkpoint", "frame", (int64_t)frame, "checkpoint names frame ", n,
                                   ", but it follows a different frame record count");
            stored = get_u64(data + pos + cs - 8u);
            computed = hash_range(data, block_start, pos + cs - 8u);
            if (stored != computed) {
                msg m = set_error(error, pos + cs - 8u, "checkpoint", "block_hash", (int64_t)frame, -1,
                                  "block hash mismatch (bytes ");
                pg__text_u64(&m, block_start);
                pg__text_put(&m, "..");
                pg__text_u64(&m, pos + cs - 9u);
                pg__text_put(&m, ", the records before this checkpoint): stored ");
                pg__text_hex(&m, stored);
                pg__text_put(&m, ", computed ");
                pg__text_hex(&m, computed);
                return PG_ERR_INVALID_ARGUMENT;
            }
            /* the state hash is the hash of the section hashes (pg_world_hash): a
             * checkpoint where it is not was altered, whatever engine wrote it */
            stored = get_u64(data + pos + 5u);
            computed = hash_of_sections(data + pos + 13u, sections);
            if (stored != computed)
                return hash_error(error, pos + 5u, "checkpoint", "hash", (int64_t)frame,
                                  "checkpoint state hash is not the hash of its section hashes (the checkpoint was altered)",
                                  stored, computed);
            pos += cs;
            block_start = pos;
            checkpoints++;
            continue;
        }
        if (tag == PG_REPLAY_TAG_END) break;
        if (tag != PG_REPLAY_TAG_FRAME) {
            msg m = set_error(error, pos, "frame", "tag", (int64_t)frame, -1, "expected a frame record (tag 'F') or the end record (tag 'E'), found byte ");
            pg__text_u64(&m, tag);
            return PG_ERR_INVALID_ARGUMENT;
        }
        if (frame == 0xFFFFFFFFu)
            return value_error(error, pos, "frame", "tag", (int64_t)frame, "more than ", 0xFFFFFFFFu, " frames");
        if (records_end - pos < 3u) return truncated(error, records_end, "frame", "command_count", (int64_t)frame, pos + 3u);
        n = get_u16(data + pos + 1);
        pos += 3u;
        {
            uint32_t c;
            for (c = 0; c < n; ++c) {
                pg_command cmd;
                size_t used = 0, eoff = 0;
                const char *efield = NULL;
                r = pg_command_decode(data + pos, records_end - pos, &cmd, &used, &eoff, &efield);
                if (r != PG_OK || used == 0 || used > records_end - pos) {
                    msg m;
                    if (eoff > records_end - pos) eoff = records_end - pos;
                    m = set_error(error, pos + eoff, "frame", efield != NULL ? efield : "command", (int64_t)frame,
                                  (int64_t)c, "command ");
                    pg__text_u64(&m, c);
                    pg__text_put(&m, " of ");
                    pg__text_u64(&m, n);
                    pg__text_put(&m, " in frame ");
                    pg__text_u64(&m, frame);
                    pg__text_put(&m, " does not decode (starts at byte ");
                    pg__text_u64(&m, pos);
                    pg__text_put(&m, pos + eoff >= records_end ? "; it runs into the end record: truncated?)"
                                                           : ")");
                    return PG_ERR_INVALID_ARGUMENT;
                }
                if ((unsigned)cmd.kind < PG_CMD_KIND_COUNT) in->kind_counts[cmd.kind]++;
                pos += used;
            }
        }
        if (n > in->max_frame_commands) in->max_frame_commands = n;
        in->command_count += n;
        frame++;
    }
    if (pos != records_end) {
        msg m = set_error(error, pos, "end", "tag", (int64_t)frame, -1, "the end record must be the last ");
        pg__text_u64(&m, PG_REPLAY_TRAILER_SIZE);
        pg__text_put(&m, " bytes of the file, but it starts at byte ");
        pg__text_u64(&m, pos);
        pg__text_put(&m, " of ");
        pg__text_u64(&m, size);
        pg__text_put(&m, pos < records_end ? " (trailing data or a corrupt record)" : " (truncated)");
        return PG_ERR_INVALID_ARGUMENT;
    }
    /* end record */
    if (data[pos] != PG_REPLAY_TAG_END)
        return value_error(error, pos, "end", "tag", (int64_t)frame, "expected the end record (tag 'E', 69), found byte ",
                           data[pos], "");
    n = get_u32(data + pos + 1);
    if (n != frame)
        return value_error(error, pos + 1, "end", "frame_count", (int64_t)frame, "end record counts ", n,
                           " frames, but a different number of frame records precede it");
    stored = get_u64(data + pos + 13);
    computed = hash_range(data, block_start, pos + 13);
    if (stored != computed)
        return hash_error(error, pos + 13, "end", "block_hash", (int64_t)frame,
                          "block hash mismatch (the records after the last checkpoint and the end record)", stored,
                          computed);
    stored = get_u64(data + pos + 21);
    computed = hash_range(data, 0, pos + 21);
    if (stored != computed)
        return hash_error(error, pos + 21, "file", "checksum", -1, "file checksum mismatch", stored, computed);
    in->end_offset = pos;
    in->frame_count = frame;
    in->checkpoint_count = checkpoints;
    in->final_hash = get_u64(data + pos + 5);
    in->checksum = stored;

    return PG_OK;
}

pg_result pg__replay_read(const uint8_t *data, size_t size, pg_replay_info *info, pg_replay_error *error,
                          pg__replay_work *w)
{
    pg_result r;
    clear_error(error);
    r = check_file(data, size, info, &w->info, error);
    if (r != PG_OK) return r;
    r = check_scene(&w->info, &w->def, error, w);
    if (r != PG_OK) return r;
    *info = w->info;
    /* sound, but stepped with other numerics than this build's: playing it here could
     * only diverge, so say which switch differs instead */
    return numeric_config_error(w->info.numeric_config, error);
}

pg_result pg_replay_read_in(const uint8_t *data, size_t size, pg_replay_info *info, pg_replay_error *error, void *work,
                            size_t work_size)
{
    pg__replay_work *w;
    clear_error(error);
    if (data == NULL && size != 0) return PG_ERR_NULL;
    if (info == NULL) return PG_ERR_NULL;
    w = pg__replay_work_in(work, work_size, error);
    if (w == NULL) return PG_ERR_INVALID_ARGUMENT;
    return pg__replay_read(data, size, info, error, w);
}

pg_result pg_replay_read(const uint8_t *data, size_t size, pg_replay_info *info, pg_replay_error *error)
{
    uint64_t work[PG_REPLAY_WORK_BYTES / 8u];
    return pg_replay_read_in(data, size, info, error, work, sizeof work);
}

/* Offset of checkpoint `index` in a valid file (scans the records). */
static size_t checkpoint_offset(const uint8_t *data, const pg_replay_info *info, uint32_t index)
{
    size_t pos = info->records_offset;
    uint32_t seen = 0;
    size_t cs = checkpoint_size(info->section_count);
    while (pos < info->end_offset) {
        if (data[pos] == PG_REPLAY_TAG_CHECKPOINT) {
            if (seen == index) return pos;
            seen++;
            pos += cs;
        } else {
            uint32_t n = get_u16(data + pos + 1), c;
            pos += 3u;
            for (c = 0; c < n; ++c) {
                pg_command cmd;
                size_t used = 0;
                if (pg_command_decode(data + pos, info->end_offset - pos, &cmd, &used, NULL, NULL) != PG_OK || used == 0)
                    return 0;
                pos += used;
            }
        }
    }
    return 0;
}

static void read_checkpoint(const uint8_t *data, const pg_replay_info *info, size_t off, uint64_t *hash,
                            uint64_t sections[PG_SECTION_COUNT])
{
    unsigned s;
    if (hash != NULL) *hash = get_u64(data + off + 5);
    if (sections != NULL) {
        for (s = 0; s < PG_SECTION_COUNT; ++s)
            sections[s] = s < info->section_count ? get_u64(data + off + 13 + (size_t)8u * s) : 0u;
    }
}

pg_result pg_replay_checkpoint(const uint8_t *data, const pg_replay_info *info, uint32_t index, uint64_t *hash,
                               uint64_t sections[PG_SECTION_COUNT])
{
    size_t off;
    if (data == NULL || info == NULL) return PG_ERR_NULL;
    if (index >= info->checkpoint_count) return PG_ERR_INVALID_ARGUMENT;
    off = checkpoint_offset(data, info, index);
    if (off == 0) return PG_ERR_INVALID_ARGUMENT;
    read_checkpoint(data, info, off, hash, sections);
    return PG_OK;
}

/* Compare the world with the checkpoint record at `off`. */
static int compare_at(const pg_world *world, const uint8_t *data, const pg_replay_info *info, size_t off,
                      uint64_t *expected, uint64_t *actual, uint32_t *mismatch)
{
    uint64_t want, have, want_s[PG_SECTION_COUNT], have_s[PG_SECTION_COUNT];
    uint32_t mask = 0;
    unsigned s;
    read_checkpoint(data, info, off, &want, want_s);
    have = pg_world_hash(world);
    pg_world_section_hashes(world, have_s);
    for (s = 0; s < PG_SECTION_COUNT && s < info->section_count; ++s) {
        if (want_s[s] != have_s[s]) mask |= 1u << s;
    }
    if (expected != NULL) *expected = want;
    if (actual != NULL) *actual = have;
    if (mismatch != NULL) *mismatch = mask;
    return want == have && mask == 0; /* everything the checkpoint stores */
}

int pg_replay_compare_checkpoint(const pg_world *world, const uint8_t *data, const pg_replay_info *info, uint32_t index,
                                 uint64_t *expected, uint64_t *actual, uint32_t *section_mismatch)
{
    size_t off;
    if (world == NULL || data == NULL || info == NULL || index >= info->checkpoint_count) return 0;
    off = checkpoint_offset(data, info, index);
    if (off == 0) return 0;
    return compare_at(world, data, info, off, expected, actual, section_mismatch);
}

/* ---- player ------------------------------------------------------------------------------ */
pg_result pg_replay_world_memory_size_in(const pg_replay_info *info, size_t *size, pg_replay_error *error, void *work,
                                         size_t work_size)
{
    pg__replay_work *w;
    pg_result r;
    if (info == NULL || size == NULL) return PG_ERR_NULL;
    w = pg__replay_work_in(work, work_size, error);
    if (w == NULL) return PG_ERR_INVALID_ARGUMENT;
    *size = 0;
    clear_error(error);
    r = check_scene(info, &w->def, error, w);
    if (r != PG_OK) return r;
    *size = pg_world_memory_size(&w->def);
    if (*size == 0) {
        set_error(error, info->scene_offset, "scene", "text", -1, -1, "the scene's world settings are invalid");
        return PG_ERR_INVALID_ARGUMENT;
    }
    return PG_OK;
}

pg_result pg_replay_world_memory_size(const pg_replay_info *info, size_t *size, pg_replay_error *error)
{
    uint64_t work[PG_REPLAY_WORK_BYTES / 8u];
    return pg_replay_world_memory_size_in(info, size, error, work, sizeof work);
}

/* *e for a scene whose world cannot be created (pg_world_create's result r). */
PG__OWN_FRAME pg_result world_error(const pg_replay_info *info, pg_result r, pg_replay_error *e)
{
    msg m = set_error(e, info->scene_offset, "scene", "text", -1, -1, "cannot create the scene's world: ");
    pg__text_put(&m, pg_result_name(r));
    return r == PG_ERR_MEMORY ? PG_ERR_MEMORY : PG_ERR_INVALID_ARGUMENT;
}

/* *first: the player's world against checkpoint 0, at p->cursor. */
PG__OWN_FRAME void compare_first(const pg_replay_player *p, pg_replay_frame_result *first)
{
    uint8_t *z = (uint8_t *)first;
    size_t i;
    for (i = 0; i < sizeof *first; ++i) z[i] = 0;
    first->checkpoint = 1;
    first->checkpoint_index = 0;
    first->match = compare_at(p->world, p->data, &p->info, p->cursor, &first->expected_hash, &first->actual_hash,
                              &first->section_mismatch);
}

pg_result pg_replay_player_begin_in(pg_replay_player *p, const uint8_t *data, const pg_replay_info *info, void *memory,
                                    size_t memory_size, pg_replay_frame_result *first, pg_replay_error *error, void *work,
                                    size_t work_size)
{
    pg__replay_work *w;
    pg_result r;
    if (p == NULL || data == NULL || info == NULL || memory == NULL) return PG_ERR_NULL;
    w = pg__replay_work_in(work, work_size, error);
    if (w == NULL) return PG_ERR_INVALID_ARGUMENT;
    clear_error(error);
    p->data = data;
    p->info = *info;
    p->world = NULL;
    p->cursor = info->records_offset;
    p->frame = 0;
    p->checkpoints_checked = 0;
    p->command_failures = 0;
    r = numeric_config_error(info->numeric_config, error);
    if (r != PG_OK) return r;
    r = check_scene(info, &w->def, error, w);
    if (r != PG_OK) return r;
    r = pg_world_create(&w->def, memory, memory_size, &p->world);
    if (r != PG_OK) {
        p->world = NULL;
        return world_error(info, r, error);
    }
    r = pg_scene_load_in(p->world, info->scene_text, info->scene_size, &w->scene_error, scene_work(w), pg_scene_work_size());
    if (r != PG_OK) {
        p->world = NULL;
        return scene_error(info, &w->scene_error, error, "scene does not load: ");
    }
    if (first != NULL) compare_first(p, first);
    p->cursor += checkpoint_size(info->section_count);
    p->checkpoints_checked = 1;
    return PG_OK;
}

pg_result pg_replay_player_begin(pg_replay_player *p, const uint8_t *data, const pg_replay_info *info, void *memory,
                                 size_t memory_size, pg_replay_frame_result *first, pg_replay_error *error)
{
    uint64_t work[PG_REPLAY_WORK_BYTES / 8u];
    return pg_replay_player_begin_in(p, data, info, memory, memory_size, first, error, work, sizeof work);
}

int pg_replay_player_done(const pg_replay_player *p)
{
    return p == NULL || p->world == NULL || p->frame >= p->info.frame_count;
}

/* Apply the commands of the frame record at `off` (already validated); returns the
 * offset after it. */
static size_t apply_frame_at(pg_world *world, const uint8_t *data, size_t end, size_t off, uint32_t *applied,
                             uint32_t *failures)
{
    uint32_t n = get_u16(data + off + 1), c, fails = 0;
    size_t pos = off + 3u;
    for (c = 0; c < n; ++c) {
        pg_command cmd;
        size_t used = 0;
        if (pg_command_decode(data + pos, end - pos, &cmd, &used, NULL, NULL) != PG_OK || used == 0) break;
        if (pg_command_apply(world, &cmd, NULL) != PG_OK) fails++;
        pos += used;
    }
    if (applied != NULL) *applied = c;
    if (failures != NULL) *failures = fails;
    return pos;
}

/* The record at pos (a frame or a checkpoint, by its tag, as the reader decides) in
 * [pos, end): the offset after it, or 0 when it is not one (0 is never a record's end:
 * records start after the header). */
static size_t record_after(const uint8_t *data, size_t pos, size_t end, size_t cs)
{
    uint32_t n, c;
    if (pos >= end) return 0;
    if (data[pos] == PG_REPLAY_TAG_CHECKPOINT) return end - pos >= cs ? pos + cs : 0;
    if (data[pos] != PG_REPLAY_TAG_FRAME || end - pos < 3u) return 0;
    n = get_u16(data + pos + 1);
    pos += 3u;
    for (c = 0; c < n; ++c) {
        pg_command cmd;
        size_t used = 0;
        if (pos >= end || pg_command_decode(data + pos, end - pos, &cmd, &used, NULL, NULL) != PG_OK || used == 0) return 0;
        pos += used;
    }
    return pos;
}

/* FNV-1a (pg_hash_bytes, the format's hash) runs backwards: h_before = (h_after *
 * prime^-1) ^ byte. */
#define FNV_PRIME UINT64_C(0x100000001b3)
#define FNV_PRIME_INVERSE UINT64_C(0xce965057aff6957b)
PG__STATIC_ASSERT(FNV_PRIME * FNV_PRIME_INVERSE == 1u, fnv_prime_inverse);

/* Is `off` where a frame record of the file (validated by pg_replay_read) starts? Only a
 * walk over the records from a known start can tell: an 'F' byte inside a command can
 * be followed by bytes that parse as records too. Walking from the first record costs
 * time in proportion to the offset, which a loop over the frames (re-simulation after
 * each step) pays quadratically, so the walk starts at the block of `off` instead:
 *   1. If off starts a record, the records from it reach the checkpoint (or the end
 *      record) that closes its block, whose block hash H covers [block start, x).
 *   2. Running the hash backwards from H over the bytes before x, the block start is
 *      where the state is the seed again (a chance of 2^-64 per byte of any other
 *      place being one: every such place is tried, the real start among them).
 *   3. From a start found at or before off, the records reach off exactly or pass it.
 * So off is accepted exactly when it is a record start (unless the file was made to
 * collide with its own hashes, and then only with records of that file). Cost: a block
 * for a real record; a backward hash to the first record for any other offset. */
static int frame_record_at(const uint8_t *data, const pg_replay_info *info, size_t off)
{
    size_t end = info->end_offset, cs = checkpoint_size(info->section_count), pos, x, y;
    uint64_t h;
    if (off < info->records_offset || off >= end || data[off] != PG_REPLAY_TAG_FRAME) return 0;
    /* 1. the record that closes the block */
    pos = off;
    do {
        pos = record_after(data, pos, end, cs);
        if (pos == 0) return 0;
    } while (pos < end && data[pos] != PG_REPLAY_TAG_CHECKPOINT);
    if (pos < end) {
        if (end - pos < cs) return 0;
        x = pos + cs - 8u; /* the checkpoint's block hash */
    } else {
        x = end + 13u; /* the end record's (info->size - end >= PG_REPLAY_TRAILER_SIZE) */
    }
    h = get_u64(data + x);
    /* 2. and 3. */
    for (y = x; y > info->records_offset;) {
        --y;
        h = (h * FNV_PRIME_INVERSE) ^ data[y];
        if (h == PG_HASH_SEED && y <= off) {
            size_t q = y;
            while (q != 0 && q < off) q = record_after(data, q, end, cs);
            if (q == off) return 1;
        }
    }
    return 0;
}

pg_result pg_replay_apply_frame(pg_world *world, const uint8_t *data, const pg_replay_info *info, size_t record_offset,
                                uint32_t *applied, uint32_t *failures)
{
    char buf[144];
    msg m;
    if (applied != NULL) *applied = 0;
    if (failures != NULL) *failures = 0;
    if (world == NULL) return PG_ERR_NULL;
    if (data == NULL) return pg__fail(world, PG_ERR_NULL, "pg_replay_apply_frame: data is NULL");
    if (info == NULL) return pg__fail(world, PG_ERR_NULL, "pg_replay_apply_frame: info is NULL");
    if (info->records_offset > info->end_offset || info->end_offset > info->size ||
        info->size - info->end_offset < PG_REPLAY_TRAILER_SIZE)
        return pg__fail(world, PG_ERR_INVALID_ARGUMENT, "pg_replay_apply_frame: info is not one pg_replay_read filled in");
    if (!frame_record_at(data, info, record_offset)) {
        m.buf = buf;
        m.cap = sizeof buf;
        m.len = 0;
        pg__text_put(&m, "pg_replay_apply_frame: record_offset ");
        pg__text_u64(&m, record_offset);
        pg__text_put(&m, " is not a frame record's start (see pg_replay_frame_result.record_offset)");
        return pg__fail(world, PG_ERR_INVALID_ARGUMENT, buf);
    }
    apply_frame_at(world, data, info->end_offset, record_offset, applied, failures);
    return PG_OK;
}

pg_result pg_replay_player_step(pg_replay_player *p, pg_replay_frame_result *out)
{
    pg_replay_frame_result fr;
    uint8_t *z = (uint8_t *)&fr;
    size_t i;
    pg_result r;
    if (p == NULL) return PG_ERR_NULL;
    if (pg_replay_player_done(p) || p->cursor >= p->info.end_offset || p->data[p->cursor] != PG_REPLAY_TAG_FRAME)
        return PG_ERR_INVALID_ARGUMENT;
    for (i = 0; i < sizeof fr; ++i) z[i] = 0;
    fr.frame = p->frame;
    fr.record_offset = p->cursor;
    fr.match = 1;
    p->cursor = apply_frame_at(p->world, p->data, p->info.end_offset, p->cursor, &fr.command_count, &fr.command_failures);
    p->command_failures += fr.command_failures;
    r = pg_world_step(p->world);
    p->frame++;
    if (p->frame % p->info.checkpoint_interval == 0u && p->cursor < p->info.end_offset &&
        p->data[p->cursor] == PG_REPLAY_TAG_CHECKPOINT) {
        fr.checkpoint = 1;
        fr.checkpoint_index = p->checkpoints_checked;
        fr.match = compare_at(p->world, p->data, &p->info, p->cursor, &fr.expected_hash, &fr.actual_hash,
                              &fr.section_mismatch);
        p->cursor += checkpoint_size(p->info.section_count);
        p->checkpoints_checked++;
    }
    if (out != NULL) *out = fr;
    return r;
}
