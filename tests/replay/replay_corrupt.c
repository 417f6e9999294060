/* replay_corrupt — damages a replay file in each region and checks what `pogon-replay
 * verify` says about it:
 *   - one flipped bit in the header, the scene, a command, the checksum: exit 2 and a
 *     message naming an offset inside that region;
 *   - a truncated file, another format version: exit 2;
 *   - a sound file of another numeric configuration: exit 2 naming the field and both
 *     sine tables, never a divergence;
 *   - a format 1 file: exit 2 saying how to upgrade it; `pogon-replay upgrade` gives back
 *     the format 2 file byte for byte, and refuses to seal a damaged one;
 *   - one changed command, re-encoded, with its block hash and the file checksum fixed:
 *     the file is valid, and verify exits 1 naming the frame of that command.
 *
 * Usage: replay_corrupt POGON_REPLAY REPLAY_FILE WORK_DIR
 * REPLAY_FILE must hold a set_linear_velocity command on a dynamic body (the corpus file
 * commands.pgr does). Test code: may use stdio, malloc, popen.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>

#include "pogon/replay_file.h"

static const char *tool, *work;
static int failures;

static uint8_t *slurp(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    uint8_t *buf;
    long n;
    if (f == NULL || fseek(f, 0, SEEK_END) != 0 || (n = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0) {
        fprintf(stderr, "cannot read %s\n", path);
        exit(2);
    }
    buf = (uint8_t *)malloc((size_t)n + 1);
    if (buf == NULL || fread(buf, 1, (size_t)n, f) != (size_t)n) exit(2);
    fclose(f);
    *size = (size_t)n;
    return buf;
}

/* Write `data` to WORK/name, run `pogon-replay VERB WORK/name [WORK/name.out]` (the
 * second path for upgrade); returns the exit code, output in out. */
