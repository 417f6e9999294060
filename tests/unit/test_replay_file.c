/* test_replay_file.c — replay files (replay_file.h): writer, validating reader, player,
 * and the snapshot round trip the player and synctest rely on. */
#include <stdlib.h>

#include "pg_test.h"
#include "pogon/replay_file.h"
#include "pogon/scene_file.h"

static const char scene_text[] =
    "pogon-scene 1\n"
    "max_bodies 64\n"
    "max_shapes 128\n"
    "max_contacts 512\n"
    "wall 40 2 position 0 -1\n"
    "box 1 1 position 0 0.5\n"
    "box 1 1 position 0.2 1.5\n"
    "ball 0.5 position -3 4 restitution 0.5\n"
    "capsule 1 0.3 position 3 3 angle 30\n"
    "star 0.6 position 5 5\n"
    "wall 2 40 position -21 19\n" /* a closed box: nothing leaves the envelope */
    "wall 2 40 position 21 19\n"
    "wall 44 2 position 0 39\n";

typedef struct world_box {
    void *memory;
    pg_world *world;
} world_box;

static world_box make_world(void)
{
    world_box b;
    pg_world_def def;
    size_t need;
    assert_int_equal(pg_scene_read_def(scene_text, sizeof scene_text - 1, &def, NULL), PG_OK);
    need = pg_world_memory_size(&def);
    assert_true(need > 0);
    b.memory = malloc(need);
    assert_non_null(b.memory);
    assert_int_equal(pg_world_create(&def, b.memory, need, &b.world), PG_OK);
    assert_int_equal(pg_scene_load(b.world, scene_text, sizeof scene_text - 1, NULL), PG_OK);
    return b;
}

/* The commands of frame f of the test run (deterministic, a few kinds). */
static uint32_t frame_commands(uint32_t f, pg_command *out)
{
    uint32_t n = 0;
    pg_body_id box = {1, 1}, ball = {3, 1};
    if (f % 17 == 3) {
        out[n] = pg_command_init(PG_CMD_APPLY_LINEAR_IMPULSE);
        out[n].body = ball;
        out[n].vec = pg_v2((f / 17) % 2 ? PG_FIX_C(-1) : PG_FIX_C(1), PG_FIX_C(1)); /* stays in the envelope */
        out[n].point = pg_v2(PG_FIX_C(-3), PG_FIX_C(4));
        n++;
    }
    if (f % 29 == 7) {
        out[n] = pg_command_init(PG_CMD_SET_ANGULAR_VELOCITY);
        out[n].body = box;
        out[n].scalar = PG_FIX_C(1);
        n++;
    }
    if (f == 40) {
        out[n] = pg_command_init(PG_CMD_MAKE);
        out[n].make_kind = PG_MAKE_BOX;
        out[n].body_def = pg_default_body_def();
        out[n].body_def.type = PG_BODY_DYNAMIC;
        out[n].body_def.position = pg_v2(0, PG_FIX_C(8));
        out[n].shape_def = pg_default_shape_def();
        out[n].size0 = PG_FIX_C(1);
        out[n].size1 = PG_FIX_C(1);
        n++;
    }
    if (f == 60) {
        out[n] = pg_command_init(PG_CMD_SET_EFFECTS);
        out[n].value = PG_EFFECTS_ALL & ~PG_EFFECT_FRICTION;
        n++;
    }
    return n;
}

/* Record `frames` frames with checkpoints every `interval` into a malloc'd buffer,
 * growing it from `initial` bytes when the writer asks. */
static uint8_t *record(uint32_t frames, uint32_t interval, size_t initial, size_t *size, uint64_t *final_hash)
{
    world_box b = make_world();
    pg_replay_writer w;
    size_t cap = initial;
    uint8_t *buf = malloc(cap);
    pg_command cmds[8];
    uint32_t f;
    pg_result r;
    assert_non_null(buf);
#define GROW(call)                                                      \
    while ((r = (call)) == PG_ERR_MEMORY) {                             \
        cap *= 2;                                                       \
        buf = realloc(buf, cap);                                        \
        assert_non_null(buf);                                           \
        assert_int_equal(pg_replay_writer_set_buffer(&w, buf, cap), PG_OK); \
    }                                                                   \
    assert_int_equal(r, PG_OK)
    while ((r = pg_replay_writer_begin(&w, buf, cap, scene_text, sizeof scene_text - 1, interval)) == PG_ERR_MEMORY) {
        cap *= 2;
        buf = realloc(buf, cap);
    }
    assert_int_equal(r, PG_OK);
    assert_true(pg_replay_writer_checkpoint_due(&w));
    assert_int_equal(pg_replay_writer_add_frame(&w, NULL, 0), PG_ERR_INVALID_ARGUMENT); /* checkpoint 0 first */
    GROW(pg_replay_writer_add_checkpoint_world(&w, b.world));
    for (f = 0; f < frames; ++f) {
        uint32_t n = frame_commands(f, cmds), i;
        GROW(pg_replay_writer_add_frame(&w, cmds, n));
        for (i = 0; i < n; ++i) pg_command_apply(b.world, &cmds[i], NULL);
        pg_world_step(b.world);
        if (pg_replay_writer_checkpoint_due(&w)) {
            assert_int_equal(pg_replay_writer_finish(&w, 0, NULL), PG_ERR_INVALID_ARGUMENT);
            GROW(pg_replay_writer_add_checkpoint_world(&w, b.world));
        }
    }
    assert_int_equal(pg_replay_writer_add_checkpoint_world(&w, b.world), PG_ERR_INVALID_ARGUMENT); /* not due */
    *final_hash = pg_world_hash(b.world);
    GROW(pg_replay_writer_finish(&w, *final_hash, size));
#undef GROW
    free(b.memory);
    return buf;
}

