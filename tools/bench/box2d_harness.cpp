// pogon-bench-box2d — the pogon-bench scenes in Box2D 2.4.1, for comparison.
//
// Usage: pogon-bench-box2d SCENE [--count N] [--steps N] [--repeat R] [--json] [--no-sleep]
//                          [--no-continuous] [--velocity-iterations N] [--position-iterations N]
//                          [--variant LABEL]
//        pogon-bench-box2d all [options]
//
// Same scenes as tools/scenes/scenes.c: a static ground 100 x 2 m whose top is at y = 0,
// 1 m boxes of density 1 and friction 0.6 (pyramid: `count` rows centred on x = 0;
// stack: `count` boxes in a column), and rain: a 42 x 2 m floor, side walls 0.5 m thick
// in 100 m pieces at x = +-20.25 up to 500 m, and `count` circles whose radii (0.25 ..
// 0.5 m) and positions come from the same xorshift32 sequence (seed 12345) in the same
// order, converted from the same Q16.16 integers. Box2D settings: gravity (0, -10),
// timestep 1/60, 8 velocity and 3 position iterations (its defaults), sleeping on
// (--no-sleep: SetAllowSleeping(false)), continuous collision on (--no-continuous:
// SetContinuousPhysics(false)); --velocity-iterations / --position-iterations change the
// iteration counts, --variant only labels the JSON line (tools/bench/peers uses it).
//
// The joint scenes of tools/scenes/joint_scenes.h, from the same integers: joint_grid
// (count = columns and rows, default 40: circles of radius 0.4 m, 1 m apart, the top row
// static, b2RevoluteJoint to the body above and the body on the left) and chain (count =
// chains, default 20, of 40 links pinned by b2RevoluteJoint at (2j, 2j) and starting
// horizontal). Box2D 2.4.1 has no capsule: a link is a box as long and wide as the
// capsule (1.25 x 0.25 m) whose mass and rotational inertia are set to the capsule's
// (b2Body::SetMassData), so the dynamics are the same. Every shape has category 2 and mask
// ~2 (nothing collides); sleeping is always off in these scenes. They report the same
// sanity figure as pogon-bench: sag_m (the grid's bottom row, mean drop) or stretch_m (the
// largest over the chains of the sum of anchor gaps), and worst_gap_m.
//
// Method (as pogon-bench): build `repeat` times (default 3), time `steps` steps (default
// 600 for pyramid/stack, 300 for rain) with clock_gettime(CLOCK_MONOTONIC) around the
// stepping only, report the median of the per-run mean ms per step. The same metrics and
// JSON keys as pogon-bench, with "engine":"box2d-2.4.1".
#include <box2d/box2d.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <time.h>
#include <vector>