static int run_tool(const char *verb, const char *name, const uint8_t *data, size_t size, char *out, size_t cap)
{
    char path[1024], cmd[3400];
    FILE *f, *p;
    size_t len = 0;
    int status;
    snprintf(path, sizeof path, "%s/%s", work, name);
    f = fopen(path, "wb");
    if (f == NULL || fwrite(data, 1, size, f) != size || fclose(f) != 0) {
        fprintf(stderr, "cannot write %s\n", path);
        exit(2);
    }
    if (strcmp(verb, "upgrade") == 0)
        snprintf(cmd, sizeof cmd, "'%s' upgrade '%s' '%s.out' 2>&1", tool, path, path);
    else
        snprintf(cmd, sizeof cmd, "'%s' %s '%s' 2>&1", tool, verb, path);
    p = popen(cmd, "r");
    if (p == NULL) exit(2);
    while (len + 1 < cap) {
        size_t n = fread(out + len, 1, cap - 1 - len, p);
        if (n == 0) break;
        len += n;
    }
    out[len] = '\0';
    status = pclose(p);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

static int run_verify(const char *name, const uint8_t *data, size_t size, char *out, size_t cap)
{
    return run_tool("verify", name, data, size, out, cap);
}

/* The offset the message names ("at offset N"), or -1. */
static long named_offset(const char *out)
{
    const char *s = strstr(out, "at offset ");
    return s != NULL ? strtol(s + 10, NULL, 10) : -1;
}

static void expect(int cond, const char *what, const char *out)
{
    if (!cond) {
        failures++;
        fprintf(stderr, "FAIL: %s\n  output: %s\n", what, out);
    } else {
        printf("ok: %s\n", what);
    }
}

/* Flip one bit at `at`, expect exit 2 and an offset in [lo, hi). */
static void flip_case(const char *label, const uint8_t *file, size_t size, size_t at, int bit, long lo, long hi)
{
    uint8_t *copy = (uint8_t *)malloc(size);
    char out[8192], what[512];
    int rc;
    long off;
    memcpy(copy, file, size);
    copy[at] ^= (uint8_t)(1u << bit);
    rc = run_verify("flipped.pgr", copy, size, out, sizeof out);
    off = named_offset(out);
    snprintf(what, sizeof what, "%s: bit %d of byte %zu flipped -> exit 2 (got %d), offset in [%ld, %ld) (got %ld)",
             label, bit, at, rc, lo, hi, off);
    expect(rc == 2 && off >= lo && off < hi, what, out);
    free(copy);
}

static void put_u64(uint8_t *p, uint64_t v)
{
    int i;
    for (i = 0; i < 8; ++i) p[i] = (uint8_t)(v >> (8 * i));
}

int main(int argc, char **argv)
{
    size_t size, pos, block_start, cs;
    uint8_t *file, *copy;
    pg_replay_info info;
    pg_replay_error err;
    char out[8192], what[512];
    uint32_t frame = 0;
    int rc;
    size_t cmd_off = 0, cmd_len = 0, cmd_block = 0, cmd_block_hash = 0;
    uint32_t cmd_frame = 0;
    pg_command cmd;

    if (argc != 4) {
        fprintf(stderr, "usage: replay_corrupt POGON_REPLAY REPLAY_FILE WORK_DIR\n");
        return 2;
    }
    tool = argv[1];
    work = argv[3];
    file = slurp(argv[2], &size);
    if (pg_replay_read(file, size, &info, &err) != PG_OK) {
        fprintf(stderr, "%s is not valid: %s\n", argv[2], err.message);
        return 2;
    }
    rc = run_verify("intact.pgr", file, size, out, sizeof out);
    expect(rc == 0, "the intact file verifies (exit 0)", out);

    /* one bit in each region */
    flip_case("header magic", file, size, 3, 1, 3, 4);
    flip_case("header format version", file, size, 8, 0, 8, 9);
    flip_case("header numeric configuration", file, size, 20, 2, 0, PG_REPLAY_HEADER_SIZE);
    flip_case("header checkpoint interval", file, size, 25, 2, 0, PG_REPLAY_HEADER_SIZE);
    flip_case("header engine version", file, size, 12, 0, 0, PG_REPLAY_HEADER_SIZE);
    flip_case("header scene size", file, size, 33, 3, 0, PG_REPLAY_HEADER_SIZE);
    flip_case("scene text", file, size, info.scene_offset + info.scene_size / 2, 4, (long)info.scene_offset,
              (long)info.records_offset);

    /* walk the records: find the first set_linear_velocity and its block */
    cs = 1u + 4u + 8u + 8u * info.section_count + 8u;
    pos = info.records_offset;
    block_start = pos;
    while (pos < info.end_offset && cmd_len == 0) {
        if (file[pos] == PG_REPLAY_TAG_CHECKPOINT) {
            pos += cs;
            block_start = pos;
            continue;
        }
        {
            uint32_t n = (uint32_t)file[pos + 1] | ((uint32_t)file[pos + 2] << 8), c;
            pos += 3;
            for (c = 0; c < n; ++c) {
                size_t used = 0;
                if (pg_command_decode(file + pos, info.end_offset - pos, &cmd, &used, NULL, NULL) != PG_OK) return 2;
                if (cmd.kind == PG_CMD_SET_LINEAR_VELOCITY && cmd_len == 0) {
                    cmd_off = pos;
                    cmd_len = used;
                    cmd_frame = frame;
                    cmd_block = block_start;
                }
                pos += used;
            }
            frame++;
        }
    }
    if (cmd_len == 0) {
        fprintf(stderr, "%s has no set_linear_velocity command\n", argv[2]);
        return 2;
    }
    /* the block hash of that block: the next checkpoint's last field, or the end record's */
    pos = cmd_off + cmd_len;
    while (pos < info.end_offset && file[pos] != PG_REPLAY_TAG_CHECKPOINT) {
        uint32_t n = (uint32_t)file[pos + 1] | ((uint32_t)file[pos + 2] << 8), c;
        pg_command tmp;
        if (file[pos] != PG_REPLAY_TAG_FRAME) {
            /* still inside the frame of the command: skip its remaining commands */
            size_t used = 0;
            if (pg_command_decode(file + pos, info.end_offset - pos, &tmp, &used, NULL, NULL) != PG_OK) return 2;
            pos += used;
            continue;
        }
        pos += 3;
        for (c = 0; c < n; ++c) {
            size_t used = 0;
            if (pg_command_decode(file + pos, info.end_offset - pos, &tmp, &used, NULL, NULL) != PG_OK) return 2;
            pos += used;
        }
    }
    cmd_block_hash = pos < info.end_offset ? pos + cs - 8u : info.end_offset + 13u;

    flip_case("command", file, size, cmd_off + cmd_len - 2, 5, (long)info.records_offset, (long)(size - 8));
    flip_case("checksum", file, size, size - 3, 6, (long)(size - 8), (long)size);

    /* truncated, wrong version with a consistent header hash */
    rc = run_verify("truncated.pgr", file, size / 2, out, sizeof out);
    snprintf(what, sizeof what, "truncated to %zu bytes -> exit 2 (got %d) naming an offset", size / 2, rc);
    expect(rc == 2 && named_offset(out) >= 0, what, out);
    copy = (uint8_t *)malloc(size);
    memcpy(copy, file, size);
    copy[8] = (uint8_t)(PG_REPLAY_FORMAT_VERSION + 1u);
    put_u64(copy + 36, pg_hash_bytes(PG_HASH_SEED, copy, 36));
    rc = run_verify("newer.pgr", copy, size, out, sizeof out);
    expect(rc == 2 && named_offset(out) == 8 && strstr(out, "format_version") != NULL &&
               strstr(out, "is newer than this build's") != NULL,
           "a newer format version -> exit 2 naming offset 8, header.format_version, newer", out);

    /* another sine table, the file sealed as its recorder would: refused, not diverged */
    memcpy(copy, file, size);
    copy[20] = (uint8_t)(PG_TRIG_TABLE_BITS == 12 ? 8 : 12);
    put_u64(copy + 36, pg_hash_bytes(PG_HASH_SEED, copy, 36));
    put_u64(copy + size - 8, pg_hash_bytes(PG_HASH_SEED, copy, size - 8));
    rc = run_verify("other_table.pgr", copy, size, out, sizeof out);
    expect(rc == 2 && named_offset(out) == 20 && strstr(out, "header.numeric_config") != NULL &&
               strstr(out, PG_TRIG_TABLE_BITS == 12 ? "recorded with an 8-bit sine table; this build has a 12-bit sine table"
                                                    : "recorded with a 12-bit sine table; this build has") != NULL &&
               strstr(out, "DIVERGED") == NULL,
           "another sine table -> exit 2 naming offset 20, header.numeric_config and both tables", out);
    rc = run_tool("info", "other_table.pgr", copy, size, out, sizeof out);
    expect(rc == 2 && strstr(out, "numerics        a") != NULL && strstr(out, "header.numeric_config") != NULL,
           "info on another sine table -> the header, the numeric configuration and the refusal, exit 2", out);

    /* format 1: the same file without the numeric configuration (bytes 20..23) */
    {
        uint8_t *v1 = (uint8_t *)malloc(size - 4), *back;
        size_t v1_size = size - 4, back_size = 0;
        char path[1100];
        memcpy(v1, file, 20);
        memcpy(v1 + 20, file + 24, size - 24);
        v1[8] = 1;
        put_u64(v1 + 32, pg_hash_bytes(PG_HASH_SEED, v1, 32));
        put_u64(v1 + v1_size - 8, pg_hash_bytes(PG_HASH_SEED, v1, v1_size - 8));
        rc = run_verify("format1.pgr", v1, v1_size, out, sizeof out);
        expect(rc == 2 && named_offset(out) == 8 && strstr(out, "convert it with `pogon-replay upgrade IN OUT`") != NULL,
               "format 1 -> exit 2 naming offset 8 and the upgrade command", out);
        rc = run_tool("upgrade", "format1.pgr", v1, v1_size, out, sizeof out);
        snprintf(path, sizeof path, "%s/format1.pgr.out", work);
        back = rc == 0 ? slurp(path, &back_size) : NULL;
        expect(rc == 0 && back != NULL && back_size == size && memcmp(back, file, size) == 0,
               "pogon-replay upgrade of the format 1 file -> exit 0, the format 2 file byte for byte", out);
        free(back);
        remove(path);
        v1[v1_size / 2] ^= 0x20;
        rc = run_tool("upgrade", "format1_damaged.pgr", v1, v1_size, out, sizeof out);
        snprintf(path, sizeof path, "%s/format1_damaged.pgr.out", work);
        expect(rc == 2 && named_offset(out) >= 0 && fopen(path, "rb") == NULL,
               "pogon-replay upgrade of a damaged format 1 file -> exit 2 naming an offset, nothing written", out);
        free(v1);
    }

    /* checkpoint 0 altered with its block hash and the file checksum recomputed: its
     * section hash for bodies, then its state hash. Either way the state hash is no longer
     * the hash of the section hashes: exit 2 naming the checkpoint's hash field */
    {
        size_t cp = info.records_offset, fields[2];
        const char *labels[2] = {"checkpoint 0 section hash (bodies) altered, regions rehashed",
                                 "checkpoint 0 state hash altered, regions rehashed"};
        int k;
        fields[0] = cp + 13u + 8u * PG_SECTION_BODIES;
        fields[1] = cp + 5u;
        for (k = 0; k < 2; ++k) {
            memcpy(copy, file, size);
            copy[fields[k] + 2] ^= 0x10;
            put_u64(copy + cp + cs - 8u, pg_hash_bytes(PG_HASH_SEED, copy + cp, cs - 8u));
            put_u64(copy + size - 8, pg_hash_bytes(PG_HASH_SEED, copy, size - 8));
            rc = run_verify("altered_checkpoint.pgr", copy, size, out, sizeof out);
            snprintf(what, sizeof what, "%s -> exit 2 (got %d) naming offset %zu and the section hashes", labels[k], rc, cp + 5u);
            expect(rc == 2 && named_offset(out) == (long)(cp + 5u) && strstr(out, "not the hash of its section hashes") != NULL &&
                       strstr(out, "another engine version") == NULL,
                   what, out);
        }
    }

    /* one changed command, re-encoded, hashes fixed: valid file, verify exits 1 naming its frame */
    memcpy(copy, file, size);
    {
        size_t used = 0, n;
        uint8_t enc[PG_COMMAND_ENCODED_MAX];
        char want[128];
        pg_command_decode(copy + cmd_off, cmd_len, &cmd, &used, NULL, NULL);
        cmd.vec.x += PG_FIX_ONE; /* one metre per second faster */
        n = pg_command_encode(&cmd, enc, sizeof enc);
        if (n != cmd_len) return 2;
        memcpy(copy + cmd_off, enc, n);
        put_u64(copy + cmd_block_hash, pg_hash_bytes(PG_HASH_SEED, copy + cmd_block, cmd_block_hash - cmd_block));
        put_u64(copy + size - 8, pg_hash_bytes(PG_HASH_SEED, copy, size - 8));
        rc = pg_replay_read(copy, size, &info, &err) == PG_OK;
        expect(rc, "the changed file is valid (hashes fixed)", err.message);
        rc = run_verify("changed.pgr", copy, size, out, sizeof out);
        if (info.checkpoint_interval == 1)
            snprintf(want, sizeof want, "(frame %u): ", cmd_frame + 1);
        else
            snprintf(want, sizeof want, "DIVERGED at checkpoint");
        snprintf(what, sizeof what, "changed set_linear_velocity in frame %u -> exit 1 (got %d) naming frame %u", cmd_frame,
                 rc, cmd_frame + 1);
        expect(rc == 1 && strstr(out, want) != NULL, what, out);
        if (info.checkpoint_interval == 1) {
            snprintf(want, sizeof want, "frame in %u..%u", cmd_frame, cmd_frame);
            expect(strstr(out, want) != NULL, "the message names the diverging frame record", out);
        }
    }
    free(copy);
    free(file);
    printf("%d failure(s)\n", failures);
    return failures == 0 ? 0 : 1;
}