static void test_write_read_play(void **state)
{
    size_t size, size2, mem;
    uint64_t final_hash, h2;
    uint8_t *file = record(125, 10, 1 << 16, &size, &final_hash);
    uint8_t *file2 = record(125, 10, 64, &size2, &h2); /* grown many times: same bytes */
    pg_replay_info info;
    pg_replay_error err;
    pg_replay_player p;
    pg_replay_frame_result fr;
    void *memory;
    uint32_t checked = 1;
    (void)state;
    assert_int_equal(size, size2);
    assert_memory_equal(file, file2, size);
    assert_int_equal(pg_replay_read(file, size, &info, &err), PG_OK);
    assert_int_equal(info.format_version, PG_REPLAY_FORMAT_VERSION);
    assert_int_equal(info.engine_major, POGON_VERSION_MAJOR);
    assert_int_equal(info.numeric_config, pg_numeric_config());
    assert_int_equal(info.numeric_config & PG_NUMCFG_TRIG_BITS_MASK, PG_TRIG_TABLE_BITS);
    assert_int_equal(info.checkpoint_interval, 10);
    assert_int_equal(info.section_count, PG_SECTION_COUNT);
    assert_int_equal(info.frame_count, 125);
    assert_int_equal(info.checkpoint_count, 13);
    assert_int_equal(info.scene_size, sizeof scene_text - 1);
    assert_memory_equal(info.scene_text, scene_text, info.scene_size);
    assert_int_equal(info.kind_counts[PG_CMD_MAKE], 1);
    assert_int_equal(info.kind_counts[PG_CMD_SET_EFFECTS], 1);
    assert_int_equal(info.kind_counts[PG_CMD_APPLY_LINEAR_IMPULSE], 8);
    assert_true(info.final_hash == final_hash);

    assert_int_equal(pg_replay_world_memory_size(&info, &mem, &err), PG_OK);
    memory = malloc(mem);
    assert_int_equal(pg_replay_player_begin(&p, file, &info, memory, mem, &fr, &err), PG_OK);
    assert_true(fr.match);
    while (!pg_replay_player_done(&p)) {
        assert_int_equal(pg_replay_player_step(&p, &fr), PG_OK);
        if (fr.checkpoint) {
            assert_true(fr.match);
            assert_int_equal(fr.section_mismatch, 0);
            checked++;
        }
    }
    assert_int_equal(checked, 13);
    assert_true(pg_world_hash(p.world) == final_hash);
    assert_int_equal(pg_replay_player_step(&p, &fr), PG_ERR_INVALID_ARGUMENT);
    free(memory);
    free(file);
    free(file2);
}

/* pg_replay_compare_checkpoint compares everything a checkpoint stores: the world at
 * checkpoint 2's frame matches it and no other; one more step differs in the bodies
 * section (and more); out-of-range indices and NULLs give 0. */
static void test_compare_checkpoint(void **state)
{
    size_t size, mem;
    uint64_t final_hash, want = 0, have = 0;
    uint8_t *file = record(40, 10, 1 << 16, &size, &final_hash);
    pg_replay_info info;
    pg_replay_error err;
    pg_replay_player p;
    pg_replay_frame_result fr;
    void *memory;
    uint32_t mask = 0, k;
    (void)state;
    assert_int_equal(pg_replay_read(file, size, &info, &err), PG_OK);
    assert_int_equal(pg_replay_world_memory_size(&info, &mem, &err), PG_OK);
    memory = malloc(mem);
    assert_int_equal(pg_replay_player_begin(&p, file, &info, memory, mem, &fr, &err), PG_OK);
    assert_int_equal(pg_replay_compare_checkpoint(p.world, file, &info, 0, &want, &have, &mask), 1);
    assert_true(want == have);
    assert_int_equal(mask, 0);
    while (p.frame < 20) assert_int_equal(pg_replay_player_step(&p, &fr), PG_OK);
    for (k = 0; k < info.checkpoint_count; ++k) {
        int m = pg_replay_compare_checkpoint(p.world, file, &info, k, &want, &have, &mask);
        PG_EXPECT_EQ(m, k == 2, "checkpoint %u against the world at frame 20", (unsigned)k);
        if (k != 2) assert_true(want != have && mask != 0);
    }
    assert_int_equal(pg_replay_player_step(&p, &fr), PG_OK);
    assert_int_equal(pg_replay_compare_checkpoint(p.world, file, &info, 2, &want, &have, &mask), 0);
    assert_true((mask & (1u << PG_SECTION_BODIES)) != 0);
    assert_true(have == pg_world_hash(p.world));
    assert_int_equal(pg_replay_compare_checkpoint(p.world, file, &info, info.checkpoint_count, NULL, NULL, NULL), 0);
    assert_int_equal(pg_replay_compare_checkpoint(NULL, file, &info, 0, NULL, NULL, NULL), 0);
    assert_int_equal(pg_replay_compare_checkpoint(p.world, NULL, &info, 0, NULL, NULL, NULL), 0);
    free(memory);
    free(file);
}

