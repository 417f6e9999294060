/* make_diverged — write a valid replay whose checkpoint at frame 60 disagrees with the
 * run in one section, to test how playback reports a divergence.
 *
 * Usage: make_diverged SCENE OUT.pgr
 * Plays SCENE for 120 frames without commands, checkpoints every 30 frames, and stores
 * checkpoint 2 (frame 60) with its bodies-section hash changed and its whole-state hash
 * made again from the sections.
 * The file's structure and checksums are correct: only replaying can tell. Test code.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "pogon/replay_file.h"
#include "pogon/scene_file.h"

int main(int argc, char **argv)
{
    static uint8_t text[1 << 16], out[1 << 16];
    pg_scene_error err;
    pg_world_def def;
    pg_world *world;
    pg_replay_writer w;
    void *memory;
    size_t length, size = 0;
    uint32_t frame;
    FILE *f;
    if (argc != 3 || (f = fopen(argv[1], "rb")) == NULL) {
        fprintf(stderr, "usage: make_diverged SCENE OUT.pgr\n");
        return 2;
    }
    length = fread(text, 1, sizeof text, f);
    fclose(f);
    if (pg_scene_read_def((const char *)text, length, &def, &err) != PG_OK) {
        fprintf(stderr, "%s: %s\n", argv[1], err.message);
        return 2;
    }
    memory = malloc(pg_world_memory_size(&def));
    if (memory == NULL || pg_world_create(&def, memory, pg_world_memory_size(&def), &world) != PG_OK ||
        pg_scene_load(world, (const char *)text, length, &err) != PG_OK ||
        pg_replay_writer_begin(&w, out, sizeof out, (const char *)text, length, 30) != PG_OK ||
        pg_replay_writer_add_checkpoint_world(&w, world) != PG_OK) {
        fprintf(stderr, "make_diverged: cannot start\n");
        return 2;
    }
    for (frame = 0; frame < 120; ++frame) {
        if (pg_replay_writer_add_frame(&w, NULL, 0) != PG_OK || pg_world_step(world) != PG_OK) return 2;
        if (pg_replay_writer_checkpoint_due(&w)) {
            uint64_t sections[PG_SECTION_COUNT];
            uint64_t hash = pg_world_hash(world);
            pg_world_section_hashes(world, sections);
            if (frame + 1 == 60) {
                /* a checkpoint consistent in itself (its state hash is the hash of its
                 * section hashes, which the writer and reader check) that the world
                 * does not match */
                uint8_t bytes[8];
                int k, i;
                sections[PG_SECTION_BODIES] ^= 1u;
                hash = PG_HASH_SEED;
                for (k = 0; k < PG_SECTION_COUNT; ++k) {
                    for (i = 0; i < 8; ++i) bytes[i] = (uint8_t)((sections[k] >> (8 * i)) & 0xFFu);
                    hash = pg_hash_bytes(hash, bytes, 8);
                }
            }
            if (pg_replay_writer_add_checkpoint(&w, hash, sections) != PG_OK) return 2;
        }
    }
    if (pg_replay_writer_finish(&w, pg_world_hash(world), &size) != PG_OK) return 2;
    f = fopen(argv[2], "wb");
    if (f == NULL || fwrite(out, 1, size, f) != size || fclose(f) != 0) return 2;
    free(memory);
    return 0;
}
