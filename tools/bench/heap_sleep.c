/* heap_sleep.c — why a large settled pile does or does not fall asleep (docs/hard-cases.md,
 * "Heap").
 *
 *   pogon-heap-sleep [BODIES [STEPS [EVERY]]]     defaults 4000, 10000, 250
 *
 * Runs the `heap` scene (tools/scenes) at the defaults and, every EVERY steps, prints one
 * line: bodies awake; the islands the awake bodies form over touching contacts and the
 * largest; the bodies whose velocity at the end of the step is above the sleep tolerance
 * (|v| > 0.05 m/s, or |w| > 2 degrees/s with |v| + extent |w| > 0.05 m/s); the bodies whose
 * motion in the step (displacement and turn times the step rate, what src/core/island.c tests)
 * is above it; the contact points holding a deep-push impulse; the largest end velocity
 * and the largest displacement speed of a body. It reads the world's internals (the
 * contacts' push impulses): a measuring tool, not an example. */
#include "scenes.h"
#include "world_types.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct pose { pg_vec2 c; pg_angle a; } pose;

static uint32_t find_root(uint32_t *parent, uint32_t i)
{
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

static double extent_of(const pg_world *w, const pg_body *b)
{
    double e = 0.0;
    uint32_t s;
    int32_t k;
    for (s = b->first_shape; s != PG_NULL_INDEX; s = w->shapes[s].next)
        for (k = 0; k < w->shapes[s].local.count; ++k) {
            double dx = (w->shapes[s].local.vertices[k].x - b->local_center.x) / 65536.0;
            double dy = (w->shapes[s].local.vertices[k].y - b->local_center.y) / 65536.0;
            double r = sqrt(dx * dx + dy * dy) + w->shapes[s].local.radius / 65536.0;
            if (r > e) e = r;
        }
    return e;
}

static int moving(double v, double om, double extent, double lin_tol, double ang_tol)
{
    return v > lin_tol || (fabs(om) > ang_tol && v + extent * fabs(om) > lin_tol);
}

int main(int argc, char **argv)
{
    uint32_t count = argc > 1 ? (uint32_t)strtoul(argv[1], NULL, 10) : 4000u;
    uint32_t steps = argc > 2 ? (uint32_t)strtoul(argv[2], NULL, 10) : 10000u;
    uint32_t every = argc > 3 ? (uint32_t)strtoul(argv[3], NULL, 10) : 250u;
    pg_world_def d = pg_scene_world_def("heap", count);
    size_t size = pg_scene_memory_size("heap", count, &d);
    void *memory = malloc(size); /* malloc aligns to 8 at least */
    pose *start = (pose *)calloc(count + 16u, sizeof(pose));
    uint32_t *parent = (uint32_t *)calloc(count + 16u, sizeof(uint32_t)), *island = (uint32_t *)calloc(count + 16u, sizeof(uint32_t));
    double lin_tol, ang_tol;
    pg_scene scene;
    pg_world *w;
    uint32_t s, i;
    if (memory == NULL || start == NULL || parent == NULL || island == NULL || every == 0) return 2;
    if (pg_scene_build("heap", count, &d, memory, size, &scene) != PG_OK) {
        fprintf(stderr, "heap_sleep: cannot build the heap of %u bodies\n", count);
        return 1;
    }
    w = scene.world;
    lin_tol = w->def.sleep_linear_tolerance / 65536.0;
    ang_tol = w->def.sleep_angular_tolerance / 65536.0;
    printf("# heap of %u bodies, %u Hz, %u substeps\n", count, w->def.step_hz, w->def.substeps);
    printf("# time_s step awake islands largest moving_by_velocity moving_by_displacement push_points max_velocity max_displacement_speed\n");
    for (s = 1; s <= steps; ++s) {
        for (i = 0; i < w->body_high; ++i) {
            start[i].c = w->bodies[i].center;
            start[i].a = w->bodies[i].angle;
        }
        if (pg_world_step(w) != PG_OK) return 1;
        if (s % every != 0) continue;
        {
            uint32_t awake = 0, by_v = 0, by_d = 0, push = 0, islands = 0, largest = 0;
            double max_v = 0.0, max_d = 0.0;
            for (i = 0; i < w->body_high; ++i) {
                const pg_body *b = &w->bodies[i];
                double v, om, dv, dom, ext;
                parent[i] = i;
                island[i] = 0;
                if (!pg__body_is_active(b)) continue;
                ++awake;
                ext = extent_of(w, b);
                v = hypot(b->v.x / 65536.0, b->v.y / 65536.0);
                om = b->w / 65536.0;
                dv = hypot((b->center.x - start[i].c.x) / 65536.0, (b->center.y - start[i].c.y) / 65536.0) * w->def.step_hz;
                dom = (double)(int32_t)(b->angle - start[i].a) / 4294967296.0 * 6.283185307179586 * w->def.step_hz;
                by_v += (uint32_t)moving(v, om, ext, lin_tol, ang_tol);
                by_d += (uint32_t)moving(dv, dom, ext, lin_tol, ang_tol);
                if (v > max_v) max_v = v;
                if (dv > max_d) max_d = dv;
            }
            for (i = 0; i < w->contact_count; ++i) {
                const pg_contact *c = &w->contacts[i];
                int32_t k;
                for (k = 0; k < c->point_count; ++k) push += c->points[k].push_impulse != 0;
                if (c->point_count > 0 && pg__body_is_active(&w->bodies[c->body_a]) && pg__body_is_active(&w->bodies[c->body_b]) &&
                    w->bodies[c->body_a].type == PG_BODY_DYNAMIC && w->bodies[c->body_b].type == PG_BODY_DYNAMIC) {
                    uint32_t ra = find_root(parent, c->body_a), rb = find_root(parent, c->body_b);
                    if (ra < rb) parent[rb] = ra;
                    else if (rb < ra) parent[ra] = rb;
                }
            }
            for (i = 0; i < w->body_high; ++i)
                if (pg__body_is_active(&w->bodies[i])) island[find_root(parent, i)] += 1;
            for (i = 0; i < w->body_high; ++i)
                if (island[i] > 0) {
                    ++islands;
                    if (island[i] > largest) largest = island[i];
                }
            printf("%.2f %u %u %u %u %u %u %u %.4f %.4f\n", s / (double)w->def.step_hz, s, awake, islands, largest, by_v, by_d, push, max_v, max_d);
            fflush(stdout);
        }
    }
    free(island);
    free(parent);
    free(start);
    free(memory);
    return 0;
}