/* pg_replay_checkpoint reads back what the writer stored: at checkpoint k (frame 10 k)
 * the world's hash and section hashes as the player sees them at that frame; an index
 * past the last and NULLs are refused. */
static void test_checkpoint_read(void **state)
{
    size_t size, mem;
    uint64_t final_hash, hash = 0, sections[PG_SECTION_COUNT], expected[PG_SECTION_COUNT];
    uint8_t *file = record(40, 10, 1 << 16, &size, &final_hash);
    pg_replay_info info;
    pg_replay_error err;
    pg_replay_player p;
    pg_replay_frame_result fr;
    void *memory;
    uint32_t k;
    int s;
    (void)state;
    assert_int_equal(pg_replay_read(file, size, &info, &err), PG_OK);
    assert_int_equal(pg_replay_world_memory_size(&info, &mem, &err), PG_OK);
    memory = malloc(mem);
    assert_int_equal(pg_replay_player_begin(&p, file, &info, memory, mem, &fr, &err), PG_OK);
    assert_true(info.checkpoint_count >= 4);
    for (k = 0; k < info.checkpoint_count; ++k) {
        while (p.frame < 10u * k) assert_int_equal(pg_replay_player_step(&p, &fr), PG_OK);
        assert_int_equal(pg_replay_checkpoint(file, &info, k, &hash, sections), PG_OK);
        PG_EXPECT_EQ(hash == pg_world_hash(p.world), 1, "checkpoint %u: the world's hash at frame %u", (unsigned)k, (unsigned)(10u * k));
        pg_world_section_hashes(p.world, expected);
        for (s = 0; s < PG_SECTION_COUNT; ++s) PG_EXPECT_EQ(sections[s] == expected[s], 1, "checkpoint %u section %d", (unsigned)k, s);
    }
    assert_int_equal(pg_replay_checkpoint(file, &info, info.checkpoint_count, &hash, sections), PG_ERR_INVALID_ARGUMENT);
    assert_int_equal(pg_replay_checkpoint(NULL, &info, 0, &hash, sections), PG_ERR_NULL);
    assert_int_equal(pg_replay_checkpoint(file, NULL, 0, &hash, sections), PG_ERR_NULL);
    free(memory);
    free(file);
}

/* Every single-bit flip is detected, and the reported offset lies in the flipped region. */
static void test_every_bit_flip(void **state)
{
    size_t size, i;
    uint64_t h;
    uint8_t *file = record(30, 10, 1 << 16, &size, &h);
    pg_replay_info info;
    pg_replay_error err;
    (void)state;
    assert_int_equal(pg_replay_read(file, size, &info, &err), PG_OK);
    for (i = 0; i < size; ++i) {
        int bit;
        for (bit = 0; bit < 8; ++bit) {
            pg_replay_info bad;
            size_t lo, hi;
            file[i] ^= (uint8_t)(1u << bit);
            if (pg_replay_read(file, size, &bad, &err) == PG_OK) {
                print_error("flip of bit %d of byte %zu not detected\n", bit, i);
                fail();
            }
            if (i < PG_REPLAY_HEADER_SIZE) lo = 0, hi = PG_REPLAY_HEADER_SIZE;
            else if (i < info.records_offset) lo = info.scene_offset, hi = info.records_offset;
            else if (i < size - 8) lo = info.records_offset, hi = size - 8;
            else lo = size - 8, hi = size;
            if (err.offset < lo || err.offset >= hi) {
                print_error("flip of bit %d of byte %zu reported at offset %zu (%s.%s: %s), outside [%zu, %zu)\n", bit,
                            i, err.offset, err.region, err.field, err.message, lo, hi);
                fail();
            }
            file[i] ^= (uint8_t)(1u << bit);
        }
    }
    free(file);
}

/* Every truncation fails, never reading past the given length (ASan would see it:
 * each prefix is copied into an exactly sized allocation). */