namespace {

struct Options {
    uint32_t count = 0, steps = 0, repeat = 3;
    bool json = false;
    bool no_sleep = false;
    bool no_continuous = false;
    uint32_t velocity_iterations = 8, position_iterations = 3;
    std::string variant;
};

struct Result {
    std::string scene;
    uint32_t count = 0, bodies = 0, steps = 0, repeat = 0;
    double ms = 0, sps = 0, ms_min = 0, ms_max = 0;
    bool stands = false;
    double disp = 0, dx = 0, dy = 0, angle_deg = 0;
    uint32_t awake = 0, contacts = 0, touching = 0;
    bool sleeping = true;
    bool continuous = true;
    uint32_t velocity_iterations = 8, position_iterations = 3;
    std::string variant;
    uint32_t joints = 0;
    std::string figure; // joint scenes: "sag" or "stretch"
    double figure_m = 0, worst_gap_m = 0;
};

bool is_joint_scene(const std::string &scene) { return scene == "joint_grid" || scene == "chain"; }

double now_ms()
{
    timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

float q16(int32_t v) { return (float)v / 65536.0f; }

uint32_t next_random(uint32_t *state)
{
    uint32_t x = *state;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    *state = x;
    return x;
}

void add_wall(b2World *w, float cx, float cy, float width, float height, float friction)
{
    b2BodyDef bd;
    bd.position.Set(cx, cy);
    b2Body *b = w->CreateBody(&bd);
    b2PolygonShape box;
    box.SetAsBox(0.5f * width, 0.5f * height);
    b2FixtureDef fd;
    fd.shape = &box;
    fd.density = 0.0f;
    fd.friction = friction;
    b->CreateFixture(&fd);
}

// ---- joint scenes ------------------------------------------------------------------------
const int32_t GRID_RADIUS = 26214; // 0.4 m in Q16.16, as tools/scenes/joint_scenes.c
const uint32_t CHAIN_LINKS = 40;
const double LINK_LENGTH = 1.0, LINK_RADIUS = 0.125;
const uint16 NO_COLLISION_CATEGORY = 0x0002;

void joint(b2World *w, b2Body *a, b2Vec2 anchor_a, b2Body *b, b2Vec2 anchor_b)
{
    b2RevoluteJointDef jd;
    jd.bodyA = a;
    jd.bodyB = b;
    jd.localAnchorA = anchor_a;
    jd.localAnchorB = anchor_b;
    jd.referenceAngle = 0.0f;
    w->CreateJoint(&jd);
}

// The bodies of a joint scene in the order tools/scenes/joint_scenes.c makes them (the
// grid row by row, its static top row included; the chains link by link), for the sanity
// figure. Returns the last body made.
b2Body *build_joints(b2World *w, const std::string &scene, uint32_t count, std::vector<b2Body *> *bodies, uint32_t *dynamic,
                     uint32_t *joints)
{
    b2FixtureDef fd;
    fd.density = 1.0f;
    fd.friction = 0.6f;
    fd.filter.categoryBits = NO_COLLISION_CATEGORY;
    fd.filter.maskBits = (uint16)~NO_COLLISION_CATEGORY;
    *dynamic = 0;
    *joints = 0;
    if (scene == "joint_grid") {
        b2CircleShape c;
        c.m_radius = q16(GRID_RADIUS);
        fd.shape = &c;
        for (uint32_t row = 0; row < count; ++row) {
            for (uint32_t col = 0; col < count; ++col) {
                b2BodyDef bd;
                bd.type = row == 0 ? b2_staticBody : b2_dynamicBody;
                bd.position.Set((float)col, -(float)row);
                b2Body *b = w->CreateBody(&bd);
                b->CreateFixture(&fd);
                bodies->push_back(b);
                if (row == 0) continue;
                joint(w, (*bodies)[(row - 1) * count + col], b2Vec2(0.0f, -0.5f), b, b2Vec2(0.0f, 0.5f));
                ++*joints;
                if (col > 0) {
                    joint(w, (*bodies)[row * count + col - 1], b2Vec2(0.5f, 0.0f), b, b2Vec2(-0.5f, 0.0f));
                    ++*joints;
                }
                ++*dynamic;
            }
        }
    } else {
        b2BodyDef pins_def;
        b2Body *pins = w->CreateBody(&pins_def); // static, no fixtures
        b2PolygonShape box;
        box.SetAsBox((float)(0.5 * LINK_LENGTH + LINK_RADIUS), (float)LINK_RADIUS);
        fd.shape = &box;
        // the capsule's mass and inertia about its centre (as src/core/mass.c): area 2rL + pi r^2,
        // I = rL^3/6 + 2r^3 L + pi r^2 (r^2/2 + L^2/4), density 1
        const double pi = 3.14159265358979323846, r = LINK_RADIUS, l = LINK_LENGTH;
        b2MassData md;
        md.mass = (float)(2.0 * r * l + pi * r * r);
        md.center.SetZero();
        md.I = (float)(r * l * l * l / 6.0 + 2.0 * r * r * r * l + pi * r * r * (r * r / 2.0 + l * l / 4.0));
        for (uint32_t j = 0; j < count; ++j) {
            float pin = 2.0f * (float)j;
            for (uint32_t i = 0; i < CHAIN_LINKS; ++i) {
                b2BodyDef bd;
                bd.type = b2_dynamicBody;
                bd.position.Set(pin + (float)i * (float)LINK_LENGTH + 0.5f * (float)LINK_LENGTH, pin);
                b2Body *b = w->CreateBody(&bd);
                b->CreateFixture(&fd);
                b->SetMassData(&md);
                if (i == 0)
                    joint(w, pins, b2Vec2(pin, pin), b, b2Vec2(-0.5f * (float)LINK_LENGTH, 0.0f));
                else
                    joint(w, bodies->back(), b2Vec2(0.5f * (float)LINK_LENGTH, 0.0f), b, b2Vec2(-0.5f * (float)LINK_LENGTH, 0.0f));
                ++*joints;
                bodies->push_back(b);
                ++*dynamic;
            }
        }
    }
    return bodies->empty() ? nullptr : bodies->back();
}

double gap(b2Vec2 a, b2Vec2 b)
{
    double dx = (double)a.x - (double)b.x, dy = (double)a.y - (double)b.y;
    return std::sqrt(dx * dx + dy * dy);
}

// The same figures as pg_joint_scene_sanity (tools/scenes/joint_scenes.c).
void joint_sanity(const std::string &scene, uint32_t count, const std::vector<b2Body *> &bodies, Result *res)
{
    res->worst_gap_m = 0.0;
    res->figure_m = 0.0;
    if (scene == "joint_grid") {
        double drop = 0.0;
        res->figure = "sag";
        for (uint32_t row = 1; row < count; ++row) {
            for (uint32_t col = 0; col < count; ++col) {
                const b2Body *b = bodies[row * count + col];
                double g = gap(bodies[(row - 1) * count + col]->GetWorldPoint(b2Vec2(0.0f, -0.5f)), b->GetWorldPoint(b2Vec2(0.0f, 0.5f)));
                res->worst_gap_m = std::max(res->worst_gap_m, g);
                if (col > 0) {
                    g = gap(bodies[row * count + col - 1]->GetWorldPoint(b2Vec2(0.5f, 0.0f)), b->GetWorldPoint(b2Vec2(-0.5f, 0.0f)));
                    res->worst_gap_m = std::max(res->worst_gap_m, g);
                }
                if (row == count - 1) drop += -(double)(count - 1) - (double)b->GetPosition().y;
            }
        }
        res->figure_m = count > 1 ? drop / (double)count : 0.0;
        return;
    }
    res->figure = "stretch";
    for (uint32_t j = 0; j < count; ++j) {
        double stretch = 0.0;
        for (uint32_t i = 0; i < CHAIN_LINKS; ++i) {
            const b2Body *b = bodies[j * CHAIN_LINKS + i];
            b2Vec2 from = i == 0 ? b2Vec2(2.0f * (float)j, 2.0f * (float)j)
                                 : bodies[j * CHAIN_LINKS + i - 1]->GetWorldPoint(b2Vec2(0.5f * (float)LINK_LENGTH, 0.0f));
            double g = gap(from, b->GetWorldPoint(b2Vec2(-0.5f * (float)LINK_LENGTH, 0.0f)));
            stretch += g;
            res->worst_gap_m = std::max(res->worst_gap_m, g);
        }
        res->figure_m = std::max(res->figure_m, stretch);
    }
}

// Builds the scene; returns the top body (the last one created).
b2Body *build(b2World *w, const std::string &scene, uint32_t count, uint32_t *bodies)
{
    const float friction = 0.6f, density = 1.0f;
    b2Body *top = nullptr;
    *bodies = 0;
    if (scene == "pyramid" || scene == "stack") {
        add_wall(w, 0.0f, -1.0f, 100.0f, 2.0f, friction);
        b2PolygonShape box;
        box.SetAsBox(0.5f, 0.5f);
        b2FixtureDef fd;
        fd.shape = &box;
        fd.density = density;
        fd.friction = friction;
        bool pyramid = scene == "pyramid";
        for (uint32_t row = 0; row < (pyramid ? count : 1u); ++row) {
            uint32_t n = pyramid ? count - row : count;
            for (uint32_t i = 0; i < n; ++i) {
                b2BodyDef bd;
                bd.type = b2_dynamicBody;
                if (pyramid)
                    bd.position.Set(q16((int32_t)(2 * i + 1) * 32768 - (int32_t)n * 32768), 0.5f + (float)row);
                else
                    bd.position.Set(0.0f, 0.5f + (float)i);
                top = w->CreateBody(&bd);
                top->CreateFixture(&fd);
                ++*bodies;
            }
        }
    } else if (scene == "rain") {
        add_wall(w, 0.0f, -1.0f, 42.0f, 2.0f, friction);
        for (uint32_t i = 0; i < 10u; ++i)
            add_wall(w, (i & 1u) ? 20.25f : -20.25f, 50.0f + 100.0f * (float)(i / 2u), 0.5f, 100.0f, friction);
        uint32_t seed = 12345u;
        for (uint32_t i = 0; i < count; ++i) {
            int32_t radius = 16384 + (int32_t)(next_random(&seed) % 16385u);
            uint32_t column = i % 39u, layer = i / 39u;
            int32_t jitter = (int32_t)(next_random(&seed) % 8193u) - 4096;
            int32_t x = (int32_t)column * 65536 - 19 * 65536 + jitter;
            int32_t y = 2 * 65536 + (int32_t)layer * 65536;
            b2BodyDef bd;
            bd.type = b2_dynamicBody;
            bd.position.Set(q16(x), q16(y));
            top = w->CreateBody(&bd);
            b2CircleShape c;
            c.m_radius = q16(radius);
            b2FixtureDef fd;
            fd.shape = &c;
            fd.density = density;
            fd.friction = friction;
            top->CreateFixture(&fd);
            ++*bodies;
        }
    }
    return top;
}

bool run(const std::string &scene, const Options &o, uint32_t count_override, Result *res)
{
    bool rain = scene == "rain", joints = is_joint_scene(scene);
    uint32_t count = count_override ? count_override : o.count ? o.count : rain ? 1000u : scene == "joint_grid" ? 40u : 20u;
    uint32_t steps = o.steps ? o.steps : rain ? 300u : 600u;
    uint32_t repeat = o.repeat ? o.repeat : 3u;
    std::vector<double> runs;
    res->scene = scene;
    res->count = count;
    res->steps = steps;
    res->repeat = repeat;
    res->stands = !rain && !joints;
    res->sleeping = !o.no_sleep && !joints; // the joint scenes time awake joints
    res->continuous = !o.no_continuous;
    res->velocity_iterations = o.velocity_iterations;
    res->position_iterations = o.position_iterations;
    res->variant = o.variant;
    for (uint32_t r = 0; r < repeat; ++r) {
        b2World *w = new b2World(b2Vec2(0.0f, -10.0f));
        w->SetAllowSleeping(res->sleeping);
        w->SetContinuousPhysics(!o.no_continuous);
        std::vector<b2Body *> scene_bodies;
        b2Body *top = joints ? build_joints(w, scene, count, &scene_bodies, &res->bodies, &res->joints)
                             : build(w, scene, count, &res->bodies);
        if (top == nullptr) {
            delete w;
            return false;
        }
        b2Vec2 start = top->GetPosition();
        double t0 = now_ms();
        for (uint32_t i = 0; i < steps; ++i) w->Step(1.0f / 60.0f, (int32)o.velocity_iterations, (int32)o.position_iterations);
        double t1 = now_ms();
        runs.push_back((t1 - t0) / (double)steps);
        b2Vec2 p = top->GetPosition();
        res->dx = (double)p.x - (double)start.x;
        res->dy = (double)p.y - (double)start.y;
        res->disp = std::sqrt(res->dx * res->dx + res->dy * res->dy);
        res->angle_deg = (double)top->GetAngle() * (180.0 / 3.14159265358979323846);
        if (joints) joint_sanity(scene, count, scene_bodies, res);
        res->awake = 0;
        for (b2Body *b = w->GetBodyList(); b != nullptr; b = b->GetNext())
            if (b->GetType() == b2_dynamicBody && b->IsAwake()) ++res->awake;
        res->contacts = (uint32_t)w->GetContactCount();
        res->touching = 0;
        for (b2Contact *c = w->GetContactList(); c != nullptr; c = c->GetNext())
            if (c->IsTouching()) ++res->touching;
        delete w;
    }
    std::sort(runs.begin(), runs.end());
    res->ms_min = runs.front();
    res->ms_max = runs.back();
    size_t n = runs.size();
    res->ms = (n & 1u) ? runs[n / 2] : 0.5 * (runs[n / 2 - 1] + runs[n / 2]);
    res->sps = res->ms > 0.0 ? 1000.0 / res->ms : 0.0;
    return true;
}

void print_json(const Result &r)
{
    std::printf("{\"engine\":\"box2d-2.4.1\",");
    if (!r.variant.empty()) std::printf("\"variant\":\"%s\",", r.variant.c_str());
    std::printf("\"continuous\":%s,\"velocity_iterations\":%u,\"position_iterations\":%u,", r.continuous ? "true" : "false",
                r.velocity_iterations, r.position_iterations);
    std::printf("\"scene\":\"%s\",\"count\":%u,\"bodies\":%u,\"steps\":%u,\"warmup\":0,"
                "\"repeat\":%u,\"sleeping\":%s,\"ms_per_step\":%.6f,\"ms_min\":%.6f,\"ms_max\":%.6f,\"steps_per_second\":%.2f,",
                r.scene.c_str(), r.count, r.bodies, r.steps, r.repeat, r.sleeping ? "true" : "false", r.ms, r.ms_min,
                r.ms_max, r.sps);
    if (r.stands)
        std::printf("\"top_displacement_m\":%.6f,\"dx_m\":%.6f,\"dy_m\":%.6f,\"angle_deg\":%.4f,", r.disp, r.dx, r.dy,
                    r.angle_deg);
    if (!r.figure.empty())
        std::printf("\"joints\":%u,\"%s_m\":%.6f,\"worst_gap_m\":%.6f,", r.joints, r.figure.c_str(), r.figure_m, r.worst_gap_m);
    std::printf("\"awake_bodies\":%u,\"contacts\":%u,\"touching\":%u}\n", r.awake, r.contacts, r.touching);
    std::fflush(stdout);
}

void print_header()
{
    std::printf("| engine | scene | count | bodies | steps | ms/step | steps/s | top disp m | dx m | dy m | angle deg | awake at end |\n");
    std::printf("| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
}

void print_row(const Result &r)
{
    std::printf("| box2d-2.4.1 | %s | %u | %u | %u | %.4f | %.1f | ", r.scene.c_str(), r.count, r.bodies, r.steps, r.ms, r.sps);
    if (r.stands)
        std::printf("%.5f | %+.5f | %+.5f | %+.3f | ", r.disp, r.dx, r.dy, r.angle_deg);
    else if (!r.figure.empty())
        std::printf("%s %.5f m, worst gap %.5f m | - | - | - | ", r.figure.c_str(), r.figure_m, r.worst_gap_m);
    else
        std::printf("- | - | - | - | ");
    std::printf("%u |\n", r.awake);
    std::fflush(stdout);
}

bool parse_u32(const char *text, uint32_t *out)
{
    if (text == nullptr || *text < '0' || *text > '9') return false;
    errno = 0;
    char *end;
    unsigned long v = std::strtoul(text, &end, 10);
    if (errno != 0 || *end != '\0' || v == 0 || v > 0xFFFFFFFFul) return false;
    *out = (uint32_t)v;
    return true;
}

} // namespace

int main(int argc, char **argv)
{
    Options o;
    std::string mode;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "--json") {
            o.json = true;
        } else if (a == "--no-sleep") {
            o.no_sleep = true;
        } else if (a == "--no-continuous") {
            o.no_continuous = true;
        } else if (a == "--variant" && i + 1 < argc) {
            o.variant = argv[++i];
        } else if (a == "--count" || a == "--steps" || a == "--repeat" || a == "--velocity-iterations" ||
                   a == "--position-iterations") {
            uint32_t v;
            if (i + 1 >= argc || !parse_u32(argv[i + 1], &v)) {
                std::fprintf(stderr, "pogon-bench-box2d: %s needs a positive integer\n", a.c_str());
                return 2;
            }
            (a == "--count" ? o.count : a == "--steps" ? o.steps : a == "--repeat" ? o.repeat
             : a == "--velocity-iterations" ? o.velocity_iterations : o.position_iterations) = v;
            ++i;
        } else if (a[0] != '-' && mode.empty()) {
            mode = a;
        } else {
            std::fprintf(stderr, "usage: pogon-bench-box2d pyramid|stack|rain|joint_grid|chain|all [--count N] [--steps N] [--repeat R] [--json] [--no-sleep]\n"
                         "         [--no-continuous] [--velocity-iterations N] [--position-iterations N] [--variant LABEL]\n");
            return 2;
        }
    }
    std::vector<std::pair<std::string, uint32_t>> todo;
    if (mode == "pyramid" || mode == "stack" || mode == "rain" || is_joint_scene(mode)) {
        todo.push_back({mode, 0u});
    } else if (mode == "all") {
        todo = {{"pyramid", 20u}, {"stack", 20u}, {"rain", 1000u}, {"rain", 2000u}, {"rain", 4000u}, {"rain", 8000u}, {"rain", 16000u}};
    } else {
        std::fprintf(stderr, "usage: pogon-bench-box2d pyramid|stack|rain|joint_grid|chain|all [--count N] [--steps N] [--repeat R] [--json] [--no-sleep]\n"
                         "         [--no-continuous] [--velocity-iterations N] [--position-iterations N] [--variant LABEL]\n");
        return 2;
    }
    if (!o.json) print_header();
    for (const auto &t : todo) {
        Result r;
        if (!run(t.first, o, t.second, &r)) {
            std::fprintf(stderr, "pogon-bench-box2d: could not build %s\n", t.first.c_str());
            return 1;
        }
        if (o.json) print_json(r); else print_row(r);
    }
    return 0;
}
