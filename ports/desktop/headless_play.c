/* headless_play.c — `--headless --play FILE [--jump F]... [--until F [--check-image BMP]]`.
 *
 * Verification plays the whole file with replay_seek (which compares every checkpoint);
 * jumps then restore kept snapshots, so the printed hashes test the jump path against
 * the straight one (`--until F` plays straight from frame 0 with nothing kept).
 */
#define _POSIX_C_SOURCE 200809L
#include "headless_play.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "file_io.h"
#include "image_check.h"
#include "replay_seek.h"

#define EXIT_DIVERGED 1
#define EXIT_BAD 2

static double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static void print_sections(FILE *f, uint32_t mask)
{
    int s, first = 1;
    for (s = 0; s < PG_SECTION_COUNT; ++s) {
        if (mask & (1u << s)) {
            fprintf(f, "%s%s", first ? "" : ", ", pg_section_name((pg_section)s));
            first = 0;
        }
    }
    if (first) fputs("none", f);
}

static void print_status(const char *path, const pga_seek *s)
{
    pga_seek_status st = pga_seek_get_status(s);
    printf("%s: frame %u of %u, %u of %u checkpoints compared, %u diverged", path, st.frame, st.frame_count,
           st.checkpoints_checked, st.checkpoint_count, st.checkpoints_failed);
    if (st.first_failed_frame >= 0) {
        printf(" (first at frame %lld: ", (long long)st.first_failed_frame);
        print_sections(stdout, st.first_failed_sections);
        printf(")");
    }
    printf(", hash 0x%016llx\n", (unsigned long long)pg_world_hash(pga_seek_world(s)));
}

/* Jump and finish the jump; prints where it came from and how long it took. */
static int jump_to(pga_seek *s, uint32_t target, const char *label)
{
    double t0 = now_seconds(), t1;
    pga_seek_status st;
    uint32_t from;
    if (pga_seek_jump(s, target) != PG_OK) {
        fprintf(stderr, "pogon-desktop: %s\n", pga_seek_error(s));
        return 0;
    }
    from = pga_seek_get_status(s).seek_from;
    while (!pga_seek_advance(s, 4096u)) {
    }
    t1 = now_seconds();
    st = pga_seek_get_status(s);
    if (st.frame != target) {
        fprintf(stderr, "pogon-desktop: the jump to %u stopped at frame %u: %s\n", target, st.frame, pga_seek_error(s));
        return 0;
    }
    printf("%s %u: hash 0x%016llx (from frame %u, %u frames stepped, %.3f s)\n", label, target,
           (unsigned long long)pg_world_hash(pga_seek_world(s)), from, target - from, t1 - t0);
    return 1;
}

int desktop_headless_play(const desktop_options *o)
{
    uint8_t *data;
    size_t size;
    char why[400];
    pga_seek *s;
    pga_seek_status st;
    int status = 0, i;
    if (!desktop_read_file(o->play_path, &data, &size, why, sizeof why)) {
        fprintf(stderr, "pogon-desktop: %s\n", why);
        return EXIT_BAD;
    }
    if (pga_seek_open(data, size, &s, why, sizeof why) != PG_OK) {
        fprintf(stderr, "pogon-desktop: %s: not a replay that can be played: %s\n", o->play_path, why);
        free(data);
        return EXIT_BAD;
    }
    free(data);
    if (o->until >= 0) {
        /* Straight from frame 0: no snapshot but frame 0's is kept yet. */
        if (o->until > (int64_t)pga_seek_info(s)->frame_count) {
            fprintf(stderr, "pogon-desktop: --until %lld is past the replay's last frame %u\n", (long long)o->until,
                    pga_seek_info(s)->frame_count);
            pga_seek_close(s);
            return EXIT_BAD;
        }
        if (!jump_to(s, (uint32_t)o->until, "until")) status = EXIT_BAD;
        if (status == 0 && o->check_image != NULL) {
            desktop_view view;
            unsigned checked = 0;
            view.center_x = o->view_x;
            view.center_y = o->view_y;
            view.scale = o->view_scale;
            view.width = o->width;
            view.height = o->height;
            if (desktop_check_image(o->check_image, &view, pga_seek_world(s), why, sizeof why, &checked)) {
                printf("image %s: %s\n", o->check_image, why);
            } else {
                fprintf(stderr, "pogon-desktop: image %s does not show frame %lld: %s\n", o->check_image,
                        (long long)o->until, why);
                status = EXIT_DIVERGED;
            }
        }
    } else {
        while (pga_seek_step(s)) {
        }
        st = pga_seek_get_status(s);
        if (st.frame != st.frame_count) {
            fprintf(stderr, "pogon-desktop: playing stopped at frame %u: %s\n", st.frame, pga_seek_error(s));
            status = EXIT_BAD;
        }
        if (pg_world_hash(pga_seek_world(s)) != pga_seek_info(s)->final_hash && st.checkpoints_failed == 0) {
            fprintf(stderr, "pogon-desktop: the final hash differs from the file's\n");
            status = EXIT_DIVERGED;
        }
        print_status(o->play_path, s);
        if (st.checkpoints_failed != 0 && status == 0) status = EXIT_DIVERGED;
        for (i = 0; i < o->jump_count && status != EXIT_BAD; ++i)
            if (!jump_to(s, o->jumps[i], "jump")) status = EXIT_BAD;
        st = pga_seek_get_status(s);
        if (st.checkpoints_failed != 0 && status == 0) status = EXIT_DIVERGED;
        if (o->jump_count != 0)
            printf("snapshots kept: %u, %zu bytes\n", st.snapshots, st.snapshot_bytes);
    }
    if (status == EXIT_DIVERGED) printf("%s: DIVERGED\n", o->play_path);
    else if (status == 0) printf("%s: OK\n", o->play_path);
    pga_seek_close(s);
    return status;
}