static void test_truncation(void **state)
{
    size_t size, n;
    uint64_t h;
    uint8_t *file = record(30, 10, 1 << 16, &size, &h);
    pg_replay_info info;
    pg_replay_error err;
    (void)state;
    for (n = 0; n < size; ++n) {
        uint8_t *prefix = malloc(n ? n : 1);
        memcpy(prefix, file, n);
        assert_int_equal(pg_replay_read(n ? prefix : NULL, n, &info, &err), n ? PG_ERR_INVALID_ARGUMENT : PG_ERR_INVALID_ARGUMENT);
        assert_true(err.offset <= n);
        free(prefix);
    }
    assert_int_equal(pg_replay_read(NULL, 5, &info, &err), PG_ERR_NULL);
    free(file);
}

/* A command changed (hashes fixed) replays to a mismatch at the next checkpoint. */
static void test_changed_command_diverges(void **state)
{
    size_t size, mem;
    uint64_t h;
    uint8_t *file = record(60, 1, 1 << 16, &size, &h);
    pg_replay_info info;
    pg_replay_error err;
    pg_replay_player p;
    pg_replay_frame_result fr;
    void *memory;
    size_t pos, block = 0, cs;
    uint32_t frame = 0, target = 0;
    int changed = 0;
    (void)state;
    assert_int_equal(pg_replay_read(file, size, &info, &err), PG_OK);
    cs = 21u + 8u * info.section_count;
    /* with N = 1 the records are C F C F ... : change the first command, frame 3's impulse */
    pos = info.records_offset;
    while (pos < info.end_offset && !changed) {
        if (file[pos] == PG_REPLAY_TAG_CHECKPOINT) {
            pos += cs;
            block = pos;
            continue;
        }
        if (file[pos + 1] != 0) {
            pg_command c;
            size_t used;
            uint8_t enc[PG_COMMAND_ENCODED_MAX];
            assert_int_equal(pg_command_decode(file + pos + 3, info.end_offset - pos - 3, &c, &used, NULL, NULL), PG_OK);
            c.vec.x += 1;
            assert_int_equal(pg_command_encode(&c, enc, sizeof enc), used);
            memcpy(file + pos + 3, enc, used);
            pos += 3 + used;
            assert_int_equal(file[pos], PG_REPLAY_TAG_CHECKPOINT);
            {
                uint64_t bh = pg_hash_bytes(PG_HASH_SEED, file + block, pos + cs - 8 - block), ck;
                int k;
                for (k = 0; k < 8; ++k) file[pos + cs - 8 + (size_t)k] = (uint8_t)(bh >> (8 * k));
                ck = pg_hash_bytes(PG_HASH_SEED, file, size - 8);
                for (k = 0; k < 8; ++k) file[size - 8 + (size_t)k] = (uint8_t)(ck >> (8 * k));
            }
            target = frame;
            changed = 1;
            break;
        }
        pos += 3;
        frame++;
    }
    assert_true(changed);
    assert_int_equal(target, 3);
    assert_int_equal(pg_replay_read(file, size, &info, &err), PG_OK);
    assert_int_equal(pg_replay_world_memory_size(&info, &mem, &err), PG_OK);
    memory = malloc(mem);
    assert_int_equal(pg_replay_player_begin(&p, file, &info, memory, mem, &fr, &err), PG_OK);
    assert_true(fr.match);
    for (;;) {
        assert_int_equal(pg_replay_player_step(&p, &fr), PG_OK);
        assert_true(fr.checkpoint);
        if (!fr.match) break;
    }
    assert_int_equal(fr.frame, target);
    assert_true(fr.section_mismatch & (1u << PG_SECTION_BODIES));
    free(memory);
    free(file);
}

/* ---- numeric configuration and format versions ---------------------------------------- */
static void put_le(uint8_t *p, uint64_t v, int bytes)
{
    int k;
    for (k = 0; k < bytes; ++k) p[k] = (uint8_t)(v >> (8 * k));
}

/* Seal a header edited by a test: its hash (over the bytes before it) and the file checksum. */
static void reseal(uint8_t *file, size_t size, size_t header_hash_at)
{
    put_le(file + header_hash_at, pg_hash_bytes(PG_HASH_SEED, file, header_hash_at), 8);
    put_le(file + size - 8, pg_hash_bytes(PG_HASH_SEED, file, size - 8), 8);
}

/* Another sine table (the other end of 8..12 from this build's) in a sound file: the
 * reader fills *info but refuses it as incompatible, naming both tables; the player
 * refuses it too. */
