/* fuzz_replay.c — libFuzzer target for the replay file reader and player
 * (src/io/replay_file.c).
 *
 * For any input bytes:
 *   - pg_replay_read returns PG_OK, PG_ERR_INVALID_ARGUMENT or PG_ERR_INCOMPATIBLE (another
 *     format version or numeric configuration), never reads past the input
 *     (libFuzzer hands over a heap block of exactly `size` bytes, ASan watches its end),
 *     and on failure reports an offset <= size, a region, a field and a NUL-terminated
 *     message;
 *   - the same bytes with every hash and checksum recomputed (so that the fuzzer gets past
 *     them to the structure behind) obey the same rules; when they are accepted:
 *       * writing the decoded file again with pg_replay_writer gives the same bytes (the
 *         format is canonical),
 *       * the player loads the scene and plays up to 64 frames without crashing.
 * Any violation aborts, which libFuzzer reports as a crash.
 *
 * Build: cmake -S . -B build-fuzz -DCMAKE_C_COMPILER=clang -DPOGON_BUILD_FUZZ=ON
 * Run:   build-fuzz/tests/fuzz/fuzz_replay -dict=tests/fuzz/replay.dict -max_total_time=180 corpus/ tests/replays
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pogon/replay_file.h"

#define WORLD_BYTES (8u << 20)
static uint64_t world_memory[WORLD_BYTES / 8];

static void check(int ok, const char *what)
{
    if (!ok) {
        fprintf(stderr, "fuzz_replay: %s\n", what);
        abort();
    }
}

static void put_u64(uint8_t *p, uint64_t v)
{
    int i;
    for (i = 0; i < 8; ++i) p[i] = (uint8_t)(v >> (8 * i));
}
static uint32_t get_u32(const uint8_t *p)
{
    return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
}
static uint64_t hash(const uint8_t *p, size_t n) { return pg_hash_bytes(PG_HASH_SEED, p, n); }

/* Recompute the hashes of a file as the layout of docs/formats.md places them, as far as
 * its structure can be followed. */
static void repair(uint8_t *d, size_t n)
{
    size_t scene, pos, block, records_end, cs;
    uint32_t interval, sections, frame = 0, checkpoints = 0;
    if (n < PG_REPLAY_HEADER_SIZE) return;
    put_u64(d + 36, hash(d, 36));
    interval = get_u32(d + 24);
    sections = get_u32(d + 28);
    scene = get_u32(d + 32);
    if (n < PG_REPLAY_HEADER_SIZE + 8u + PG_REPLAY_TRAILER_SIZE ||
        scene > n - PG_REPLAY_HEADER_SIZE - 8u - PG_REPLAY_TRAILER_SIZE) {
        if (n >= 8) put_u64(d + n - 8, hash(d, n - 8));
        return;
    }
    put_u64(d + PG_REPLAY_HEADER_SIZE + scene, hash(d + PG_REPLAY_HEADER_SIZE, scene));
    records_end = n - PG_REPLAY_TRAILER_SIZE;
    pos = block = PG_REPLAY_HEADER_SIZE + scene + 8;
    if (interval != 0 && sections >= 1 && sections <= PG_REPLAY_MAX_SECTIONS) {
        cs = 21u + 8u * sections;
        for (;;) {
            if (frame % interval == 0 && checkpoints <= frame / interval) {
                if (cs > records_end - pos) break;
                put_u64(d + pos + cs - 8, hash(d + block, pos + cs - 8 - block));
                pos += cs;
                block = pos;
                checkpoints++;
                continue;
            }
            if (pos >= records_end || d[pos] != PG_REPLAY_TAG_FRAME || records_end - pos < 3) break;
            {
                uint32_t count = (uint32_t)d[pos + 1] | ((uint32_t)d[pos + 2] << 8), c;
                size_t p = pos + 3;
                for (c = 0; c < count; ++c) {
                    pg_command cmd;
                    size_t used = 0;
                    if (pg_command_decode(d + p, records_end - p, &cmd, &used, NULL, NULL) != PG_OK) break;
                    p += used;
                }
                if (c != count) break;
                pos = p;
            }
            frame++;
        }
        if (pos == records_end) put_u64(d + records_end + 13, hash(d + block, records_end + 13 - block));
    }
    put_u64(d + n - 8, hash(d, n - 8));
}