static void test_other_numeric_config_is_refused(void **state)
{
    size_t size, mem, n;
    uint64_t h;
    uint8_t *file = record(30, 10, 1 << 16, &size, &h);
    uint32_t other = PG_TRIG_TABLE_BITS == 12 ? 8u : 12u;
    pg_replay_info info;
    pg_replay_error err;
    pg_replay_player p;
    char want[200], mine[64], theirs[64];
    void *memory;
    (void)state;
    put_le(file + 20, other, 4);
    reseal(file, size, 36);
    assert_int_equal(pg_replay_read(file, size, &info, &err), PG_ERR_INCOMPATIBLE);
    assert_string_equal(err.region, "header");
    assert_string_equal(err.field, "numeric_config");
    assert_int_equal(err.offset, 20);
    n = pg_numeric_config_describe(other, theirs, sizeof theirs);
    assert_int_equal(n, strlen(theirs));
    assert_int_equal(pg_numeric_config_describe(other, theirs, 4), n); /* cut, but the whole length */
    assert_int_equal(strlen(theirs), 3);
    pg_numeric_config_describe(other, theirs, sizeof theirs);
    pg_numeric_config_describe(pg_numeric_config(), mine, sizeof mine);
    assert_string_equal(theirs, other == 8u ? "an 8-bit sine table" : "a 12-bit sine table");
    snprintf(want, sizeof want, "recorded with %s; this build has %s", theirs, mine);
    if (strstr(err.message, want) == NULL) fail_msg("message '%s' lacks '%s'", err.message, want);
    /* the file is sound: what it holds is reported */
    assert_int_equal(info.numeric_config, other);
    assert_int_equal(info.frame_count, 30);
    assert_int_equal(info.final_hash, h);
    assert_int_equal(pg_replay_world_memory_size(&info, &mem, &err), PG_OK);
    memory = malloc(mem);
    assert_int_equal(pg_replay_player_begin(&p, file, &info, memory, mem, NULL, &err), PG_ERR_INCOMPATIBLE);
    assert_string_equal(err.field, "numeric_config");
    free(memory);
    free(file);
}

/* A format 1 file (the format 2 file without numeric_config) is refused with the way to
 * upgrade it; pg_replay_upgrade gives back the format 2 file byte for byte; a damaged
 * format 1 file is not upgraded; a newer version is refused as such. */
static void test_format_1_upgrades(void **state)
{
    size_t size, v1_size, need = 0, i;
    uint64_t h;
    uint8_t *file = record(30, 10, 1 << 16, &size, &h);
    uint8_t *v1, *out;
    pg_replay_info info;
    pg_replay_error err;
    (void)state;
    v1_size = size - 4;
    v1 = malloc(v1_size);
    memcpy(v1, file, 20);
    memcpy(v1 + 20, file + 24, size - 24);
    put_le(v1 + 8, 1, 2);
    reseal(v1, v1_size, 32);
    assert_int_equal(pg_replay_read(v1, v1_size, &info, &err), PG_ERR_INCOMPATIBLE);
    assert_int_equal(info.format_version, 1);
    assert_string_equal(err.field, "format_version");
    if (strstr(err.message, "pogon-replay upgrade IN OUT") == NULL) fail_msg("message: %s", err.message);

    out = malloc(size);
    assert_int_equal(pg_replay_upgrade(v1, v1_size, pg_numeric_config(), out, size - 1, &need, &err), PG_ERR_MEMORY);
    assert_int_equal(need, size);
    assert_int_equal(pg_replay_upgrade(v1, v1_size, pg_numeric_config(), out, size, &need, &err), PG_OK);
    assert_int_equal(need, size);
    assert_memory_equal(out, file, size);
    /* the current format is copied as it is */
    memset(out, 0, size);
    assert_int_equal(pg_replay_upgrade(file, size, pg_numeric_config(), out, size, &need, &err), PG_OK);
    assert_memory_equal(out, file, size);

    /* any damaged byte of the old file is refused, never sealed into a new one */
    for (i = 0; i < v1_size; i += 7) {
        if (i == 8 || i == 9) continue; /* the version itself: refused as another version */
        v1[i] ^= 0x10;
        if (pg_replay_upgrade(v1, v1_size, pg_numeric_config(), out, size, &need, &err) == PG_OK)
            fail_msg("damage at byte %zu was upgraded", i);
        assert_true(err.offset < v1_size);
        v1[i] ^= 0x10;
    }
    /* a newer format is not for this build */
    put_le(v1 + 8, PG_REPLAY_FORMAT_VERSION + 1, 2);
    reseal(v1, v1_size, 32);
    assert_int_equal(pg_replay_read(v1, v1_size, &info, &err), PG_ERR_INCOMPATIBLE);
    if (strstr(err.message, "is newer than this build's") == NULL) fail_msg("message: %s", err.message);
    assert_int_equal(pg_replay_upgrade(v1, v1_size, pg_numeric_config(), out, size, &need, &err), PG_ERR_INCOMPATIBLE);
    free(out);
    free(v1);
    free(file);
}

/* A format 3 file (before chain segments in add_shape; every record reads the same in
 * format 4) is refused with the way to upgrade it; pg_replay_upgrade gives back the
 * current file byte for byte, and refuses a damaged one. */
static void test_format_3_upgrades(void **state)
{
    size_t size, need = 0, i;
    uint64_t h;
    uint8_t *file = record(30, 10, 1 << 16, &size, &h);
    uint8_t *v3 = malloc(size), *out = malloc(size);
    pg_replay_info info;
    pg_replay_error err;
    (void)state;
    assert_int_equal(PG_REPLAY_FORMAT_VERSION, 4);
    memcpy(v3, file, size);
    put_le(v3 + 8, 3, 2);
    reseal(v3, size, 36);
    assert_int_equal(pg_replay_read(v3, size, &info, &err), PG_ERR_INCOMPATIBLE);
    assert_int_equal(info.format_version, 3);
    assert_string_equal(err.field, "format_version");
    if (strstr(err.message, "pogon-replay upgrade IN OUT") == NULL) fail_msg("message: %s", err.message);
    assert_int_equal(pg_replay_upgrade(v3, size, pg_numeric_config(), out, size, &need, &err), PG_OK);
    assert_int_equal(need, size);
    assert_memory_equal(out, file, size);
    for (i = 0; i < size; i += 5) {
        if (i == 8 || i == 9) continue; /* the version itself: refused as another version */
        v3[i] ^= 0x04;
        if (pg_replay_upgrade(v3, size, pg_numeric_config(), out, size, &need, &err) == PG_OK)
            fail_msg("damage at byte %zu was upgraded", i);
        v3[i] ^= 0x04;
    }
    free(out);
    free(v3);
    free(file);
}

/* Snapshot/restore round trip: world A steps 10000 frames untouched; world B is saved
 * every 100 frames and the snapshot restored into world C, which carries on (and the
 * other way round next time). The hashes agree every frame, the snapshots bit for bit. */
static void test_snapshot_round_trip_10000(void **state)
{
    world_box a = make_world(), b = make_world(), c = make_world();
    pg_world *cur = b.world, *other = c.world;
    pg_command cmds[8];
    uint8_t *snap_a = NULL, *snap_cur = NULL;
    size_t cap = 0;
    uint32_t f;
    (void)state;
    for (f = 0; f < 10000; ++f) {
        uint32_t n = frame_commands(f % 400 + (f >= 400 ? 100 : 0), cmds), i; /* MAKE and SET_EFFECTS once */
        for (i = 0; i < n; ++i) {
            pg_command_apply(a.world, &cmds[i], NULL);
            pg_command_apply(cur, &cmds[i], NULL);
        }
        pg_world_step(a.world);
        pg_world_step(cur);
        if (pg_world_hash(a.world) != pg_world_hash(cur)) {
            print_error("hash differs after frame %u\n", f);
            fail();
        }
        if (f % 100 == 99) {
            size_t need = pg_world_snapshot_size(cur), wa, wc;
            pg_world *t;
            if (pg_world_snapshot_size(a.world) > need) need = pg_world_snapshot_size(a.world);
            if (need > cap) {
                cap = need;
                snap_a = realloc(snap_a, cap);
                snap_cur = realloc(snap_cur, cap);
            }
            assert_int_equal(pg_world_snapshot_save(a.world, snap_a, cap, &wa), PG_OK);
            assert_int_equal(pg_world_snapshot_save(cur, snap_cur, cap, &wc), PG_OK);
            assert_int_equal(wa, wc);
            assert_memory_equal(snap_a, snap_cur, wa);
            assert_int_equal(pg_world_snapshot_restore(other, snap_cur, wc), PG_OK);
            assert_true(pg_world_hash(other) == pg_world_hash(cur));
            t = cur, cur = other, other = t;
        }
    }
    assert_true(pg_world_frame(a.world) == 10000);
    free(snap_a);
    free(snap_cur);
    free(a.memory);
    free(b.memory);
    free(c.memory);
}

static void test_writer_rejects(void **state)
{
    uint8_t buf[4096];
    pg_replay_writer w;
    uint64_t sections[PG_SECTION_COUNT] = {0};
    pg_command bad;
    (void)state;
    assert_int_equal(pg_replay_writer_begin(&w, buf, sizeof buf, scene_text, sizeof scene_text - 1, 0),
                     PG_ERR_INVALID_ARGUMENT);
    assert_int_equal(pg_replay_writer_begin(&w, buf, 50, scene_text, sizeof scene_text - 1, 5), PG_ERR_MEMORY);
    assert_int_equal(pg_replay_writer_begin(&w, buf, sizeof buf, scene_text, sizeof scene_text - 1, 5), PG_OK);
    /* a state hash that is not the hash of the section hashes is refused */
    assert_int_equal(pg_replay_writer_add_checkpoint(&w, 1, sections), PG_ERR_INVALID_ARGUMENT);
    {
        uint8_t zeros[8 * PG_SECTION_COUNT] = {0};
        uint64_t h = pg_hash_bytes(PG_HASH_SEED, zeros, sizeof zeros);
        assert_int_equal(pg_replay_writer_add_checkpoint(&w, h, sections), PG_OK);
        assert_int_equal(pg_replay_writer_add_checkpoint(&w, h, sections), PG_ERR_INVALID_ARGUMENT); /* not due */
    }
    bad = pg_command_init(PG_CMD_NONE);
    {
        size_t before = w.size;
        assert_int_equal(pg_replay_writer_add_frame(&w, &bad, 1), PG_ERR_INVALID_ARGUMENT);
        assert_int_equal(w.size, before);
    }
    assert_int_equal(pg_replay_writer_add_frame(&w, NULL, 0), PG_OK);
    assert_int_equal(pg_replay_writer_finish(&w, 7, NULL), PG_OK);
    assert_int_equal(pg_replay_writer_add_frame(&w, NULL, 0), PG_ERR_INVALID_ARGUMENT);
    {
        pg_replay_info info;
        pg_replay_error err;
        assert_int_equal(pg_replay_read(buf, w.size, &info, &err), PG_OK);
        assert_int_equal(info.frame_count, 1);
        assert_true(info.final_hash == 7);
    }
}