/* Write the decoded file again; it must come out byte for byte. */
static void rewrite_equal(const uint8_t *d, const pg_replay_info *info)
{
    pg_replay_writer w;
    uint8_t *out;
    size_t pos = info->records_offset, size = 0, cs = 21u + 8u * info->section_count;
    uint32_t index = 0;
    pg_command *cmds = malloc(sizeof(pg_command) * (info->max_frame_commands + 1u));
    if (info->section_count != PG_SECTION_COUNT || info->engine_major != POGON_VERSION_MAJOR ||
        info->engine_minor != POGON_VERSION_MINOR || info->engine_patch != POGON_VERSION_PATCH) {
        free(cmds);
        return;
    }
    out = malloc(info->size);
    check(out != NULL && cmds != NULL, "malloc");
    check(pg_replay_writer_begin(&w, out, info->size, info->scene_text, info->scene_size, info->checkpoint_interval) ==
              PG_OK,
          "writer_begin on a valid file's header");
    while (pos < info->end_offset) {
        if (d[pos] == PG_REPLAY_TAG_CHECKPOINT) {
            uint64_t h, s[PG_SECTION_COUNT];
            unsigned k;
            h = 0;
            for (k = 0; k < 8; ++k) h |= (uint64_t)d[pos + 5 + k] << (8 * k);
            for (k = 0; k < PG_SECTION_COUNT; ++k) {
                unsigned b;
                s[k] = 0;
                for (b = 0; b < 8; ++b) s[k] |= (uint64_t)d[pos + 13 + 8 * k + b] << (8 * b);
            }
            check(pg_replay_writer_add_checkpoint(&w, h, s) == PG_OK, "writer_add_checkpoint");
            pos += cs;
            index++;
        } else {
            uint32_t n = (uint32_t)d[pos + 1] | ((uint32_t)d[pos + 2] << 8), c;
            pos += 3;
            for (c = 0; c < n; ++c) {
                size_t used = 0;
                check(pg_command_decode(d + pos, info->end_offset - pos, &cmds[c], &used, NULL, NULL) == PG_OK,
                      "a command of a valid file does not decode");
                pos += used;
            }
            check(pg_replay_writer_add_frame(&w, cmds, n) == PG_OK, "writer_add_frame");
        }
    }
    check(index == info->checkpoint_count, "checkpoint count");
    check(pg_replay_writer_finish(&w, info->final_hash, &size) == PG_OK, "writer_finish");
    check(size == info->size && memcmp(out, d, size) == 0, "rewriting a valid file gives other bytes");
    free(out);
    free(cmds);
}

static void play(const uint8_t *d, const pg_replay_info *info)
{
    size_t need = 0;
    pg_replay_error err;
    pg_replay_player p;
    pg_replay_frame_result fr;
    int frames = 0;
    uint64_t h, s[PG_SECTION_COUNT];
    if (info->checkpoint_count > 0) {
        check(pg_replay_checkpoint(d, info, info->checkpoint_count - 1, &h, s) == PG_OK, "pg_replay_checkpoint");
    }
    if (pg_replay_world_memory_size(info, &need, &err) != PG_OK || need > sizeof world_memory) return;
    if (pg_replay_player_begin(&p, d, info, world_memory, sizeof world_memory, &fr, &err) != PG_OK) {
        check(err.offset <= info->size && memchr(err.message, 0, sizeof err.message) != NULL, "player error");
        return;
    }
    while (!pg_replay_player_done(&p) && frames < 64) {
        pg_replay_player_step(&p, &fr);
        frames++;
    }
}

static void read_one(const uint8_t *d, size_t n, int repaired)
{
    pg_replay_info info;
    pg_replay_error err;
    pg_result r = pg_replay_read(d, n, &info, &err);
    if (r == PG_ERR_INCOMPATIBLE && info.format_version == PG_REPLAY_FORMAT_VERSION) {
        /* sound, but of another numeric configuration: filled in, and refused by the player */
        pg_replay_player p;
        check(info.numeric_config != pg_numeric_config() && err.offset == 20, "incompatible for another reason");
        check(pg_replay_player_begin(&p, d, &info, world_memory, sizeof world_memory, NULL, &err) == PG_ERR_INCOMPATIBLE,
              "the player plays a file of another numeric configuration");
        return;
    }
    if (r != PG_OK) {
        check(r == PG_ERR_INVALID_ARGUMENT || r == PG_ERR_INCOMPATIBLE, "unexpected result");
        check(err.offset <= n, "error offset beyond the input");
        check(err.region != NULL && err.field != NULL, "error without region or field");
        check(memchr(err.message, 0, sizeof err.message) != NULL && err.message[0] != '\0', "bad error message");
        return;
    }
    check(info.size == n && info.end_offset + PG_REPLAY_TRAILER_SIZE == n, "info sizes");
    if (repaired || n < 65536) {
        rewrite_equal(d, &info);
        play(d, &info);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    uint8_t *copy;
    read_one(data, size, 0);
    copy = malloc(size ? size : 1);
    check(copy != NULL, "malloc");
    if (size) memcpy(copy, data, size);
    repair(copy, size);
    read_one(copy, size, 1);
    free(copy);
    return 0;
}