/* pg_replay_apply_frame accepts exactly the offsets of the file's frame records: every
 * other offset (past the end, wrapping, a checkpoint, a byte inside a command, even one
 * that reads 'F') is PG_ERR_INVALID_ARGUMENT with a message and changes nothing.
 * Before: (size_t)-2 wrapped record_offset + 3 (UBSan in replay_file.c) and an 'F' byte
 * inside a command was applied as a frame. */
static void test_apply_frame_offsets(void **state)
{
    world_box b = make_world(), fresh = make_world();
    pg_replay_writer w;
    static uint8_t buf[1 << 14];
    pg_command cmds[2];
    pg_replay_info info;
    pg_replay_error err;
    size_t size, off, starts[8], inside_f = 0;
    uint32_t nstarts = 0, f, applied, failures;
    uint64_t h;
    void *memory;
    size_t mem;
    pg_replay_player p;
    pg_replay_frame_result fr;
    pg_body_id ball = {3, 1};
    (void)state;
    assert_int_equal(pg_replay_writer_begin(&w, buf, sizeof buf, scene_text, sizeof scene_text - 1, 2), PG_OK);
    assert_int_equal(pg_replay_writer_add_checkpoint_world(&w, b.world), PG_OK);
    for (f = 0; f < 5; ++f) {
        uint32_t n = 0, i;
        if (f == 1 || f == 2) {
            cmds[n] = pg_command_init(PG_CMD_SET_USER_DATA); /* user data "F\0\0...": a frame tag with 0 commands */
            cmds[n].body = ball;
            cmds[n].user_data = (uint64_t)PG_REPLAY_TAG_FRAME;
            n++;
            cmds[n] = pg_command_init(PG_CMD_SET_ANGULAR_VELOCITY);
            cmds[n].body = ball;
            cmds[n].scalar = PG_FIX_C(2);
            n++;
        }
        assert_int_equal(pg_replay_writer_add_frame(&w, cmds, n), PG_OK);
        for (i = 0; i < n; ++i) assert_int_equal(pg_command_apply(b.world, &cmds[i], NULL), PG_OK);
        assert_int_equal(pg_world_step(b.world), PG_OK);
        if (pg_replay_writer_checkpoint_due(&w)) assert_int_equal(pg_replay_writer_add_checkpoint_world(&w, b.world), PG_OK);
    }
    assert_int_equal(pg_replay_writer_finish(&w, pg_world_hash(b.world), &size), PG_OK);
    assert_int_equal(pg_replay_read(buf, size, &info, &err), PG_OK);
    /* the real frame records, from the player */
    assert_int_equal(pg_replay_world_memory_size(&info, &mem, &err), PG_OK);
    memory = malloc(mem);
    assert_int_equal(pg_replay_player_begin(&p, buf, &info, memory, mem, &fr, &err), PG_OK);
    while (!pg_replay_player_done(&p)) {
        assert_int_equal(pg_replay_player_step(&p, &fr), PG_OK);
        starts[nstarts++] = fr.record_offset;
    }
    assert_int_equal(nstarts, 5);
    /* each applies its commands */
    for (f = 0; f < nstarts; ++f) {
        assert_int_equal(pg_replay_apply_frame(fresh.world, buf, &info, starts[f], &applied, &failures), PG_OK);
        PG_EXPECT_EQ(applied, f == 1 || f == 2 ? 2 : 0, "frame %u", f);
        PG_EXPECT_EQ(failures, 0, "frame %u", f);
    }
    h = pg_world_hash(fresh.world);
    /* 'F' bytes that are not record starts (the user data) */
    for (off = info.records_offset; off < info.end_offset; ++off) {
        int real = 0;
        for (f = 0; f < nstarts; ++f) real |= off == starts[f];
        if (real || buf[off] != PG_REPLAY_TAG_FRAME) continue;
        inside_f++;
        if (pg_replay_apply_frame(fresh.world, buf, &info, off, NULL, NULL) != PG_ERR_INVALID_ARGUMENT)
            fail_msg("offset %zu (an 'F' inside a command) accepted as a frame record", off);
    }
    assert_true(inside_f >= 2);
    /* offsets that wrap (record_offset + 3 overflowed before) */
    for (off = 1; off <= 8; ++off) {
        applied = 99;
        assert_int_equal(pg_replay_apply_frame(fresh.world, buf, &info, (size_t)0 - off, &applied, NULL), PG_ERR_INVALID_ARGUMENT);
        assert_int_equal(applied, 0);
    }
    /* every other offset in and just past the file is refused */
    for (off = 0; off <= size + 4; ++off) {
        int real = 0;
        for (f = 0; f < nstarts; ++f) real |= off == starts[f];
        if (real) continue;
        applied = failures = 99;
        if (pg_replay_apply_frame(fresh.world, buf, &info, off, &applied, &failures) != PG_ERR_INVALID_ARGUMENT)
            fail_msg("offset %zu (byte %d) accepted as a frame record", off, off < size ? buf[off] : -1);
        PG_EXPECT_EQ(applied, 0, "offset %zu", off);
        PG_EXPECT_EQ(failures, 0, "offset %zu", off);
        if (strstr(pg_world_last_error(fresh.world), "pg_replay_apply_frame") == NULL)
            fail_msg("offset %zu: last error \"%s\"", off, pg_world_last_error(fresh.world));
    }
    assert_true(pg_world_hash(fresh.world) == h);
    assert_int_equal(pg_replay_apply_frame(fresh.world, NULL, &info, starts[0], NULL, NULL), PG_ERR_NULL);
    assert_non_null(strstr(pg_world_last_error(fresh.world), "data is NULL"));
    assert_int_equal(pg_replay_apply_frame(fresh.world, buf, NULL, starts[0], NULL, NULL), PG_ERR_NULL);
    assert_non_null(strstr(pg_world_last_error(fresh.world), "info is NULL"));
    assert_int_equal(pg_replay_apply_frame(NULL, buf, &info, starts[0], NULL, NULL), PG_ERR_NULL);
    free(memory);
    free(b.memory);
    free(fresh.memory);
}

/* On a longer recording (13 checkpoint blocks, commands in some frames): exactly the
 * frame record starts found by walking the file from its first record are accepted. */
static void test_apply_frame_every_offset(void **state)
{
    size_t size, pos, off, cs, nstarts = 0;
    uint64_t h;
    uint8_t *file = record(125, 10, 1 << 16, &size, &h);
    uint8_t *is_start;
    pg_replay_info info;
    pg_replay_error err;
    world_box b = make_world();
    (void)state;
    assert_int_equal(pg_replay_read(file, size, &info, &err), PG_OK);
    is_start = calloc(size + 8, 1);
    assert_non_null(is_start);
    cs = 21u + 8u * info.section_count;
    for (pos = info.records_offset; pos < info.end_offset;) { /* the reference walk */
        uint32_t n, c;
        if (file[pos] == PG_REPLAY_TAG_CHECKPOINT) {
            pos += cs;
            continue;
        }
        assert_int_equal(file[pos], PG_REPLAY_TAG_FRAME);
        is_start[pos] = 1;
        nstarts++;
        n = (uint32_t)file[pos + 1] | ((uint32_t)file[pos + 2] << 8);
        pos += 3;
        for (c = 0; c < n; ++c) {
            pg_command cmd;
            size_t used;
            assert_int_equal(pg_command_decode(file + pos, info.end_offset - pos, &cmd, &used, NULL, NULL), PG_OK);
            pos += used;
        }
    }
    assert_int_equal(nstarts, 125);
    for (off = 0; off < size + 8; ++off) {
        uint64_t before = pg_world_hash(b.world);
        pg_result r = pg_replay_apply_frame(b.world, file, &info, off, NULL, NULL);
        if (r != (is_start[off] ? PG_OK : PG_ERR_INVALID_ARGUMENT))
            fail_msg("offset %zu (byte %d, a record start: %d): %s", off, off < size ? file[off] : -1, is_start[off], pg_result_name(r));
        if (!is_start[off] && pg_world_hash(b.world) != before) fail_msg("refused offset %zu changed the world", off);
    }
    free(is_start);
    free(file);
    free(b.memory);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_writer_rejects),
        cmocka_unit_test(test_compare_checkpoint),
        cmocka_unit_test(test_write_read_play),
        cmocka_unit_test(test_every_bit_flip),
        cmocka_unit_test(test_truncation),
        cmocka_unit_test(test_changed_command_diverges),
        cmocka_unit_test(test_other_numeric_config_is_refused),
        cmocka_unit_test(test_format_1_upgrades),
        cmocka_unit_test(test_format_3_upgrades),
        cmocka_unit_test(test_snapshot_round_trip_10000),
        cmocka_unit_test(test_apply_frame_offsets),
        cmocka_unit_test(test_checkpoint_read),
        cmocka_unit_test(test_apply_frame_every_offset),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
