/* scene_file.c — the pogon scene text format (docs/formats.md, "Scene files"):
 * a reader that checks everything and a writer of the current state.
 *
 * READER
 *   One pass over the text, line by line, token by token, with a cursor that never
 *   passes `length`. No allocation, no recursion, no NUL needed. The same pass runs in
 *   two modes: READ (world == NULL) collects the settings, counts bodies and shapes and
 *   checks every value it can without a world (ranges, geometry through pg_geometry_*,
 *   each dynamic body's mass data as pg_shape_create will check it); LOAD repeats it and
 *   makes the bodies. pg_scene_load runs READ first, with the room the world has left
 *   for bodies and shapes, so every refusal is found before anything is created.
 *
 * WRITER
 *   The world's def, then every used body slot as a `body` block. Values that equal the
 *   defaults are left out; numbers are shortest exact decimals (pg_fix_format). It reads
 *   the pools directly (world_internal.h): flags such as allow_sleep have no getter.
 */
#include "pogon/joint.h"
#include "pogon/scene_file.h"
#include "chain.h"
#include "decompose.h"
#include "intmath.h"
#include "joint_pool.h"
#include "mass.h"
#include "text.h"
#include "work_area.h"
#include "world_internal.h"

/* A function whose frame must not be merged into its caller's (gcc inlines a static
 * function called once): a line's locals stay out of `run`, which every pg_make_* call
 * sits under (docs/embedded.md, "Stack"). */
#if defined(__GNUC__) || defined(__clang__)
#define PG__OWN_FRAME static __attribute__((noinline))
#else
#define PG__OWN_FRAME static
#endif

/* ---- small text helpers ------------------------------------------------------------------ */
typedef struct text_out {
    char *buf;
    size_t cap, len;
} text_out;

static void put_char(text_out *o, char c)
{
    if (o->buf != NULL && o->len + 1u < o->cap) o->buf[o->len] = c;
    o->len += 1u;
}

static void put_str(text_out *o, const char *s)
{
    while (*s != '\0') put_char(o, *s++);
}

static void put_u64(text_out *o, uint64_t v)
{
    char rev[24];
    int n = 0;
    do {
        rev[n++] = (char)('0' + (int)(v % 10u));
        v /= 10u;
    } while (v != 0);
    while (n > 0) put_char(o, rev[--n]);
}

static void put_hex(text_out *o, uint64_t v)
{
    static const char digits[] = "0123456789abcdef";
    char rev[20];
    int n = 0;
    do {
        rev[n++] = digits[v & 15u];
        v >>= 4;
    } while (v != 0);
    put_str(o, "0x");
    while (n > 0) put_char(o, rev[--n]);
}

static void put_fix(text_out *o, pg_fix v)
{
    char num[PG_FIX_FORMAT_MAX];
    pg_fix_format(v, num, sizeof num);
    put_str(o, num);
}

/* Terminate: the NUL goes at min(len, cap - 1). */
static void finish_out(text_out *o)
{
    if (o->buf != NULL && o->cap > 0) o->buf[o->len < o->cap - 1u ? o->len : o->cap - 1u] = '\0';
}

/* ---- angles ---------------------------------------------------------------------------------- */
pg_angle pg_scene_angle_from_degrees(pg_fix degrees)
{
    /* degrees * 2^32 / 360 from Q16.16: x = degrees * 2^16 (|x| < 2^47), rounded x / 360 */
    int64_t x = (int64_t)degrees * 65536;
    int64_t magnitude = x < 0 ? -x : x;
    uint32_t q = (uint32_t)((uint64_t)((magnitude + 180) / 360) & 0xFFFFFFFFu);
    return x < 0 ? (pg_angle)(0u - q) : (pg_angle)q;
}

/* The Q16.16 degrees nearest to a binary angle, in [-180, 180). */
static pg_fix degrees_from_angle(pg_angle a)
{
    int64_t s = a >= 0x80000000u ? (int64_t)a - (INT64_C(1) << 32) : (int64_t)a;
    return (pg_fix)pg__round_shift64(s * 360, 16);
}

/* ---- the reader's state --------------------------------------------------------------------- */
enum { MODE_READ = 0, MODE_LOAD = 1 };

/* Properties. A slot is what "given twice" is checked on (angle and angle_bits share one). */
enum prop_id {
    P_STEP_HZ, P_SUBSTEPS, P_GRAVITY, P_EFFECTS, P_MAX_BODIES, P_MAX_SHAPES, P_MAX_CONTACTS, P_MAX_JOINTS,
    P_MAX_CONTACT_EVENTS,
    P_CONTACT_HERTZ, P_CONTACT_DAMPING_RATIO, P_CONTACT_PUSH_MAX, P_RESTITUTION_THRESHOLD,
    P_MAX_LINEAR_SPEED, P_SLEEP_LINEAR_TOLERANCE, P_SLEEP_ANGULAR_TOLERANCE, P_TIME_TO_SLEEP,
    P_TYPE, P_POSITION, P_ANGLE, P_LINEAR_VELOCITY, P_ANGULAR_VELOCITY, P_LINEAR_DAMPING,
    P_ANGULAR_DAMPING, P_GRAVITY_SCALE, P_FIXED_ROTATION, P_ALLOW_SLEEP, P_AWAKE, P_USER_DATA,
    P_DENSITY, P_FRICTION, P_RESTITUTION, P_CATEGORY, P_MASK, P_OFFSET,
    P_ANGLE_BITS, /* shares the slot of P_ANGLE */
    P_COUNT
};
#define SETTING_COUNT (P_TIME_TO_SLEEP + 1)

/* Where a property may appear. */
enum {
    CTX_SETTING = 1u << 0,
    CTX_BODY = 1u << 1,       /* body line, body block, ready-made line */
    CTX_TYPE = 1u << 2,       /* `type` on a ready-made line */
    CTX_MATERIAL = 1u << 3,   /* shape lines and ready-made lines */
    CTX_OFFSET = 1u << 4,     /* circle and box shapes */
    CTX_SHAPE_ANGLE = 1u << 5 /* box shapes */
};

typedef struct prop_info {
    const char *name;
    uint8_t id, slot, ctx;
} prop_info;

static const prop_info props_table[] = {
    {"step_hz", P_STEP_HZ, P_STEP_HZ, CTX_SETTING},
    {"substeps", P_SUBSTEPS, P_SUBSTEPS, CTX_SETTING},
    {"gravity", P_GRAVITY, P_GRAVITY, CTX_SETTING},
    {"effects", P_EFFECTS, P_EFFECTS, CTX_SETTING},
    {"max_bodies", P_MAX_BODIES, P_MAX_BODIES, CTX_SETTING},
    {"max_shapes", P_MAX_SHAPES, P_MAX_SHAPES, CTX_SETTING},
    {"max_contacts", P_MAX_CONTACTS, P_MAX_CONTACTS, CTX_SETTING},
    {"max_joints", P_MAX_JOINTS, P_MAX_JOINTS, CTX_SETTING},
    {"max_contact_events", P_MAX_CONTACT_EVENTS, P_MAX_CONTACT_EVENTS, CTX_SETTING},
    {"contact_hertz", P_CONTACT_HERTZ, P_CONTACT_HERTZ, CTX_SETTING},
    {"contact_damping_ratio", P_CONTACT_DAMPING_RATIO, P_CONTACT_DAMPING_RATIO, CTX_SETTING},
    {"contact_push_max", P_CONTACT_PUSH_MAX, P_CONTACT_PUSH_MAX, CTX_SETTING},
    {"restitution_threshold", P_RESTITUTION_THRESHOLD, P_RESTITUTION_THRESHOLD, CTX_SETTING},
    {"max_linear_speed", P_MAX_LINEAR_SPEED, P_MAX_LINEAR_SPEED, CTX_SETTING},
    {"sleep_linear_tolerance", P_SLEEP_LINEAR_TOLERANCE, P_SLEEP_LINEAR_TOLERANCE, CTX_SETTING},
    {"sleep_angular_tolerance", P_SLEEP_ANGULAR_TOLERANCE, P_SLEEP_ANGULAR_TOLERANCE, CTX_SETTING},
    {"time_to_sleep", P_TIME_TO_SLEEP, P_TIME_TO_SLEEP, CTX_SETTING},
    {"type", P_TYPE, P_TYPE, CTX_TYPE},
    {"position", P_POSITION, P_POSITION, CTX_BODY},
    {"angle", P_ANGLE, P_ANGLE, CTX_BODY | CTX_SHAPE_ANGLE},
    {"angle_bits", P_ANGLE_BITS, P_ANGLE, CTX_BODY | CTX_SHAPE_ANGLE},
    {"linear_velocity", P_LINEAR_VELOCITY, P_LINEAR_VELOCITY, CTX_BODY},
    {"angular_velocity", P_ANGULAR_VELOCITY, P_ANGULAR_VELOCITY, CTX_BODY},
    {"linear_damping", P_LINEAR_DAMPING, P_LINEAR_DAMPING, CTX_BODY},
    {"angular_damping", P_ANGULAR_DAMPING, P_ANGULAR_DAMPING, CTX_BODY},
    {"gravity_scale", P_GRAVITY_SCALE, P_GRAVITY_SCALE, CTX_BODY},
    {"fixed_rotation", P_FIXED_ROTATION, P_FIXED_ROTATION, CTX_BODY},
    {"allow_sleep", P_ALLOW_SLEEP, P_ALLOW_SLEEP, CTX_BODY},
    {"awake", P_AWAKE, P_AWAKE, CTX_BODY},
    {"user_data", P_USER_DATA, P_USER_DATA, CTX_BODY},
    {"density", P_DENSITY, P_DENSITY, CTX_MATERIAL},
    {"friction", P_FRICTION, P_FRICTION, CTX_MATERIAL},
    {"restitution", P_RESTITUTION, P_RESTITUTION, CTX_MATERIAL},
    {"category", P_CATEGORY, P_CATEGORY, CTX_MATERIAL},
    {"mask", P_MASK, P_MASK, CTX_MATERIAL},
    {"offset", P_OFFSET, P_OFFSET, CTX_OFFSET},
};
#define PROPS_TABLE_COUNT (sizeof props_table / sizeof props_table[0])

static const char *const effect_names[7] = {"gravity", "rotation", "friction", "restitution", "damping", "sleeping", "continuous"};
static const char *const type_names[3] = {"static", "kinematic", "dynamic"};

/* The six ready-made kinds: keyword, number of sizes and their names. */
/* NOLINTNEXTLINE(clang-analyzer-optin.performance.Padding): six constant rows; the fields stay in the order a row reads */
typedef struct make_info {
    const char *name;
    int sizes;
    const char *size_names[2];
    uint32_t shapes;
} make_info;
static const make_info make_table[6] = {
    {"ball", 1, {"radius", NULL}, 1},
    {"capsule", 2, {"length", "radius"}, 1},
    {"box", 2, {"width", "height"}, 1},
    {"triangle", 1, {"circumradius", NULL}, 1},
    {"star", 1, {"circumradius", NULL}, 2},
    {"wall", 2, {"width", "height"}, 1},
};

/* A token: [start, start + len) of the text; len 0 means "end of line". */
typedef struct token {
    size_t start, len;
} token;

/* Values of the properties of one statement (a body, a shape line, a ready-made line). */
typedef struct props {
    uint64_t seen;            /* bit per slot */
    uint32_t line[P_COUNT], column[P_COUNT]; /* where each property's first value is */
    pg_body_def bd;
    pg_shape_def sd;
    pg_vec2 offset;
    pg_angle angle;
} props;

typedef struct scene_parser {
    const char *text;
    size_t length;
    int mode;
    pg_world *world;
    pg_scene_error *error;
    pg_scene_error scratch_error; /* when the caller passed NULL */
    pg_result result;

    /* the current line: [line_start, line_end), content before any '#' ends at content_end */
    size_t next_line, line_start, line_end, content_end, at, last_end;
    uint32_t line;

    pg_world_def def;
    uint64_t settings_seen;
    uint32_t setting_line[SETTING_COUNT], setting_column[SETTING_COUNT];
    int bodies_started;
    uint32_t bodies, shapes;

    /* the open body block */
    int in_body;
    uint32_t body_line;
    props body;
    uint32_t body_shapes;
    int body_made;
    pg_body_id body_id;

    /* READ: the collision forms and densities of the shapes of the body being read, for
     * the mass checks pg_shape_create makes as each shape is added (about 9 KB), the
     * list pg_compound_mass reads them from and its work space (what a world lends from
     * its scratch; the reader has no world) */
    pg_geom mass_geoms[64];
    pg_fix mass_densities[64];
    const pg_geom *mass_list[64];
    uint64_t mass_work[PG__MASS_WORK_BYTES / 8u];

    /* the one-line body being read (a ready-made kind, a concave polygon, a chain): its
     * properties, points, a concave polygon's pieces and the reason a check refused it.
     * The parser lives in the caller's work area, so these stay out of the frames that
     * call down to pg_make_* (docs/embedded.md, "Stack"). */
    props item;
    pg_vec2 points[PG_CHAIN_MAX_POINTS > PG_CONCAVE_MAX_VERTICES ? PG_CHAIN_MAX_POINTS : PG_CONCAVE_MAX_VERTICES];
    pg__decomposition pieces;
    char why[144];

    /* READ for pg_scene_load: the free body and shape slots of the world, and where the
     * scene first needs more (over_kind 1: bodies, 2: shapes; 0: it fits) */
    int room_given;
    uint32_t room_bodies, room_shapes;
    int over_kind;
    uint32_t over_line, over_count;

    /* joints: how many so far; READ for pg_scene_load: the world's free joint slots and
     * the line of the first joint beyond them (0: they fit); LOAD: the slot of the
     * file's body 0 */
    uint32_t joints, room_joints, joint_over_line, body_base;
} scene_parser;

/* ---- errors (messages: text.h) ----------------------------------------------------------- */
typedef pg__text msg;

/* 'token' (cut at 24 bytes) or "end of line". Tokens hold printable ASCII only. */
static void msg_token(msg *m, const scene_parser *P, token t)
{
    char buf[32];
    size_t i, n = t.len < 24u ? t.len : 24u;
    if (t.len == 0) {
        pg__text_put(m, "end of line");
        return;
    }
    buf[0] = '\'';
    for (i = 0; i < n; ++i) buf[1 + i] = P->text[t.start + i];
    buf[1 + n] = '\0';
    pg__text_put(m, buf);
    pg__text_put(m, t.len > n ? "...'" : "'");
}

static uint32_t sat_u32(size_t v) { return v > 0xFFFFFFFFu ? 0xFFFFFFFFu : (uint32_t)v; }

static uint32_t column_at(const scene_parser *P, size_t pos) { return sat_u32(pos - P->line_start + 1u); }

/* The column of a token, or for "end of line" the column just past the last token. */
static uint32_t token_column(const scene_parser *P, token t)
{
    return column_at(P, t.len == 0 ? P->last_end : t.start);
}

/* Start an error at (current line, column): the message gets its position prefix. */
static msg fail(scene_parser *P, pg_result r, uint32_t column)
{
    msg m;
    P->result = r;
    P->error->line = P->line;
    P->error->column = column;
    m = pg__text_in(P->error->message, sizeof P->error->message);
    if (P->line != 0) {
        pg__text_put(&m, "line ");
        pg__text_u64(&m, P->line);
        pg__text_put(&m, ", column ");
        pg__text_u64(&m, column);
        pg__text_put(&m, ": ");
    }
    return m;
}

/* "expected <what>, got <token>" */
static pg_result fail_expected(scene_parser *P, token t, const char *what, const char *name, const char *part)
{
    msg m = fail(P, PG_ERR_INVALID_ARGUMENT, token_column(P, t));
    pg__text_put(&m, "expected ");
    pg__text_put(&m, what);
    if (name != NULL) {
        pg__text_put(&m, " for '");
        pg__text_put(&m, name);
        pg__text_put(&m, "'");
    }
    if (part != NULL) {
        pg__text_put(&m, " (");
        pg__text_put(&m, part);
        pg__text_put(&m, ")");
    }
    pg__text_put(&m, ", got ");
    msg_token(&m, P, t);
    return P->result;
}

/* "'name' is <value>, outside <range>" */
static pg_result fail_range(scene_parser *P, uint32_t column, const char *name, pg_fix value, const char *range)
{
    msg m = fail(P, PG_ERR_ENVELOPE, column);
    pg__text_put(&m, "'");
    pg__text_put(&m, name);
    pg__text_put(&m, "' is ");
    pg__text_fix(&m, value);
    pg__text_put(&m, ", outside ");
    pg__text_put(&m, range);
    return P->result;
}

/* ---- lines and tokens ---------------------------------------------------------------------------- */
static int is_space(char c) { return c == ' ' || c == '\t' || c == '\r'; }

/* Move to the next line. Returns 0 at the end of the text, -1 after an error (a byte that
 * is not text before the comment), 1 otherwise. */
static int load_line(scene_parser *P)
{
    size_t i;
    if (P->next_line > P->length) return 0;
    P->line_start = P->next_line;
    for (i = P->line_start; i < P->length && P->text[i] != '\n'; ++i) {}
    P->line_end = i;
    P->next_line = i + 1u;
    for (i = P->line_start; i < P->line_end && P->text[i] != '#'; ++i) {}
    P->content_end = i;
    P->at = P->line_start;
    P->last_end = P->line_start;
    if (P->line < 0xFFFFFFFFu) P->line += 1u;
    for (i = P->line_start; i < P->content_end; ++i) {
        unsigned char c = (unsigned char)P->text[i];
        if (!is_space((char)c) && (c < 0x21u || c > 0x7Eu)) {
            static const char hex[] = "0123456789abcdef";
            char code[5];
            msg m = fail(P, PG_ERR_INVALID_ARGUMENT, column_at(P, i));
            code[0] = '0';
            code[1] = 'x';
            code[2] = hex[c >> 4];
            code[3] = hex[c & 15u];
            code[4] = '\0';
            pg__text_put(&m, "unexpected byte ");
            pg__text_put(&m, code);
            pg__text_put(&m, ": a scene file is ASCII text (anything may follow a '#')");
            return -1;
        }
    }
    return 1;
}

static token next_token(scene_parser *P)
{
    token t;
    while (P->at < P->content_end && is_space(P->text[P->at])) ++P->at;
    t.start = P->at;
    while (P->at < P->content_end && !is_space(P->text[P->at])) ++P->at;
    t.len = P->at - t.start;
    if (t.len != 0) P->last_end = P->at;
    return t;
}

static token peek_token(scene_parser *P)
{
    size_t at = P->at, last = P->last_end;
    token t = next_token(P);
    P->at = at;
    P->last_end = last;
    return t;
}

static int token_is(const scene_parser *P, token t, const char *word)
{
    size_t i;
    for (i = 0; i < t.len; ++i)
        if (word[i] == '\0' || word[i] != P->text[t.start + i]) return 0;
    return word[t.len] == '\0' && t.len != 0;
}

/* Does the token start like a number (so a vertex list goes on)? */
static int looks_numeric(const scene_parser *P, token t)
{
    char c = 'x';
    if (t.len != 0) c = P->text[t.start];
    return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.';
}

static pg_result expect_end_of_line(scene_parser *P, const char *after)
{
    token t = next_token(P);
    msg m;
    if (t.len == 0) return PG_OK;
    m = fail(P, PG_ERR_INVALID_ARGUMENT, token_column(P, t));
    pg__text_put(&m, "unexpected ");
    msg_token(&m, P, t);
    pg__text_put(&m, " after ");
    pg__text_put(&m, after);
    return P->result;
}

/* ---- values -------------------------------------------------------------------------------------- */
static pg_result read_fix(scene_parser *P, const char *name, const char *part, pg_fix *out, uint32_t *column)
{
    token t = next_token(P);
    pg_fix_status s;
    if (column != NULL) *column = token_column(P, t);
    if (t.len == 0) return fail_expected(P, t, "a number", name, part);
    s = pg_fix_parse(P->text + t.start, t.len, out);
    if (s == PG_FIX_SYNTAX) return fail_expected(P, t, "a number", name, part);
    if (s != PG_FIX_OK) {
        msg m = fail(P, PG_ERR_ENVELOPE, token_column(P, t));
        pg__text_put(&m, "number out of range for '");
        pg__text_put(&m, name);
        pg__text_put(&m, "': ");
        msg_token(&m, P, t);
        pg__text_put(&m, " (Q16.16 holds -32767.99998..32767.99998)");
        return P->result;
    }
    return PG_OK;
}

/* Unsigned integer, decimal or 0x hex, at most `max`. */
static pg_result read_uint(scene_parser *P, const char *name, uint64_t max, uint64_t *out, uint32_t *column)
{
    token t = next_token(P);
    size_t i = 0;
    uint64_t v = 0;
    int base = 10, overflow = 0;
    if (column != NULL) *column = token_column(P, t);
    if (t.len >= 2 && P->text[t.start] == '0' && (P->text[t.start + 1] == 'x' || P->text[t.start + 1] == 'X')) {
        base = 16;
        i = 2;
    }
    if (i >= t.len) return fail_expected(P, t, "an integer", name, NULL);
    for (; i < t.len; ++i) {
        char c = P->text[t.start + i];
        uint64_t d;
        if (c >= '0' && c <= '9') d = (uint64_t)(c - '0');
        else if (base == 16 && c >= 'a' && c <= 'f') d = (uint64_t)(c - 'a') + 10u;
        else if (base == 16 && c >= 'A' && c <= 'F') d = (uint64_t)(c - 'A') + 10u;
        else return fail_expected(P, t, base == 16 ? "a hexadecimal integer" : "an integer", name, NULL);
        if (v > (UINT64_MAX - d) / (uint64_t)base) overflow = 1;
        else v = v * (uint64_t)base + d;
    }
    if (overflow || v > max) {
        msg m = fail(P, PG_ERR_ENVELOPE, token_column(P, t));
        pg__text_put(&m, "integer out of range for '");
        pg__text_put(&m, name);
        pg__text_put(&m, "': ");
        msg_token(&m, P, t);
        pg__text_put(&m, " (at most ");
        pg__text_u64(&m, max);
        pg__text_put(&m, ")");
        return P->result;
    }
    *out = v;
    return PG_OK;
}

static pg_result read_u32(scene_parser *P, const char *name, uint32_t lo, uint32_t hi, uint32_t *out)
{
    uint64_t v = 0;
    uint32_t column = 0;
    pg_result r = read_uint(P, name, 0xFFFFFFFFu, &v, &column);
    if (r != PG_OK) return r;
    if (v < lo || v > hi) {
        msg m = fail(P, PG_ERR_ENVELOPE, column);
        pg__text_put(&m, "'");
        pg__text_put(&m, name);
        pg__text_put(&m, "' is ");
        pg__text_u64(&m, v);
        pg__text_put(&m, ", outside ");
        pg__text_u64(&m, lo);
        pg__text_put(&m, "..");
        pg__text_u64(&m, hi);
        return P->result;
    }
    *out = (uint32_t)v;
    return PG_OK;
}

static pg_result read_flag(scene_parser *P, const char *name, int *out)
{
    token t = next_token(P);
    if (token_is(P, t, "0")) *out = 0;
    else if (token_is(P, t, "1")) *out = 1;
    else return fail_expected(P, t, "0 or 1", name, NULL);
    return PG_OK;
}

/* A number within [lo, hi]; lo_open / hi_open exclude the bound. */
static pg_result read_fix_in(scene_parser *P, const char *name, const char *part, pg_fix lo, pg_fix hi, int lo_open,
                             const char *range, pg_fix *out)
{
    uint32_t column = 0;
    pg_result r = read_fix(P, name, part, out, &column);
    if (r != PG_OK) return r;
    if (*out < lo || *out > hi || (lo_open && *out == lo)) return fail_range(P, column, name, *out, range);
    return PG_OK;
}

static pg_result read_type(scene_parser *P, const char *name, pg_body_type *out)
{
    token t = next_token(P);
    int i;
    for (i = 0; i < 3; ++i)
        if (token_is(P, t, type_names[i])) {
            *out = (pg_body_type)i;
            return PG_OK;
        }
    return fail_expected(P, t, "static, kinematic or dynamic", name, NULL);
}

static int effect_bit(const scene_parser *P, token t)
{
    int i;
    for (i = 0; i < 7; ++i)
        if (token_is(P, t, effect_names[i])) return i;
    return -1;
}

/* effects all | none | 0xBITS | NAME... */
static pg_result read_effects(scene_parser *P, uint32_t *out)
{
    token t = peek_token(P);
    uint32_t bits = 0;
    if (token_is(P, t, "all") || token_is(P, t, "none")) {
        (void)next_token(P);
        *out = token_is(P, t, "all") ? PG_EFFECTS_ALL : 0u;
        return PG_OK;
    }
    if (t.len != 0 && P->text[t.start] >= '0' && P->text[t.start] <= '9') {
        uint64_t v = 0;
        uint32_t column = 0;
        pg_result r = read_uint(P, "effects", 0xFFFFFFFFu, &v, &column);
        if (r != PG_OK) return r;
        if ((v & ~(uint64_t)PG_EFFECTS_ALL) != 0) {
            msg m = fail(P, PG_ERR_ENVELOPE, column);
            pg__text_put(&m, "'effects' has bits outside 0x7f (gravity 0x1 .. continuous 0x40)");
            return P->result;
        }
        *out = (uint32_t)v;
        return PG_OK;
    }
    if (effect_bit(P, t) < 0)
        return fail_expected(P, t, "all, none, an integer or effect names (gravity rotation friction restitution damping sleeping continuous)", "effects", NULL);
    while (effect_bit(P, t) >= 0) {
        bits |= 1u << effect_bit(P, t);
        (void)next_token(P);
        t = peek_token(P);
    }
    *out = bits;
    return PG_OK;
}

/* ---- properties ------------------------------------------------------------------------------------ */
static const char *prop_name(int id)
{
    size_t i;
    for (i = 0; i < PROPS_TABLE_COUNT; ++i)
        if (props_table[i].id == id) return props_table[i].name;
    return "?";
}

static const prop_info *find_prop(const scene_parser *P, token t)
{
    size_t i;
    for (i = 0; i < PROPS_TABLE_COUNT; ++i)
        if (token_is(P, t, props_table[i].name)) return &props_table[i];
    return NULL;
}

static void props_init(props *pr, pg_body_type type)
{
    size_t i;
    pr->seen = 0;
    for (i = 0; i < P_COUNT; ++i) pr->line[i] = pr->column[i] = 0;
    pr->bd = pg_default_body_def();
    pr->bd.type = type;
    pr->sd = pg_default_shape_def();
    pr->offset = pg_v2_zero();
    pr->angle = 0;
}

#define POS_LIMIT "-1000..1000 m"

/* A world setting; the value goes into P->def. */
static pg_result read_setting(scene_parser *P, const prop_info *info)
{
    pg_world_def *d = &P->def;
    const char *n = info->name;
    switch (info->id) {
    case P_STEP_HZ: return read_u32(P, n, 1, 1000, &d->step_hz);
    case P_SUBSTEPS: return read_u32(P, n, 1, 16, &d->substeps);
    case P_GRAVITY: {
        pg_result r = read_fix_in(P, n, "x", -PG_FIX_C(1000), PG_FIX_C(1000), 0, "-1000..1000 m/s^2", &d->gravity.x);
        return r != PG_OK ? r : read_fix_in(P, n, "y", -PG_FIX_C(1000), PG_FIX_C(1000), 0, "-1000..1000 m/s^2", &d->gravity.y);
    }
    case P_EFFECTS: return read_effects(P, &d->effects);
    case P_MAX_BODIES: return read_u32(P, n, 1, 1u << 24, &d->max_bodies);
    case P_MAX_SHAPES: return read_u32(P, n, 1, 1u << 24, &d->max_shapes);
    case P_MAX_CONTACTS: return read_u32(P, n, 1, 1u << 24, &d->max_contacts);
    case P_MAX_JOINTS: return read_u32(P, n, 0, 1u << 24, &d->max_joints);
    case P_MAX_CONTACT_EVENTS: return read_u32(P, n, 0, 1u << 24, &d->max_contact_events);
    case P_CONTACT_HERTZ: return read_fix_in(P, n, NULL, 0, PG_FIX_C(1000), 1, "(0, 1000] Hz", &d->contact_hertz);
    case P_CONTACT_DAMPING_RATIO: return read_fix_in(P, n, NULL, 0, PG_FIX_C(1000), 0, "0..1000", &d->contact_damping_ratio);
    case P_CONTACT_PUSH_MAX: return read_fix_in(P, n, NULL, 0, PG_FIX_C(1000), 1, "(0, 1000] m/s", &d->contact_push_max);
    case P_RESTITUTION_THRESHOLD: return read_fix_in(P, n, NULL, 0, PG_FIX_MAX, 0, ">= 0 m/s", &d->restitution_threshold);
    case P_MAX_LINEAR_SPEED: return read_fix_in(P, n, NULL, 0, PG_FIX_C(4096), 1, "(0, 4096] m/s", &d->max_linear_speed);
    case P_SLEEP_LINEAR_TOLERANCE: return read_fix_in(P, n, NULL, 0, PG_FIX_MAX, 0, ">= 0 m/s", &d->sleep_linear_tolerance);
    case P_SLEEP_ANGULAR_TOLERANCE: return read_fix_in(P, n, NULL, 0, PG_FIX_MAX, 0, ">= 0 rad/s", &d->sleep_angular_tolerance);
    default: return read_fix_in(P, n, NULL, 0, PG_FIX_MAX, 0, ">= 0 s", &d->time_to_sleep);
    }
}

/* A body, material or shape-placement property; the value goes into *pr. */
static pg_result read_prop(scene_parser *P, const prop_info *info, props *pr)
{
    const char *n = info->name;
    pg_result r = PG_OK;
    uint64_t v = 0;
    switch (info->id) {
    case P_TYPE: return read_type(P, n, &pr->bd.type);
    case P_POSITION:
        r = read_fix_in(P, n, "x", -PG_ENV_MAX_POSITION, PG_ENV_MAX_POSITION, 0, POS_LIMIT, &pr->bd.position.x);
        return r != PG_OK ? r : read_fix_in(P, n, "y", -PG_ENV_MAX_POSITION, PG_ENV_MAX_POSITION, 0, POS_LIMIT, &pr->bd.position.y);
    case P_ANGLE: {
        pg_fix degrees = 0;
        r = read_fix(P, n, "degrees", &degrees, NULL);
        pr->angle = pg_scene_angle_from_degrees(degrees);
        return r;
    }
    case P_ANGLE_BITS:
        r = read_uint(P, n, 0xFFFFFFFFu, &v, NULL);
        pr->angle = (pg_angle)(v & 0xFFFFFFFFu);
        return r;
    case P_LINEAR_VELOCITY:
        r = read_fix(P, n, "x", &pr->bd.linear_velocity.x, NULL);
        return r != PG_OK ? r : read_fix(P, n, "y", &pr->bd.linear_velocity.y, NULL);
    case P_ANGULAR_VELOCITY:
        return read_fix_in(P, n, NULL, -PG_FIX_C(1000), PG_FIX_C(1000), 0, "-1000..1000 rad/s", &pr->bd.angular_velocity);
    case P_LINEAR_DAMPING: return read_fix_in(P, n, NULL, 0, PG_FIX_C(1000), 0, "0..1000 1/s", &pr->bd.linear_damping);
    case P_ANGULAR_DAMPING: return read_fix_in(P, n, NULL, 0, PG_FIX_C(1000), 0, "0..1000 1/s", &pr->bd.angular_damping);
    case P_GRAVITY_SCALE: return read_fix_in(P, n, NULL, -PG_FIX_C(100), PG_FIX_C(100), 0, "-100..100", &pr->bd.gravity_scale);
    case P_FIXED_ROTATION: return read_flag(P, n, &pr->bd.fixed_rotation);
    case P_ALLOW_SLEEP: return read_flag(P, n, &pr->bd.allow_sleep);
    case P_AWAKE: return read_flag(P, n, &pr->bd.awake);
    case P_USER_DATA: return read_uint(P, n, UINT64_MAX, &pr->bd.user_data, NULL);
    case P_DENSITY: return read_fix_in(P, n, NULL, 0, PG_ENV_MAX_DENSITY, 0, "0..100 kg/m^2", &pr->sd.density);
    case P_FRICTION: return read_fix_in(P, n, NULL, 0, PG_ENV_MAX_FRICTION, 0, "0..10", &pr->sd.friction);
    case P_RESTITUTION: return read_fix_in(P, n, NULL, 0, PG_FIX_ONE, 0, "0..1", &pr->sd.restitution);
    case P_CATEGORY:
        r = read_uint(P, n, 0xFFFFFFFFu, &v, NULL);
        pr->sd.category = (uint32_t)(v & 0xFFFFFFFFu);
        return r;
    case P_MASK:
        r = read_uint(P, n, 0xFFFFFFFFu, &v, NULL);
        pr->sd.mask = (uint32_t)(v & 0xFFFFFFFFu);
        return r;
    default: /* P_OFFSET */
        r = read_fix(P, n, "x", &pr->offset.x, NULL);
        return r != PG_OK ? r : read_fix(P, n, "y", &pr->offset.y, NULL);
    }
}

/* Properties up to the end of the line. `ctx` says which apply; `what` names the
 * statement in messages ("a body", "a circle shape"). pr is NULL for world settings. */
static pg_result read_props(scene_parser *P, unsigned ctx, props *pr, const char *what)
{
    for (;;) {
        token t = next_token(P);
        const prop_info *info;
        uint64_t bit;
        pg_result r;
        if (t.len == 0) return PG_OK;
        info = find_prop(P, t);
        if (info == NULL) {
            msg m = fail(P, PG_ERR_INVALID_ARGUMENT, token_column(P, t));
            pg__text_put(&m, "expected a property of ");
            pg__text_put(&m, what);
            pg__text_put(&m, ", got ");
            msg_token(&m, P, t);
            return P->result;
        }
        if ((info->ctx & ctx) == 0) {
            msg m = fail(P, PG_ERR_INVALID_ARGUMENT, token_column(P, t));
            pg__text_put(&m, "'");
            pg__text_put(&m, info->name);
            pg__text_put(&m, "' does not apply to ");
            pg__text_put(&m, what);
            return P->result;
        }
        bit = (uint64_t)1 << info->slot;
        if (pr == NULL) {
            if ((P->settings_seen & bit) != 0) {
                msg m = fail(P, PG_ERR_INVALID_ARGUMENT, token_column(P, t));
                pg__text_put(&m, "'");
                pg__text_put(&m, info->name);
                pg__text_put(&m, "' is already set on line ");
                pg__text_u64(&m, P->setting_line[info->slot]);
                return P->result;
            }
            P->settings_seen |= bit;
            P->setting_line[info->slot] = P->line;
            P->setting_column[info->slot] = token_column(P, t);
            r = read_setting(P, info);
        } else {
            if ((pr->seen & bit) != 0) {
                msg m = fail(P, PG_ERR_INVALID_ARGUMENT, token_column(P, t));
                pg__text_put(&m, "'");
                pg__text_put(&m, info->name);
                pg__text_put(&m, "' is given twice for ");
                pg__text_put(&m, what);
                return P->result;
            }
            pr->seen |= bit;
            pr->line[info->slot] = P->line;
            pr->column[info->slot] = token_column(P, peek_token(P)); /* where its value is */
            r = read_prop(P, info, pr);
        }
        if (r != PG_OK) return r;
    }
}

/* Checks that need the whole statement: velocities against the type and the speed cap,
 * density against the type. */
/* An error at a property's value (properties of a body block span lines). */
static msg fail_prop(scene_parser *P, pg_result r, const props *pr, int slot)
{
    if (pr->line[slot] != 0) P->line = pr->line[slot];
    return fail(P, r, pr->column[slot]);
}

static pg_result check_body_props(scene_parser *P, const props *pr)
{
    const pg_body_def *bd = &pr->bd;
    if (bd->type == PG_BODY_STATIC && (pr->seen & (((uint64_t)1 << P_LINEAR_VELOCITY) | ((uint64_t)1 << P_ANGULAR_VELOCITY))) != 0) {
        msg m = fail_prop(P, PG_ERR_BODY_TYPE, pr, (pr->seen & ((uint64_t)1 << P_LINEAR_VELOCITY)) != 0 ? P_LINEAR_VELOCITY : P_ANGULAR_VELOCITY);
        pg__text_put(&m, "a static body has no velocity");
        return P->result;
    }
    {
        int64_t cap = P->def.max_linear_speed;
        int64_t s2 = (int64_t)bd->linear_velocity.x * bd->linear_velocity.x + (int64_t)bd->linear_velocity.y * bd->linear_velocity.y;
        if (s2 > cap * cap) {
            msg m = fail_prop(P, PG_ERR_ENVELOPE, pr, P_LINEAR_VELOCITY);
            pg__text_put(&m, "'linear_velocity' has speed ");
            pg__text_fix(&m, pg_v2_length(bd->linear_velocity));
            pg__text_put(&m, " m/s, above max_linear_speed ");
            pg__text_fix(&m, P->def.max_linear_speed);
            return P->result;
        }
    }
    return PG_OK;
}

static pg_result check_density(scene_parser *P, const props *pr, pg_body_type type, uint32_t fallback_column)
{
    if (type == PG_BODY_DYNAMIC && pr->sd.density < PG_ENV_MIN_DENSITY)
        return fail_range(P, (pr->seen & ((uint64_t)1 << P_DENSITY)) != 0 ? pr->column[P_DENSITY] : fallback_column, "density",
                          pr->sd.density, "0.1..100 kg/m^2 (a dynamic body)");
    return PG_OK;
}

/* ---- geometry --------------------------------------------------------------------------------------- */
static pg_result fail_geometry(scene_parser *P, pg_result r, uint32_t column, const char *kind)
{
    msg m = fail(P, r, column);
    pg__text_put(&m, "the ");
    pg__text_put(&m, kind);
    switch (r) {
    case PG_ERR_DEGENERATE: pg__text_put(&m, " is degenerate: no area or length, or repeated or collinear points"); break;
    case PG_ERR_NOT_CONVEX: pg__text_put(&m, " is not convex (list the vertices of a convex polygon, either winding)"); break;
    case PG_ERR_ENVELOPE: pg__text_put(&m, " is outside the envelope: radius 0.005..50 m, at least 0.01 m thick, vertices within 1000 m of the body (50 m on a dynamic or kinematic body)"); break;
    default: pg__text_put(&m, " is invalid: "); pg__text_put(&m, pg_result_message(r)); break;
    }
    return P->result;
}

/* The geometry a ready-made kind makes (make_table[kind].shapes of them: two for a
 * star), validated as pg_make_* does (shape.c). */
static pg_result make_geometry(int kind, const pg_fix *size, pg_geometry g[2])
{
    pg_result r;
    switch (kind) {
    case 0: return pg_geometry_circle(pg_v2_zero(), size[0], &g[0]);
    case 1:
        if (size[0] < 0) return PG_ERR_DEGENERATE;
        return pg_geometry_capsule(pg_v2(-size[0] / 2, 0), pg_v2(size[0] - size[0] / 2, 0), size[1], &g[0]);
    case 3: return pg_geometry_triangle(pg_v2_zero(), size[0], PG_ANGLE_QUARTER, &g[0]);
    case 4:
        r = pg_geometry_triangle(pg_v2_zero(), size[0], PG_ANGLE_QUARTER, &g[0]);
        return r != PG_OK ? r : pg_geometry_triangle(pg_v2_zero(), size[0], PG_ANGLE_QUARTER + PG_ANGLE_HALF, &g[1]);
    default: return pg_geometry_box(size[0] / 2, size[1] / 2, pg_v2_zero(), 0, &g[0]);
    }
}

/* What pg_shape_create and pg_make_* refuse for a shape too far from the origin of a body
 * of type `type` (a static body's shapes reach farther than a moving body's), as
 * PG_ERR_ENVELOPE at `column`; PG_OK when g fits. */
static pg_result check_reach(scene_parser *P, const pg_geometry *g, pg_body_type type, uint32_t column, const char *kind)
{
    pg_fix reach = pg__geometry_reach(g);
    msg m;
    if (reach <= pg__body_reach_limit(type)) return PG_OK;
    m = fail(P, PG_ERR_ENVELOPE, column);
    pg__text_put(&m, "the ");
    pg__text_put(&m, kind);
    pg__text_put(&m, " reaches ");
    pg__text_fix(&m, reach);
    pg__text_put(&m, " m from its body's origin, beyond 50 m for a moving body (only a static body's shapes reach 1000 m)");
    return P->result;
}

/* ---- bodies -------------------------------------------------------------------------------------------- */
/* What the library cannot be told through a def: a body that starts asleep once its
 * shapes are on (adding a shape wakes it), and a static body without the awake flag. */
static void apply_awake(pg_world *world, pg_body_id id, int awake)
{
    pg_body *b = pg__body(world, id);
    if (b == NULL || awake) return;
    if (b->type == PG_BODY_STATIC) {
        b->flags &= ~(uint32_t)PG_BODY_FLAG_AWAKE;
        return;
    }
    if ((world->def.effects & PG__EFFECT(PG_EFFECT_SLEEPING)) == 0) return; /* nothing sleeps without sleeping */
    b->flags &= ~(uint32_t)PG_BODY_FLAG_AWAKE;
    b->v = pg_v2_zero();
    b->w = 0;
    b->sleep_time = 0;
    b->island = id.index;
}

static pg_result fail_world(scene_parser *P, const char *doing)
{
    msg m = fail(P, P->result, 1);
    pg__text_put(&m, doing);
    pg__text_put(&m, ": ");
    pg__text_put(&m, pg_world_last_error(P->world));
    return P->result;
}

/* Count `bodies` (0 or 1) more bodies and `shapes` more shapes; in READ mode check them
 * against the capacities the file gives. */
static pg_result count_objects(scene_parser *P, uint32_t bodies, uint32_t shapes)
{
    P->bodies = P->bodies > 0xFFFFFFFFu - bodies ? 0xFFFFFFFFu : P->bodies + bodies;
    P->shapes = P->shapes > 0xFFFFFFFFu - shapes ? 0xFFFFFFFFu : P->shapes + shapes;
    if (P->mode == MODE_READ && P->room_given && P->over_kind == 0 && (P->bodies > P->room_bodies || P->shapes > P->room_shapes)) {
        P->over_kind = P->bodies > P->room_bodies ? 1 : 2;
        P->over_line = P->line;
        P->over_count = P->over_kind == 1 ? P->bodies : P->shapes;
    }
    if (P->mode == MODE_READ && (P->settings_seen & ((uint64_t)1 << P_MAX_BODIES)) != 0 && P->bodies > P->def.max_bodies) {
        msg m = fail(P, PG_ERR_CAPACITY, 1);
        pg__text_put(&m, "body ");
        pg__text_u64(&m, P->bodies);
        pg__text_put(&m, " is beyond max_bodies ");
        pg__text_u64(&m, P->def.max_bodies);
        pg__text_put(&m, " (line ");
        pg__text_u64(&m, P->setting_line[P_MAX_BODIES]);
        pg__text_put(&m, ")");
        return P->result;
    }
    if (P->mode == MODE_READ && (P->settings_seen & ((uint64_t)1 << P_MAX_SHAPES)) != 0 && P->shapes > P->def.max_shapes) {
        msg m = fail(P, PG_ERR_CAPACITY, 1);
        pg__text_put(&m, "shape ");
        pg__text_u64(&m, P->shapes);
        pg__text_put(&m, " is beyond max_shapes ");
        pg__text_u64(&m, P->def.max_shapes);
        pg__text_put(&m, " (line ");
        pg__text_u64(&m, P->setting_line[P_MAX_SHAPES]);
        pg__text_put(&m, ")");
        return P->result;
    }
    return PG_OK;
}

/* READ: what pg_shape_create will refuse when shape `g` (the body's shape number n, from
 * 0) is added to a dynamic body: the body's mass data with its shapes so far
 * (pg__body_mass_problem), as a message, or NULL. Loading adds the shapes one by one and
 * checks each step, so reading does too. */
static const char *mass_problem(scene_parser *P, uint32_t n, const pg_geometry *g, pg_fix density, int rotates)
{
    uint32_t i;
    if (n >= 64) return NULL; /* refused before: a body has at most 64 shapes */
    pg__shape_build_local(g, &P->mass_geoms[n]);
    P->mass_densities[n] = density;
    for (i = 0; i <= n; ++i) P->mass_list[i] = &P->mass_geoms[i];
    return pg__mass_data_problem(pg_compound_mass(P->mass_list, P->mass_densities, (int)n + 1, P->mass_work), rotates);
}

/* "cannot make the <kind>: <why>" as PG_ERR_ENVELOPE at `column` of the current line. */
static pg_result fail_mass(scene_parser *P, uint32_t column, const char *kind, const char *why)
{
    msg m = fail(P, PG_ERR_ENVELOPE, column);
    pg__text_put(&m, "cannot make the ");
    pg__text_put(&m, kind);
    pg__text_put(&m, ": ");
    pg__text_put(&m, why);
    return P->result;
}

/* KIND SIZE... [properties] */
PG__OWN_FRAME pg_result parse_make(scene_parser *P, int kind, token keyword)
{
    const make_info *mk = &make_table[kind];
    pg_fix size[2] = {0, 0};
    uint32_t size_column = 0;
    props *pr = &P->item;
    pg_geometry g[2];
    pg_result r;
    int i;
    props_init(pr, kind == 5 ? PG_BODY_STATIC : PG_BODY_DYNAMIC);
    for (i = 0; i < mk->sizes; ++i) {
        uint32_t column = 0;
        r = read_fix(P, mk->size_names[i], NULL, &size[i], &column);
        if (r != PG_OK) return r;
        if (i == 0) size_column = column;
    }
    r = read_props(P, CTX_BODY | CTX_TYPE | CTX_MATERIAL, pr, mk->name);
    if (r != PG_OK) return r;
    if (kind == 5 && pr->bd.type != PG_BODY_STATIC) {
        msg m = fail(P, PG_ERR_BODY_TYPE, pr->column[P_TYPE]);
        pg__text_put(&m, "a wall is always static");
        return P->result;
    }
    pr->bd.angle = pr->angle;
    r = check_body_props(P, pr);
    if (r == PG_OK) r = check_density(P, pr, pr->bd.type, token_column(P, keyword));
    if (r != PG_OK) return r;
    r = make_geometry(kind, size, g);
    if (r != PG_OK) return fail_geometry(P, r, size_column, mk->name);
    for (i = 0; i < (int)mk->shapes; ++i) {
        r = check_reach(P, &g[i], pr->bd.type, size_column, mk->name);
        if (r != PG_OK) return r;
    }
    if (P->mode == MODE_READ && pr->bd.type == PG_BODY_DYNAMIC) { /* pg_make_* checks the whole body, then each shape as it adds it */
        uint32_t k;
        for (k = 0; k < mk->shapes; ++k) {
            const char *why = mass_problem(P, k, &g[k], pr->sd.density, !pr->bd.fixed_rotation);
            if (why != NULL) return fail_mass(P, size_column, mk->name, why);
        }
    }
    r = count_objects(P, 1, mk->shapes);
    if (r != PG_OK || P->mode == MODE_READ) return r;
    {
        pg_body_id id;
        switch (kind) {
        case 0: r = pg_make_ball(P->world, &pr->bd, &pr->sd, size[0], &id); break;
        case 1: r = pg_make_capsule(P->world, &pr->bd, &pr->sd, size[0], size[1], &id); break;
        case 2: r = pg_make_box(P->world, &pr->bd, &pr->sd, size[0], size[1], &id); break;
        case 3: r = pg_make_triangle(P->world, &pr->bd, &pr->sd, size[0], &id); break;
        case 4: r = pg_make_star(P->world, &pr->bd, &pr->sd, size[0], &id); break;
        default: r = pg_make_wall(P->world, &pr->bd, &pr->sd, size[0], size[1], &id); break;
        }
        if (r != PG_OK) {
            P->result = r;
            return fail_world(P, "cannot make the body");
        }
        apply_awake(P->world, id, pr->bd.awake);
    }
    return PG_OK;
}

/* ---- concave polygons and chains ----------------------------------------------------------------------------- */
/* X Y pairs up to the first token that is not a number: at most `max` points. */
static pg_result read_points(scene_parser *P, const char *what, pg_vec2 *v, int32_t max, int32_t *n, uint32_t *column)
{
    pg_result r = PG_OK;
    *n = 0;
    *column = token_column(P, peek_token(P));
    while (r == PG_OK && looks_numeric(P, peek_token(P))) {
        if (*n == max) {
            msg m = fail(P, PG_ERR_INVALID_ARGUMENT, token_column(P, peek_token(P)));
            pg__text_put(&m, "a ");
            pg__text_put(&m, what);
            pg__text_put(&m, " has at most ");
            pg__text_i64(&m, max);
            pg__text_put(&m, " points");
            return P->result;
        }
        r = read_fix(P, what, "x", &v[*n].x, NULL);
        if (r == PG_OK) r = read_fix(P, what, "y", &v[*n].y, NULL);
        ++*n;
    }
    return r;
}

/* "the WHAT: DETAIL" as code r at `column`. */
static pg_result fail_detail(scene_parser *P, pg_result r, uint32_t column, const char *what, const char *detail)
{
    msg m = fail(P, r, column);
    pg__text_put(&m, "the ");
    pg__text_put(&m, what);
    pg__text_put(&m, ": ");
    pg__text_put(&m, detail);
    return P->result;
}

/* The concave polygon of n points in P->points, with the line's properties in P->item:
 * its decomposition (into P->pieces), each piece within reach, and in READ the whole
 * dynamic body's mass. */
PG__OWN_FRAME pg_result check_concave_pieces(scene_parser *P, int32_t n, uint32_t column)
{
    const props *pr = &P->item;
    const pg__decomposition *d = &P->pieces;
    pg__text why = pg__text_in(P->why, sizeof P->why);
    int32_t k;
    pg_result r = pg__decompose(P->points, n, &P->pieces, &why);
    if (r != PG_OK) return fail_detail(P, r, column, "concave polygon", P->why);
    for (k = 0; k < d->count; ++k) {
        pg_geometry g;
        pg__piece_geometry(P->points, &d->pieces[k], &g);
        r = check_reach(P, &g, pr->bd.type, column, "concave polygon");
        if (r != PG_OK) return r;
        pg__shape_build_local(&g, &P->mass_geoms[k]);
        P->mass_densities[k] = pr->sd.density;
    }
    if (P->mode == MODE_READ && pr->bd.type == PG_BODY_DYNAMIC) {
        const char *problem;
        for (k = 0; k < d->count; ++k) P->mass_list[k] = &P->mass_geoms[k];
        problem = pg__mass_data_problem(pg_compound_mass(P->mass_list, P->mass_densities, d->count, P->mass_work), !pr->bd.fixed_rotation);
        if (problem != NULL) return fail_mass(P, column, "concave polygon", problem);
    }
    return PG_OK;
}

/* concave X1 Y1 X2 Y2 ... [properties]: a body of the polygon's convex pieces, as
 * pg_make_concave makes it (checked as it checks: the pieces, their reach, the whole
 * body's mass). */
PG__OWN_FRAME pg_result parse_concave(scene_parser *P, token keyword)
{
    pg_vec2 *v = P->points;
    int32_t n = 0;
    uint32_t column = 0;
    props *pr = &P->item;
    pg_result r;
    props_init(pr, PG_BODY_DYNAMIC);
    r = read_points(P, "concave polygon", v, PG_CONCAVE_MAX_VERTICES, &n, &column);
    if (r == PG_OK) r = read_props(P, CTX_BODY | CTX_TYPE | CTX_MATERIAL, pr, "concave");
    if (r != PG_OK) return r;
    pr->bd.angle = pr->angle;
    r = check_body_props(P, pr);
    if (r == PG_OK) r = check_density(P, pr, pr->bd.type, token_column(P, keyword));
    if (r != PG_OK) return r;
    r = check_concave_pieces(P, n, column);
    if (r != PG_OK) return r;
    r = count_objects(P, 1, (uint32_t)P->pieces.count);
    if (r != PG_OK || P->mode == MODE_READ) return r;
    {
        pg_body_id id;
        r = pg_make_concave(P->world, &pr->bd, &pr->sd, v, n, &id);
        if (r != PG_OK) {
            P->result = r;
            return fail_world(P, "cannot make the body");
        }
        apply_awake(P->world, id, pr->bd.awake);
    }
    return PG_OK;
}

/* chain X1 Y1 X2 Y2 ... [loop] [properties]: static terrain, as pg_make_chain makes it. */
PG__OWN_FRAME pg_result parse_chain(scene_parser *P, token keyword)
{
    pg_vec2 *v = P->points;
    pg__text why = pg__text_in(P->why, sizeof P->why);
    int32_t n = 0, k;
    int loop = 0;
    uint32_t column = 0;
    props *pr = &P->item;
    pg_result r;
    props_init(pr, PG_BODY_STATIC);
    r = read_points(P, "chain", v, PG_CHAIN_MAX_POINTS, &n, &column);
    if (r != PG_OK) return r;
    if (token_is(P, peek_token(P), "loop")) {
        (void)next_token(P);
        loop = 1;
    }
    r = read_props(P, CTX_BODY | CTX_TYPE | CTX_MATERIAL, pr, "chain");
    if (r != PG_OK) return r;
    if (pr->bd.type != PG_BODY_STATIC) {
        msg m = fail(P, PG_ERR_BODY_TYPE, pr->column[P_TYPE]);
        pg__text_put(&m, "a chain is always static");
        return P->result;
    }
    pr->bd.angle = pr->angle;
    r = check_body_props(P, pr);
    if (r == PG_OK) r = check_density(P, pr, pr->bd.type, token_column(P, keyword));
    if (r != PG_OK) return r;
    r = pg__chain_problem(v, n, loop, &why);
    if (r != PG_OK) return fail_detail(P, r, column, "chain", P->why);
    for (k = 0; k < (loop ? n : n - 1); ++k) {
        pg_geometry g;
        pg__chain_segment(v, n, loop, k, &g);
        r = check_reach(P, &g, PG_BODY_STATIC, column, "chain");
        if (r != PG_OK) return r;
    }
    r = count_objects(P, 1, (uint32_t)(loop ? n : n - 1));
    if (r != PG_OK || P->mode == MODE_READ) return r;
    {
        pg_body_id id;
        r = pg_make_chain(P->world, &pr->bd, &pr->sd, v, n, loop, &id);
        if (r != PG_OK) {
            P->result = r;
            return fail_world(P, "cannot make the body");
        }
        apply_awake(P->world, id, pr->bd.awake);
    }
    return PG_OK;
}

/* body TYPE [properties] */
static pg_result parse_body_line(scene_parser *P)
{
    pg_body_type type = PG_BODY_STATIC;
    pg_result r = read_type(P, "body", &type);
    if (r != PG_OK) return r;
    props_init(&P->body, type);
    P->in_body = 1;
    P->body_line = P->line;
    P->body_shapes = 0;
    P->body_made = 0;
    r = count_objects(P, 1, 0);
    if (r != PG_OK) return r;
    return read_props(P, CTX_BODY, &P->body, "a body");
}

/* The open body's properties are complete (at its first shape or at 'end'): check them
 * and, when loading, create the body. */
static pg_result make_open_body(scene_parser *P)
{
    pg_result r;
    if (P->body_shapes == 0) {
        r = check_body_props(P, &P->body);
        if (r != PG_OK) return r;
    }
    if (P->mode == MODE_READ || P->body_made) return PG_OK;
    P->body.bd.angle = P->body.angle;
    r = pg_body_create(P->world, &P->body.bd, &P->body_id);
    if (r != PG_OK) {
        P->result = r;
        return fail_world(P, "cannot create the body");
    }
    P->body_made = 1;
    return PG_OK;
}

/* shape KIND GEOMETRY... [properties] */
static pg_result parse_shape(scene_parser *P)
{
    static const char *const kinds[6] = {"circle", "segment", "capsule", "box", "polygon", "chain_segment"};
    static const char *const whats[6] = {"a circle shape", "a segment shape", "a capsule shape", "a box shape", "a polygon shape",
                                         "a chain segment shape"};
    static const char *const parts[8][2] = {{"vertex 1 x", "vertex 1 y"}, {"vertex 2 x", "vertex 2 y"}, {"vertex 3 x", "vertex 3 y"},
                                            {"vertex 4 x", "vertex 4 y"}, {"vertex 5 x", "vertex 5 y"}, {"vertex 6 x", "vertex 6 y"},
                                            {"vertex 7 x", "vertex 7 y"}, {"vertex 8 x", "vertex 8 y"}};
    token kt = next_token(P);
    uint32_t kind_column = token_column(P, kt);
    int kind;
    pg_fix a[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    pg_vec2 v[PG_MAX_VERTICES];
    int32_t count = 0;
    unsigned ctx = CTX_MATERIAL;
    props pr;
    pg_geometry g;
    pg_result r = PG_OK;
    for (kind = 0; kind < 6; ++kind)
        if (token_is(P, kt, kinds[kind])) break;
    if (kind == 6) return fail_expected(P, kt, "a shape kind (circle, segment, capsule, box, polygon or chain_segment)", NULL, NULL);
    props_init(&pr, P->body.bd.type);
    switch (kind) {
    case 0:
        r = read_fix(P, "circle", "radius", &a[0], NULL);
        ctx |= CTX_OFFSET;
        break;
    case 1:
    case 2: {
        static const char *const names[5] = {"x1", "y1", "x2", "y2", "radius"};
        int i;
        for (i = 0; r == PG_OK && i < (kind == 1 ? 4 : 5); ++i) r = read_fix(P, kinds[kind], names[i], &a[i], NULL);
        break;
    }
    case 3:
        r = read_fix(P, "box", "width", &a[0], NULL);
        if (r == PG_OK) r = read_fix(P, "box", "height", &a[1], NULL);
        ctx |= CTX_OFFSET | CTX_SHAPE_ANGLE;
        break;
    case 5: { /* the neighbour before, the segment, the neighbour after */
        static const char *const names[8] = {"before x", "before y", "x1", "y1", "x2", "y2", "after x", "after y"};
        int i;
        for (i = 0; r == PG_OK && i < 8; ++i) r = read_fix(P, kinds[kind], names[i], &a[i], NULL);
        break;
    }
    default:
        while (r == PG_OK && looks_numeric(P, peek_token(P))) {
            if (count == PG_MAX_VERTICES) {
                msg m = fail(P, PG_ERR_INVALID_ARGUMENT, token_column(P, peek_token(P)));
                pg__text_put(&m, "a polygon has at most 8 vertices; this is vertex 9");
                return P->result;
            }
            r = read_fix(P, "polygon", parts[count][0], &v[count].x, NULL);
            if (r == PG_OK) r = read_fix(P, "polygon", parts[count][1], &v[count].y, NULL);
            ++count;
        }
        if (r == PG_OK && count < 3) {
            msg m = fail(P, PG_ERR_INVALID_ARGUMENT, kind_column);
            pg__text_put(&m, "a polygon needs 3 to 8 vertices (x y pairs), got ");
            pg__text_u64(&m, (uint64_t)count);
            return P->result;
        }
        break;
    }
    if (r != PG_OK) return r;
    r = read_props(P, ctx, &pr, whats[kind]);
    if (r != PG_OK) return r;
    r = check_density(P, &pr, P->body.bd.type, kind_column);
    if (r != PG_OK) return r;
    switch (kind) {
    case 0: r = pg_geometry_circle(pr.offset, a[0], &g); break;
    case 1: r = pg_geometry_segment(pg_v2(a[0], a[1]), pg_v2(a[2], a[3]), &g); break;
    case 2: r = pg_geometry_capsule(pg_v2(a[0], a[1]), pg_v2(a[2], a[3]), a[4], &g); break;
    case 3: r = pg_geometry_box(a[0] / 2, a[1] / 2, pr.offset, pr.angle, &g); break;
    case 5: r = pg_geometry_chain_segment(pg_v2(a[0], a[1]), pg_v2(a[2], a[3]), pg_v2(a[4], a[5]), pg_v2(a[6], a[7]), &g); break;
    default: r = pg_geometry_polygon(v, count, &g); break;
    }
    if (r != PG_OK) return fail_geometry(P, r, kind_column, kinds[kind]);
    if (kind == 5 && P->body.bd.type != PG_BODY_STATIC) {
        msg m = fail(P, PG_ERR_BODY_TYPE, kind_column);
        pg__text_put(&m, "chain segments go on static bodies only");
        return P->result;
    }
    r = check_reach(P, &g, P->body.bd.type, kind_column, kinds[kind]);
    if (r != PG_OK) return r;
    if (P->body_shapes >= 64) {
        msg m = fail(P, PG_ERR_CAPACITY, 1);
        pg__text_put(&m, "a body has at most 64 shapes (body of line ");
        pg__text_u64(&m, P->body_line);
        pg__text_put(&m, ")");
        return P->result;
    }
    r = make_open_body(P);
    if (r != PG_OK) return r;
    if (P->mode == MODE_READ && P->body.bd.type == PG_BODY_DYNAMIC) {
        const char *why = mass_problem(P, P->body_shapes, &g, pr.sd.density, !P->body.bd.fixed_rotation);
        if (why != NULL) {
            msg m = fail(P, PG_ERR_ENVELOPE, kind_column);
            pg__text_put(&m, "cannot add the ");
            pg__text_put(&m, kinds[kind]);
            pg__text_put(&m, " to the body of line ");
            pg__text_u64(&m, P->body_line);
            pg__text_put(&m, ": ");
            pg__text_put(&m, why);
            return P->result;
        }
    }
    P->body_shapes += 1u;
    r = count_objects(P, 0, 1);
    if (r != PG_OK || P->mode == MODE_READ) return r;
    {
        pg_shape_id sid;
        r = pg_shape_create(P->world, P->body_id, &pr.sd, &g, &sid);
        if (r != PG_OK) {
            P->result = r;
            (void)fail_world(P, "cannot add the shape");
            (void)pg_body_destroy(P->world, P->body_id); /* no partly built body */
            P->body_made = 0;
            return P->result;
        }
    }
    return PG_OK;
}

static pg_result end_body(scene_parser *P)
{
    pg_result r = make_open_body(P);
    if (r != PG_OK) return r;
    if (P->mode == MODE_LOAD) apply_awake(P->world, P->body_id, P->body.bd.awake);
    P->in_body = 0;
    return PG_OK;
}

/* ---- statements ------------------------------------------------------------------------------------------ */
PG__OWN_FRAME pg_result parse_header(scene_parser *P)
{
    token t = next_token(P), version;
    msg m;
    if (!token_is(P, t, PG_SCENE_MAGIC)) {
        if (t.len == 0) P->last_end = P->line_start;
        return fail_expected(P, t, "'pogon-scene 1' as the first line", NULL, NULL);
    }
    version = next_token(P);
    if (token_is(P, version, "1")) return expect_end_of_line(P, "the version line");
    if (version.len != 0 && P->text[version.start] >= '0' && P->text[version.start] <= '9') {
        m = fail(P, PG_ERR_INVALID_ARGUMENT, token_column(P, version));
        pg__text_put(&m, "unsupported version ");
        msg_token(&m, P, version);
        pg__text_put(&m, ": this reader knows version 1");
        return P->result;
    }
    return fail_expected(P, version, "the format version (1) after 'pogon-scene'", NULL, NULL);
}

static int make_kind_of(const scene_parser *P, token t)
{
    int i;
    for (i = 0; i < 6; ++i)
        if (token_is(P, t, make_table[i].name)) return i;
    return -1;
}

/* ---- joints ------------------------------------------------------------------------------------------------ */
/* joint KIND A B [properties]   (mouse: joint mouse B [properties])
 * A and B are body numbers: the file's bodies counted from 0 in file order, each above
 * the joint line. Property names are the fields of the kind's def (pogon/joint.h);
 * anchors are in each body's frame, as the defs take them. */
enum jprop_id {
    J_LOCAL_ANCHOR_A, J_LOCAL_ANCHOR_B, J_LENGTH, J_ENABLE_SPRING, J_HERTZ, J_DAMPING_RATIO,
    J_ENABLE_LIMIT, J_MIN_LENGTH, J_MAX_LENGTH, J_REFERENCE_ANGLE, J_LOWER_ANGLE, J_UPPER_ANGLE,
    J_ENABLE_MOTOR, J_MOTOR_SPEED, J_MAX_MOTOR_TORQUE, J_LINEAR_HERTZ, J_LINEAR_DAMPING_RATIO,
    J_ANGULAR_HERTZ, J_ANGULAR_DAMPING_RATIO, J_LOCAL_AXIS_A, J_LOWER_TRANSLATION,
    J_UPPER_TRANSLATION, J_MAX_MOTOR_FORCE, J_TARGET, J_MAX_FORCE, J_COLLIDE_CONNECTED, J_USER_DATA,
    J_REFERENCE_ANGLE_BITS, /* shares the slot of J_REFERENCE_ANGLE */
    J_COUNT
};
#define JK_D (1u << PG_JOINT_DISTANCE)
#define JK_R (1u << PG_JOINT_REVOLUTE)
#define JK_W (1u << PG_JOINT_WELD)
#define JK_P (1u << PG_JOINT_PRISMATIC)
#define JK_M (1u << PG_JOINT_MOUSE)
#define JK_TWO (JK_D | JK_R | JK_W | JK_P) /* the kinds that join two bodies */

typedef struct jprop_info {
    const char *name;
    uint8_t id, slot, kinds;
} jprop_info;

static const jprop_info jprops_table[] = {
    {"local_anchor_a", J_LOCAL_ANCHOR_A, J_LOCAL_ANCHOR_A, JK_TWO},
    {"local_anchor_b", J_LOCAL_ANCHOR_B, J_LOCAL_ANCHOR_B, JK_TWO | JK_M},
    {"length", J_LENGTH, J_LENGTH, JK_D},
    {"enable_spring", J_ENABLE_SPRING, J_ENABLE_SPRING, JK_D},
    {"hertz", J_HERTZ, J_HERTZ, JK_D | JK_M},
    {"damping_ratio", J_DAMPING_RATIO, J_DAMPING_RATIO, JK_D | JK_M},
    {"enable_limit", J_ENABLE_LIMIT, J_ENABLE_LIMIT, JK_D | JK_R | JK_P},
    {"min_length", J_MIN_LENGTH, J_MIN_LENGTH, JK_D},
    {"max_length", J_MAX_LENGTH, J_MAX_LENGTH, JK_D},
    {"reference_angle", J_REFERENCE_ANGLE, J_REFERENCE_ANGLE, JK_R | JK_W | JK_P},
    {"reference_angle_bits", J_REFERENCE_ANGLE_BITS, J_REFERENCE_ANGLE, JK_R | JK_W | JK_P},
    {"lower_angle", J_LOWER_ANGLE, J_LOWER_ANGLE, JK_R},
    {"upper_angle", J_UPPER_ANGLE, J_UPPER_ANGLE, JK_R},
    {"enable_motor", J_ENABLE_MOTOR, J_ENABLE_MOTOR, JK_R | JK_P},
    {"motor_speed", J_MOTOR_SPEED, J_MOTOR_SPEED, JK_R | JK_P},
    {"max_motor_torque", J_MAX_MOTOR_TORQUE, J_MAX_MOTOR_TORQUE, JK_R},
    {"linear_hertz", J_LINEAR_HERTZ, J_LINEAR_HERTZ, JK_W},
    {"linear_damping_ratio", J_LINEAR_DAMPING_RATIO, J_LINEAR_DAMPING_RATIO, JK_W},
    {"angular_hertz", J_ANGULAR_HERTZ, J_ANGULAR_HERTZ, JK_W},
    {"angular_damping_ratio", J_ANGULAR_DAMPING_RATIO, J_ANGULAR_DAMPING_RATIO, JK_W},
    {"local_axis_a", J_LOCAL_AXIS_A, J_LOCAL_AXIS_A, JK_P},
    {"lower_translation", J_LOWER_TRANSLATION, J_LOWER_TRANSLATION, JK_P},
    {"upper_translation", J_UPPER_TRANSLATION, J_UPPER_TRANSLATION, JK_P},
    {"max_motor_force", J_MAX_MOTOR_FORCE, J_MAX_MOTOR_FORCE, JK_P},
    {"target", J_TARGET, J_TARGET, JK_M},
    {"max_force", J_MAX_FORCE, J_MAX_FORCE, JK_M},
    {"collide_connected", J_COLLIDE_CONNECTED, J_COLLIDE_CONNECTED, JK_TWO},
    {"user_data", J_USER_DATA, J_USER_DATA, JK_TWO | JK_M},
};
#define JPROPS_TABLE_COUNT (sizeof jprops_table / sizeof jprops_table[0])

static const char *const joint_kind_names[PG_JOINT_TYPE_COUNT] = {"distance", "revolute", "weld", "prismatic", "mouse"};

#define JOINT_LENGTH_MIN ((pg_fix)328) /* 0.005 m, as pg_distance_joint_create */
#define JOINT_LENGTH_MAX PG_FIX_C(100)

/* One joint line: the kind's fields, named as in the defs, in one struct (the pg_joint
 * layout: lower/upper hold min/max length, angles or translations; max_motor the
 * torque, force or mouse force; hertz2/damping2 the weld's angular softness). */
typedef struct joint_line {
    pg_joint_type kind;
    uint32_t body[2];          /* body numbers; a mouse joint has body[1] only */
    uint32_t body_column[2];
    uint32_t seen, column[J_COUNT];
    pg_vec2 anchor_a, anchor_b, axis, target;
    pg_angle reference_angle;
    pg_fix length, hertz, damping, hertz2, damping2, lower, upper, motor_speed, max_motor;
    int enable_spring, enable_limit, enable_motor, collide;
    uint64_t user_data;
} joint_line;

static void joint_line_init(joint_line *J, pg_joint_type kind)
{
    size_t i;
    unsigned char *p = (unsigned char *)J;
    for (i = 0; i < sizeof *J; ++i) p[i] = 0;
    J->kind = kind;
    J->axis = pg_v2(PG_FIX_ONE, 0);
    J->length = PG_FIX_ONE;
    if (kind == PG_JOINT_DISTANCE) J->upper = JOINT_LENGTH_MAX;
    if (kind == PG_JOINT_MOUSE) {
        pg_mouse_joint_def md = pg_default_mouse_joint_def();
        J->hertz = md.hertz;
        J->damping = md.damping_ratio;
        J->max_motor = md.max_force;
    }
}

static const jprop_info *find_jprop(const scene_parser *P, token t)
{
    size_t i;
    for (i = 0; i < JPROPS_TABLE_COUNT; ++i)
        if (token_is(P, t, jprops_table[i].name)) return &jprops_table[i];
    return NULL;
}

static pg_result read_vec(scene_parser *P, const char *name, pg_vec2 *out)
{
    pg_result r = read_fix(P, name, "x", &out->x, NULL);
    return r != PG_OK ? r : read_fix(P, name, "y", &out->y, NULL);
}

static pg_result read_jprop(scene_parser *P, const jprop_info *info, joint_line *J)
{
    const char *n = info->name;
    const pg_fix K = PG_FIX_C(1000);
    pg_result r;
    uint64_t v = 0;
    switch (info->id) {
    case J_LOCAL_ANCHOR_A: return read_vec(P, n, &J->anchor_a);
    case J_LOCAL_ANCHOR_B: return read_vec(P, n, &J->anchor_b);
    case J_LENGTH: return read_fix_in(P, n, NULL, JOINT_LENGTH_MIN, JOINT_LENGTH_MAX, 0, "0.005..100 m", &J->length);
    case J_ENABLE_SPRING: return read_flag(P, n, &J->enable_spring);
    case J_HERTZ:
        if (J->kind == PG_JOINT_MOUSE) return read_fix_in(P, n, NULL, 0, K, 1, "(0, 1000] Hz", &J->hertz);
        return read_fix_in(P, n, NULL, 0, K, 0, "0..1000 Hz", &J->hertz);
    case J_DAMPING_RATIO: return read_fix_in(P, n, NULL, 0, K, 0, "0..1000", &J->damping);
    case J_ENABLE_LIMIT: return read_flag(P, n, &J->enable_limit);
    case J_MIN_LENGTH: return read_fix_in(P, n, NULL, 0, JOINT_LENGTH_MAX, 0, "0..100 m", &J->lower);
    case J_MAX_LENGTH: return read_fix_in(P, n, NULL, 0, JOINT_LENGTH_MAX, 0, "0..100 m", &J->upper);
    case J_REFERENCE_ANGLE: {
        pg_fix degrees = 0;
        r = read_fix(P, n, "degrees", &degrees, NULL);
        J->reference_angle = pg_scene_angle_from_degrees(degrees);
        return r;
    }
    case J_REFERENCE_ANGLE_BITS:
        r = read_uint(P, n, 0xFFFFFFFFu, &v, NULL);
        J->reference_angle = (pg_angle)(v & 0xFFFFFFFFu);
        return r;
    case J_LOWER_ANGLE: return read_fix_in(P, n, NULL, -PG_FIX_PI, PG_FIX_PI, 0, "-pi..pi rad", &J->lower);
    case J_UPPER_ANGLE: return read_fix_in(P, n, NULL, -PG_FIX_PI, PG_FIX_PI, 0, "-pi..pi rad", &J->upper);
    case J_ENABLE_MOTOR: return read_flag(P, n, &J->enable_motor);
    case J_MOTOR_SPEED: return read_fix_in(P, n, NULL, -K, K, 0, "-1000..1000", &J->motor_speed);
    case J_MAX_MOTOR_TORQUE: return read_fix_in(P, n, NULL, 0, PG_FIX_MAX, 0, ">= 0 N m", &J->max_motor);
    case J_LINEAR_HERTZ: return read_fix_in(P, n, NULL, 0, K, 0, "0..1000 Hz", &J->hertz);
    case J_LINEAR_DAMPING_RATIO: return read_fix_in(P, n, NULL, 0, K, 0, "0..1000", &J->damping);
    case J_ANGULAR_HERTZ: return read_fix_in(P, n, NULL, 0, K, 0, "0..1000 Hz", &J->hertz2);
    case J_ANGULAR_DAMPING_RATIO: return read_fix_in(P, n, NULL, 0, K, 0, "0..1000", &J->damping2);
    case J_LOCAL_AXIS_A: return read_vec(P, n, &J->axis);
    case J_LOWER_TRANSLATION: return read_fix_in(P, n, NULL, -JOINT_LENGTH_MAX, JOINT_LENGTH_MAX, 0, "-100..100 m", &J->lower);
    case J_UPPER_TRANSLATION: return read_fix_in(P, n, NULL, -JOINT_LENGTH_MAX, JOINT_LENGTH_MAX, 0, "-100..100 m", &J->upper);
    case J_MAX_MOTOR_FORCE: return read_fix_in(P, n, NULL, 0, PG_FIX_MAX, 0, ">= 0 N", &J->max_motor);
    case J_TARGET:
        r = read_fix_in(P, n, "x", -PG_ENV_MAX_POSITION, PG_ENV_MAX_POSITION, 0, POS_LIMIT, &J->target.x);
        return r != PG_OK ? r : read_fix_in(P, n, "y", -PG_ENV_MAX_POSITION, PG_ENV_MAX_POSITION, 0, POS_LIMIT, &J->target.y);
    case J_MAX_FORCE: return read_fix_in(P, n, NULL, 0, PG_FIX_MAX, 0, ">= 0 N", &J->max_motor);
    case J_COLLIDE_CONNECTED: return read_flag(P, n, &J->collide);
    default: return read_uint(P, n, UINT64_MAX, &J->user_data, NULL); /* J_USER_DATA */
    }
}

static pg_result read_jprops(scene_parser *P, joint_line *J)
{
    for (;;) {
        token t = next_token(P);
        const jprop_info *info;
        msg m;
        if (t.len == 0) return PG_OK;
        info = find_jprop(P, t);
        if (info == NULL || (info->kinds & (1u << J->kind)) == 0) {
            m = fail(P, PG_ERR_INVALID_ARGUMENT, token_column(P, t));
            pg__text_put(&m, "expected a property of a ");
            pg__text_put(&m, joint_kind_names[J->kind]);
            pg__text_put(&m, " joint, got ");
            msg_token(&m, P, t);
            return P->result;
        }
        if ((J->seen & (1u << info->slot)) != 0) {
            m = fail(P, PG_ERR_INVALID_ARGUMENT, token_column(P, t));
            pg__text_put(&m, "'");
            pg__text_put(&m, info->name);
            pg__text_put(&m, "' is given twice for a joint");
            return P->result;
        }
        J->seen |= 1u << info->slot;
        J->column[info->slot] = token_column(P, peek_token(P));
        {
            pg_result r = read_jprop(P, info, J);
            if (r != PG_OK) return r;
        }
    }
}

/* The type of the file's body number k (above the current line), found by reading the
 * text again from its start: the reader keeps no table of bodies (it allocates nothing
 * and a scene may hold 2^24 bodies). The text up to here has been checked already. */
static pg_body_type scene_body_type(scene_parser *P, uint32_t k)
{
    const size_t next_line = P->next_line, line_start = P->line_start, line_end = P->line_end;
    const size_t content_end = P->content_end, at = P->at, last_end = P->last_end;
    const uint32_t line = P->line;
    uint32_t count = 0;
    int in_block = 0, i;
    pg_body_type type = PG_BODY_DYNAMIC;
    P->next_line = 0;
    P->line = 0;
    while (P->line + 1u < line && load_line(P) > 0) {
        token t = next_token(P);
        int kind;
        if (P->line == 1 || t.len == 0) continue;
        if (in_block) {
            if (token_is(P, t, "end")) in_block = 0;
            continue;
        }
        if (token_is(P, t, "body")) {
            if (count == k) {
                token ty = next_token(P);
                for (i = 0; i < 3; ++i)
                    if (token_is(P, ty, type_names[i])) type = (pg_body_type)i;
                break;
            }
            in_block = 1;
            ++count;
            continue;
        }
        kind = make_kind_of(P, t);
        if (kind < 0) continue;
        if (count == k) {
            type = kind == 5 ? PG_BODY_STATIC : PG_BODY_DYNAMIC;
            for (t = next_token(P); t.len != 0; t = next_token(P))
                if (token_is(P, t, "type")) {
                    token ty = next_token(P);
                    for (i = 0; i < 3; ++i)
                        if (token_is(P, ty, type_names[i])) type = (pg_body_type)i;
                }
            break;
        }
        ++count;
    }
    P->next_line = next_line;
    P->line_start = line_start;
    P->line_end = line_end;
    P->content_end = content_end;
    P->at = at;
    P->last_end = last_end;
    P->line = line;
    return type;
}

static pg_result fail_joint(scene_parser *P, pg_result r, uint32_t column, const char *what)
{
    msg m = fail(P, r, column);
    pg__text_put(&m, what);
    return P->result;
}

static pg_result check_joint_anchor(scene_parser *P, const joint_line *J, int slot, pg_vec2 a, pg_body_type type)
{
    pg_fix limit = type == PG_BODY_STATIC ? PG_ENV_MAX_POSITION : PG_FIX_C(50);
    if (a.x < -limit || a.x > limit || a.y < -limit || a.y > limit) {
        msg m = fail(P, PG_ERR_ENVELOPE, J->column[slot]);
        pg__text_put(&m, slot == J_LOCAL_ANCHOR_A ? "'local_anchor_a'" : "'local_anchor_b'");
        pg__text_put(&m, type == PG_BODY_STATIC ? " is beyond 1000 m of its static body's origin"
                                                : " is beyond 50 m of its moving body's origin");
        return P->result;
    }
    return PG_OK;
}

/* READ: what the create call would refuse, found from the text alone. */
static pg_result check_joint_line(scene_parser *P, const joint_line *J)
{
    pg_body_type ta = PG_BODY_STATIC, tb = scene_body_type(P, J->body[1]);
    pg_result r;
    if (J->kind == PG_JOINT_MOUSE) {
        if (tb != PG_BODY_DYNAMIC) return fail_joint(P, PG_ERR_BODY_TYPE, J->body_column[1], "a mouse joint's body must be dynamic");
        return check_joint_anchor(P, J, J_LOCAL_ANCHOR_B, J->anchor_b, tb);
    }
    if (J->body[0] == J->body[1]) return fail_joint(P, PG_ERR_INVALID_ARGUMENT, J->body_column[1], "a joint joins two different bodies");
    ta = scene_body_type(P, J->body[0]);
    if (ta == PG_BODY_STATIC && tb == PG_BODY_STATIC)
        return fail_joint(P, PG_ERR_BODY_TYPE, J->body_column[0], "both bodies are static: at least one must be able to move");
    if ((r = check_joint_anchor(P, J, J_LOCAL_ANCHOR_A, J->anchor_a, ta)) != PG_OK) return r;
    if ((r = check_joint_anchor(P, J, J_LOCAL_ANCHOR_B, J->anchor_b, tb)) != PG_OK) return r;
    if (J->lower > J->upper && J->kind != PG_JOINT_WELD) {
        static const int lower_slot[PG_JOINT_TYPE_COUNT] = {J_MIN_LENGTH, J_LOWER_ANGLE, 0, J_LOWER_TRANSLATION, 0};
        static const char *const what[PG_JOINT_TYPE_COUNT] = {"'min_length' is above 'max_length'", "'lower_angle' is above 'upper_angle'", "",
                                                              "'lower_translation' is above 'upper_translation'", ""};
        return fail_joint(P, PG_ERR_INVALID_ARGUMENT, J->column[lower_slot[J->kind]] != 0 ? J->column[lower_slot[J->kind]] : 1u, what[J->kind]);
    }
    if (J->kind == PG_JOINT_PRISMATIC) {
        int64_t x = J->axis.x, y = J->axis.y;
        if (J->axis.x < PG_FIX_MIN || J->axis.y < PG_FIX_MIN || pg__sqrt_nearest((uint64_t)(x * x + y * y)) < 66u)
            return fail_joint(P, PG_ERR_DEGENERATE, J->column[J_LOCAL_AXIS_A], "'local_axis_a' has no direction: give a nonzero vector");
    }
    return PG_OK;
}

/* LOAD: the handle of the file's body number k. pg_scene_load refuses a scene with
 * joints unless the world's body slots are used without gaps, so the file's bodies took
 * the slots from body_base up. */
static pg_body_id scene_body_id(const scene_parser *P, uint32_t k)
{
    pg_body_id id;
    id.index = P->body_base + k;
    id.generation = P->world->bodies[id.index].generation;
    return id;
}

static pg_result make_joint(scene_parser *P, const joint_line *J)
{
    pg_world *w = P->world;
    pg_joint_id id;
    pg_result r;
    pg_body_id a = scene_body_id(P, J->body[0]), b = scene_body_id(P, J->body[1]);
    switch (J->kind) {
    case PG_JOINT_DISTANCE: {
        pg_distance_joint_def d = pg_default_distance_joint_def();
        d.body_a = a, d.body_b = b, d.local_anchor_a = J->anchor_a, d.local_anchor_b = J->anchor_b;
        d.length = J->length, d.enable_spring = J->enable_spring, d.hertz = J->hertz, d.damping_ratio = J->damping;
        d.enable_limit = J->enable_limit, d.min_length = J->lower, d.max_length = J->upper;
        d.collide_connected = J->collide, d.user_data = J->user_data;
        r = pg_distance_joint_create(w, &d, &id);
        break;
    }
    case PG_JOINT_REVOLUTE: {
        pg_revolute_joint_def d = pg_default_revolute_joint_def();
        d.body_a = a, d.body_b = b, d.local_anchor_a = J->anchor_a, d.local_anchor_b = J->anchor_b;
        d.reference_angle = J->reference_angle, d.enable_limit = J->enable_limit, d.lower_angle = J->lower, d.upper_angle = J->upper;
        d.enable_motor = J->enable_motor, d.motor_speed = J->motor_speed, d.max_motor_torque = J->max_motor;
        d.collide_connected = J->collide, d.user_data = J->user_data;
        r = pg_revolute_joint_create(w, &d, &id);
        break;
    }
    case PG_JOINT_WELD: {
        pg_weld_joint_def d = pg_default_weld_joint_def();
        d.body_a = a, d.body_b = b, d.local_anchor_a = J->anchor_a, d.local_anchor_b = J->anchor_b;
        d.reference_angle = J->reference_angle, d.linear_hertz = J->hertz, d.linear_damping_ratio = J->damping;
        d.angular_hertz = J->hertz2, d.angular_damping_ratio = J->damping2;
        d.collide_connected = J->collide, d.user_data = J->user_data;
        r = pg_weld_joint_create(w, &d, &id);
        break;
    }
    case PG_JOINT_PRISMATIC: {
        pg_prismatic_joint_def d = pg_default_prismatic_joint_def();
        d.body_a = a, d.body_b = b, d.local_anchor_a = J->anchor_a, d.local_anchor_b = J->anchor_b;
        d.local_axis_a = J->axis, d.reference_angle = J->reference_angle;
        d.enable_limit = J->enable_limit, d.lower_translation = J->lower, d.upper_translation = J->upper;
        d.enable_motor = J->enable_motor, d.motor_speed = J->motor_speed, d.max_motor_force = J->max_motor;
        d.collide_connected = J->collide, d.user_data = J->user_data;
        r = pg_prismatic_joint_create(w, &d, &id);
        break;
    }
    default: {
        /* made at the body's origin, then given the file's anchor and target: the
         * anchor is state, not "the body point under the target" */
        pg_mouse_joint_def d = pg_default_mouse_joint_def();
        d.body = b, d.target = w->bodies[b.index].origin;
        d.hertz = J->hertz, d.damping_ratio = J->damping, d.max_force = J->max_motor, d.user_data = J->user_data;
        r = pg_mouse_joint_create(w, &d, &id);
        if (r == PG_OK) r = pg_mouse_joint_set_target(w, id, J->target);
        if (r == PG_OK) pg__joint(w, id)->anchor_b = J->anchor_b;
        break;
    }
    }
    if (r != PG_OK) {
        P->result = r;
        return fail_world(P, "cannot create the joint");
    }
    return PG_OK;
}

/* joint KIND [A] B [properties] */
static pg_result parse_joint(scene_parser *P)
{
    joint_line J;
    token t = next_token(P);
    int kind, i, first;
    pg_result r;
    for (kind = 0; kind < PG_JOINT_TYPE_COUNT; ++kind)
        if (token_is(P, t, joint_kind_names[kind])) break;
    if (kind == PG_JOINT_TYPE_COUNT) return fail_expected(P, t, "a joint kind (distance revolute weld prismatic mouse)", "joint", NULL);
    joint_line_init(&J, (pg_joint_type)kind);
    first = kind == PG_JOINT_MOUSE ? 1 : 0;
    for (i = first; i < 2; ++i) {
        uint64_t v = 0;
        const char *name = i == 0 ? "body_a" : kind == PG_JOINT_MOUSE ? "body" : "body_b";
        r = read_uint(P, name, 0xFFFFFFFFu, &v, &J.body_column[i]);
        if (r != PG_OK) return r;
        if (v >= P->bodies) {
            msg m = fail(P, PG_ERR_INVALID_ARGUMENT, J.body_column[i]);
            pg__text_put(&m, "there is no body ");
            pg__text_u64(&m, v);
            pg__text_put(&m, " above this line: a joint names bodies by their number in the file, from 0 (");
            pg__text_u64(&m, P->bodies);
            pg__text_put(&m, " so far)");
            return P->result;
        }
        J.body[i] = (uint32_t)v;
    }
    if (kind == PG_JOINT_MOUSE) J.body[0] = J.body[1];
    r = read_jprops(P, &J);
    if (r != PG_OK) return r;
    P->joints = P->joints < 0xFFFFFFFFu ? P->joints + 1u : P->joints;
    if (P->mode == MODE_READ) {
        r = check_joint_line(P, &J);
        if (r != PG_OK) return r;
        if ((P->settings_seen & ((uint64_t)1 << P_MAX_JOINTS)) != 0 && P->joints > P->def.max_joints) {
            msg m = fail(P, PG_ERR_CAPACITY, 1);
            pg__text_put(&m, "joint ");
            pg__text_u64(&m, P->joints);
            pg__text_put(&m, " is beyond max_joints ");
            pg__text_u64(&m, P->def.max_joints);
            pg__text_put(&m, " (line ");
            pg__text_u64(&m, P->setting_line[P_MAX_JOINTS]);
            pg__text_put(&m, ")");
            return P->result;
        }
        if (P->room_given && P->joints > P->room_joints && P->joint_over_line == 0) P->joint_over_line = P->line;
        return PG_OK;
    }
    return make_joint(P, &J);
}

static pg_result parse_statement(scene_parser *P, token t)
{
    const prop_info *info = find_prop(P, t);
    msg m;
    if (P->in_body) {
        if (token_is(P, t, "end")) {
            pg_result r = expect_end_of_line(P, "'end'");
            return r != PG_OK ? r : end_body(P);
        }
        if (token_is(P, t, "shape")) return parse_shape(P);
        if (info != NULL && (info->ctx & CTX_BODY) != 0) {
            if (P->body_shapes > 0) {
                m = fail(P, PG_ERR_INVALID_ARGUMENT, token_column(P, t));
                pg__text_put(&m, "body properties must come before the body's shapes");
                return P->result;
            }
            P->at = t.start;
            return read_props(P, CTX_BODY, &P->body, "a body");
        }
        if (token_is(P, t, "body") || token_is(P, t, "joint") || make_kind_of(P, t) >= 0 || token_is(P, t, "concave") ||
            token_is(P, t, "chain")) {
            m = fail(P, PG_ERR_INVALID_ARGUMENT, token_column(P, t));
            pg__text_put(&m, "expected 'end' to close the body of line ");
            pg__text_u64(&m, P->body_line);
            pg__text_put(&m, " before ");
            msg_token(&m, P, t);
            return P->result;
        }
        return fail_expected(P, t, "a body property, 'shape' or 'end'", NULL, NULL);
    }
    if (info != NULL && (info->ctx & CTX_SETTING) != 0) {
        if (P->bodies_started) {
            m = fail(P, PG_ERR_INVALID_ARGUMENT, token_column(P, t));
            pg__text_put(&m, "world settings must come before the first body");
            return P->result;
        }
        P->at = t.start;
        return read_props(P, CTX_SETTING, NULL, "the world settings");
    }
    if (token_is(P, t, "body")) {
        P->bodies_started = 1;
        return parse_body_line(P);
    }
    if (make_kind_of(P, t) >= 0) {
        P->bodies_started = 1;
        return parse_make(P, make_kind_of(P, t), t);
    }
    if (token_is(P, t, "concave") || token_is(P, t, "chain")) {
        P->bodies_started = 1;
        return token_is(P, t, "concave") ? parse_concave(P, t) : parse_chain(P, t);
    }
    if (token_is(P, t, "joint")) {
        P->bodies_started = 1;
        return parse_joint(P);
    }
    if (token_is(P, t, "end") || token_is(P, t, "shape")) {
        m = fail(P, PG_ERR_INVALID_ARGUMENT, token_column(P, t));
        msg_token(&m, P, t);
        pg__text_put(&m, " outside a body: open one with 'body TYPE'");
        return P->result;
    }
    if (info != NULL) {
        m = fail(P, PG_ERR_INVALID_ARGUMENT, token_column(P, t));
        pg__text_put(&m, "'");
        pg__text_put(&m, info->name);
        pg__text_put(&m, "' outside a body: put it inside 'body' ... 'end' or on a ready-made line");
        return P->result;
    }
    return fail_expected(P, t, "a setting, 'body', a ready-made kind (ball capsule box triangle star wall concave chain) or 'joint'", NULL, NULL);
}

static pg_result run(scene_parser *P)
{
    int status;
    while ((status = load_line(P)) > 0) {
        token t;
        pg_result r;
        if (P->line == 1) {
            r = parse_header(P);
            if (r != PG_OK) return r;
            continue;
        }
        t = next_token(P);
        if (t.len == 0) continue;
        r = parse_statement(P, t);
        if (r != PG_OK) return r;
    }
    if (status < 0) return P->result;
    if (P->line == 0) { /* empty text */
        token none;
        P->line = 1;
        P->line_start = 0;
        P->last_end = 0;
        none.start = 0;
        none.len = 0;
        return fail_expected(P, none, "'pogon-scene 1' as the first line", NULL, NULL);
    }
    if (P->in_body) {
        msg m = fail(P, PG_ERR_INVALID_ARGUMENT, column_at(P, P->last_end));
        pg__text_put(&m, "expected 'end' to close the body of line ");
        pg__text_u64(&m, P->body_line);
        pg__text_put(&m, ", got end of file");
        return P->result;
    }
    return PG_OK;
}

static void parser_init(scene_parser *P, const char *text, size_t length, pg_scene_error *error, pg_world *world)
{
    size_t i;
    unsigned char *p = (unsigned char *)P;
    for (i = 0; i < sizeof *P; ++i) p[i] = 0;
    P->text = text;
    P->length = length;
    P->world = world;
    P->mode = world != NULL ? MODE_LOAD : MODE_READ;
    P->error = error != NULL ? error : &P->scratch_error;
    P->error->line = 0;
    P->error->column = 0;
    P->error->message[0] = '\0';
    P->def = pg_default_world_def();
    P->result = PG_OK;
}

static pg_result fail_null(pg_scene_error *error, const char *what)
{
    if (error != NULL) {
        msg m;
        error->line = 0;
        error->column = 0;
        m = pg__text_in(error->message, sizeof error->message);
        pg__text_put(&m, what);
        pg__text_put(&m, " is NULL");
    }
    return PG_ERR_NULL;
}

/* The def after a successful READ pass: capacities not given are what the scene needs. */
static void finish_def(scene_parser *P)
{
    uint64_t contacts = (uint64_t)P->shapes * 4u + 64u;
    if ((P->settings_seen & ((uint64_t)1 << P_MAX_BODIES)) == 0) P->def.max_bodies = P->bodies < 1 ? 1u : P->bodies > (1u << 24) ? 1u << 24 : P->bodies;
    if ((P->settings_seen & ((uint64_t)1 << P_MAX_SHAPES)) == 0) P->def.max_shapes = P->shapes < 1 ? 1u : P->shapes > (1u << 24) ? 1u << 24 : P->shapes;
    if ((P->settings_seen & ((uint64_t)1 << P_MAX_CONTACTS)) == 0) P->def.max_contacts = contacts > (1u << 24) ? 1u << 24 : (uint32_t)contacts;
    if ((P->settings_seen & ((uint64_t)1 << P_MAX_JOINTS)) == 0 && P->joints > P->def.max_joints) P->def.max_joints = P->joints > (1u << 24) ? 1u << 24 : P->joints;
}

/* ---- the work area ---------------------------------------------------------------------- */
/* The parser is the whole work area: the working sets above are what it holds. */
PG__STATIC_ASSERT(sizeof(scene_parser) <= PG_SCENE_WORK_BYTES, scene_work_fits);

size_t pg_scene_work_size(void) { return sizeof(scene_parser); }

/* The parser in `work`, or NULL after an error naming what the work area lacks
 * (work_area.h). */
static scene_parser *parser_in(void *work, size_t work_size, pg_scene_error *error)
{
    const char *why = pg__work_area_problem(work, work_size, sizeof(scene_parser));
    if (why != NULL) {
        if (error != NULL) {
            msg m;
            error->line = 0;
            error->column = 0;
            m = pg__text_in(error->message, sizeof error->message);
            pg__text_put(&m, why);
            pg__work_area_explain(&m, "scene reader", "pg_scene_work_size()", sizeof(scene_parser), work, work_size);
        }
        return NULL;
    }
    return (scene_parser *)work;
}

pg_result pg_scene_read_def_in(const char *text, size_t length, pg_world_def *def, pg_scene_error *error, void *work,
                               size_t work_size)
{
    scene_parser *P;
    pg_result r;
    if (text == NULL) return fail_null(error, "text");
    if (def == NULL) return fail_null(error, "def");
    P = parser_in(work, work_size, error);
    if (P == NULL) return PG_ERR_INVALID_ARGUMENT;
    parser_init(P, text, length, error, NULL);
    r = run(P);
    if (r != PG_OK) return r;
    finish_def(P);
    *def = P->def;
    return PG_OK;
}

pg_result pg_scene_read_def(const char *text, size_t length, pg_world_def *def, pg_scene_error *error)
{
    uint64_t work[PG_SCENE_WORK_BYTES / 8u];
    return pg_scene_read_def_in(text, length, def, error, work, sizeof work);
}

/* The first setting (other than capacities) where the world differs from the scene. */
static int differing_setting(const pg_world_def *a, const pg_world_def *b)
{
    if (a->step_hz != b->step_hz) return P_STEP_HZ;
    if (a->substeps != b->substeps) return P_SUBSTEPS;
    if (a->gravity.x != b->gravity.x || a->gravity.y != b->gravity.y) return P_GRAVITY;
    if (a->effects != b->effects) return P_EFFECTS;
    if (a->contact_hertz != b->contact_hertz) return P_CONTACT_HERTZ;
    if (a->contact_damping_ratio != b->contact_damping_ratio) return P_CONTACT_DAMPING_RATIO;
    if (a->contact_push_max != b->contact_push_max) return P_CONTACT_PUSH_MAX;
    if (a->restitution_threshold != b->restitution_threshold) return P_RESTITUTION_THRESHOLD;
    if (a->max_linear_speed != b->max_linear_speed) return P_MAX_LINEAR_SPEED;
    if (a->sleep_linear_tolerance != b->sleep_linear_tolerance) return P_SLEEP_LINEAR_TOLERANCE;
    if (a->sleep_angular_tolerance != b->sleep_angular_tolerance) return P_SLEEP_ANGULAR_TOLERANCE;
    if (a->time_to_sleep != b->time_to_sleep) return P_TIME_TO_SLEEP;
    return -1;
}

/* After a READ pass of a scene with joints: the world must have room for them, and its
 * body slots must be used without gaps, so that the file's bodies take the slots from
 * body_high up and its body numbers name them. */
static pg_result check_joint_room(scene_parser *P, const pg_world *world)
{
    msg m;
    if (P->joints == 0) return PG_OK;
    if (world->body_count != world->body_high) {
        P->line = 1;
        m = fail(P, PG_ERR_INVALID_ARGUMENT, 1);
        pg__text_put(&m, "a scene with joints loads into a world whose body slots have no gaps (no body destroyed): its joints name bodies by number");
        return P->result;
    }
    if (P->joint_over_line != 0) {
        P->line = P->joint_over_line;
        m = fail(P, PG_ERR_CAPACITY, 1);
        pg__text_put(&m, "the scene's ");
        pg__text_u64(&m, P->joints);
        pg__text_put(&m, " joints do not fit: the world has ");
        pg__text_u64(&m, P->room_joints);
        pg__text_put(&m, " free joint slots of max_joints ");
        pg__text_u64(&m, world->def.max_joints);
        return P->result;
    }
    return PG_OK;
}

/* The READ pass of pg_scene_load, before it runs: the world's free slots are the room the
 * scene has, so that the pass notes where the scene outgrows them. */
static void begin_check(scene_parser *P, const pg_world *world, const char *text, size_t length, pg_scene_error *error)
{
    parser_init(P, text, length, error, NULL);
    P->room_given = 1;
    P->room_bodies = world->def.max_bodies - world->body_count;
    P->room_shapes = world->def.max_shapes - world->shape_count;
    P->room_joints = world->def.max_joints - world->joint_count;
}

/* After a successful READ pass of pg_scene_load: the world's settings and its room. PG_OK
 * when the LOAD pass can run; the world is not touched. */
PG__OWN_FRAME pg_result check_world(scene_parser *P, const pg_world *world)
{
    const pg_world_def *wd = &world->def;
    int which = differing_setting(wd, &P->def);
    if (which >= 0) {
        const uint64_t bit = (uint64_t)1 << which;
        msg m;
        int given = (P->settings_seen & bit) != 0;
        P->line = given ? P->setting_line[which] : 1u;
        m = fail(P, PG_ERR_INVALID_ARGUMENT, given ? P->setting_column[which] : 1u);
        pg__text_put(&m, "the world's ");
        pg__text_put(&m, prop_name(which));
        pg__text_put(&m, given ? " differs from the scene's" : " differs from the default the scene uses");
        pg__text_put(&m, ": create the world from pg_scene_read_def's def");
        return P->result;
    }
    if (P->over_kind != 0) { /* no room: refused before anything is made */
        msg m;
        int bodies = P->over_kind == 1;
        P->line = P->over_line;
        m = fail(P, PG_ERR_CAPACITY, 1);
        pg__text_put(&m, bodies ? "body " : "shape ");
        pg__text_u64(&m, P->over_count);
        pg__text_put(&m, " of the scene does not fit: the world has ");
        pg__text_u64(&m, bodies ? P->room_bodies : P->room_shapes);
        pg__text_put(&m, bodies ? " free body slots of max_bodies " : " free shape slots of max_shapes ");
        pg__text_u64(&m, bodies ? wd->max_bodies : wd->max_shapes);
        pg__text_put(&m, ", the scene needs ");
        pg__text_u64(&m, bodies ? P->bodies : P->shapes);
        return P->result;
    }
    return check_joint_room(P, world);
}

pg_result pg_scene_load_in(pg_world *world, const char *text, size_t length, pg_scene_error *error, void *work,
                            size_t work_size)
{
    scene_parser *P;
    pg_result r;
    if (world == NULL) return fail_null(error, "world");
    if (text == NULL) return fail_null(error, "text");
    P = parser_in(work, work_size, error);
    if (P == NULL) return PG_ERR_INVALID_ARGUMENT;
    begin_check(P, world, text, length, error); /* check everything first: nothing is made on a refusal */
    r = run(P);
    if (r == PG_OK) r = check_world(P, world);
    if (r != PG_OK) return r;
    parser_init(P, text, length, error, world);
    P->body_base = world->body_high;
    return run(P);
}

pg_result pg_scene_load(pg_world *world, const char *text, size_t length, pg_scene_error *error)
{
    uint64_t work[PG_SCENE_WORK_BYTES / 8u];
    return pg_scene_load_in(world, text, length, error, work, sizeof work);
}

/* ---- writer ----------------------------------------------------------------------------------------------- */
static void put_setting_fix(text_out *o, const char *name, pg_fix v)
{
    put_str(o, name);
    put_char(o, ' ');
    put_fix(o, v);
    put_char(o, '\n');
}

static void put_setting_u64(text_out *o, const char *name, uint64_t v)
{
    put_str(o, name);
    put_char(o, ' ');
    put_u64(o, v);
    put_char(o, '\n');
}

static void put_vec(text_out *o, const char *indent, const char *name, pg_vec2 v)
{
    put_str(o, indent);
    put_str(o, name);
    put_char(o, ' ');
    put_fix(o, v.x);
    put_char(o, ' ');
    put_fix(o, v.y);
    put_char(o, '\n');
}

static void put_point(text_out *o, pg_vec2 v)
{
    put_char(o, ' ');
    put_fix(o, v.x);
    put_char(o, ' ');
    put_fix(o, v.y);
}

static void write_settings(text_out *o, const pg_world_def *d)
{
    put_str(o, PG_SCENE_MAGIC " 1\n");
    put_setting_u64(o, "step_hz", d->step_hz);
    put_setting_u64(o, "substeps", d->substeps);
    put_vec(o, "", "gravity", d->gravity);
    put_str(o, "effects");
    if (d->effects == PG_EFFECTS_ALL) {
        put_str(o, " all");
    } else if (d->effects == 0) {
        put_str(o, " none");
    } else {
        int i;
        for (i = 0; i < 7; ++i)
            if ((d->effects & (1u << i)) != 0) {
                put_char(o, ' ');
                put_str(o, effect_names[i]);
            }
    }
    put_char(o, '\n');
    put_setting_fix(o, "contact_hertz", d->contact_hertz);
    put_setting_fix(o, "contact_damping_ratio", d->contact_damping_ratio);
    put_setting_fix(o, "contact_push_max", d->contact_push_max);
    put_setting_fix(o, "restitution_threshold", d->restitution_threshold);
    put_setting_fix(o, "max_linear_speed", d->max_linear_speed);
    put_setting_fix(o, "sleep_linear_tolerance", d->sleep_linear_tolerance);
    put_setting_fix(o, "sleep_angular_tolerance", d->sleep_angular_tolerance);
    put_setting_fix(o, "time_to_sleep", d->time_to_sleep);
    put_setting_u64(o, "max_bodies", d->max_bodies);
    put_setting_u64(o, "max_shapes", d->max_shapes);
    put_setting_u64(o, "max_contacts", d->max_contacts);
    put_setting_u64(o, "max_joints", d->max_joints);
    /* absent means the default (PG_EVENTS_AS_CONTACTS), which has no number of its own */
    if (d->max_contact_events != PG_EVENTS_AS_CONTACTS) put_setting_u64(o, "max_contact_events", d->max_contact_events);
}

static void write_shape(text_out *o, const pg_shape *s)
{
    const pg_geometry *g = &s->geometry;
    pg_shape_def dd = pg_default_shape_def();
    int32_t i;
    put_str(o, "  shape ");
    switch (g->kind) {
    case PG_SHAPE_CIRCLE:
        put_str(o, "circle ");
        put_fix(o, g->radius);
        if (g->vertices[0].x != 0 || g->vertices[0].y != 0) {
            put_str(o, " offset");
            put_point(o, g->vertices[0]);
        }
        break;
    case PG_SHAPE_SEGMENT:
        put_str(o, "segment");
        put_point(o, g->vertices[0]);
        put_point(o, g->vertices[1]);
        break;
    case PG_SHAPE_CAPSULE:
        put_str(o, "capsule");
        put_point(o, g->vertices[0]);
        put_point(o, g->vertices[1]);
        put_char(o, ' ');
        put_fix(o, g->radius);
        break;
    case PG_SHAPE_CHAIN_SEGMENT:
        put_str(o, "chain_segment");
        put_point(o, g->vertices[2]);
        put_point(o, g->vertices[0]);
        put_point(o, g->vertices[1]);
        put_point(o, g->vertices[3]);
        break;
    default:
        put_str(o, "polygon");
        for (i = 0; i < g->count && i < PG_MAX_VERTICES; ++i) put_point(o, g->vertices[i]);
        break;
    }
    if (s->density != dd.density) put_str(o, " density "), put_fix(o, s->density);
    if (s->friction != dd.friction) put_str(o, " friction "), put_fix(o, s->friction);
    if (s->restitution != dd.restitution) put_str(o, " restitution "), put_fix(o, s->restitution);
    if (s->category != dd.category) put_str(o, " category "), put_hex(o, s->category);
    if (s->mask != dd.mask) put_str(o, " mask "), put_hex(o, s->mask);
    put_char(o, '\n');
}

static void write_body(text_out *o, const pg_world *world, const pg_body *b)
{
    uint32_t s, n = 0;
    put_str(o, "body ");
    put_str(o, type_names[b->type == PG_BODY_KINEMATIC ? 1 : b->type == PG_BODY_DYNAMIC ? 2 : 0]);
    put_char(o, '\n');
    put_vec(o, "  ", "position", b->origin);
    if (b->angle != 0) {
        pg_fix degrees = degrees_from_angle(b->angle);
        if (pg_scene_angle_from_degrees(degrees) == b->angle) {
            put_str(o, "  angle ");
            put_fix(o, degrees);
        } else {
            put_str(o, "  angle_bits ");
            put_hex(o, b->angle);
            put_str(o, "  # about ");
            put_fix(o, degrees);
            put_str(o, " degrees");
        }
        put_char(o, '\n');
    }
    if (b->type != PG_BODY_STATIC && (b->v.x != 0 || b->v.y != 0)) put_vec(o, "  ", "linear_velocity", b->v);
    if (b->type != PG_BODY_STATIC && b->w != 0) put_str(o, "  angular_velocity "), put_fix(o, b->w), put_char(o, '\n');
    if (b->linear_damping != 0) put_str(o, "  linear_damping "), put_fix(o, b->linear_damping), put_char(o, '\n');
    if (b->angular_damping != 0) put_str(o, "  angular_damping "), put_fix(o, b->angular_damping), put_char(o, '\n');
    if (b->gravity_scale != PG_FIX_ONE) put_str(o, "  gravity_scale "), put_fix(o, b->gravity_scale), put_char(o, '\n');
    if ((b->flags & PG_BODY_FLAG_FIXED_ROTATION) != 0) put_str(o, "  fixed_rotation 1\n");
    if ((b->flags & PG_BODY_FLAG_ALLOW_SLEEP) == 0) put_str(o, "  allow_sleep 0\n");
    /* a joint wakes its bodies as it is made, so a body with joints loads awake */
    if ((b->flags & PG_BODY_FLAG_AWAKE) == 0 && b->first_joint == PG_NULL_INDEX) put_str(o, "  awake 0\n");
    if (b->user_data != 0) put_str(o, "  user_data "), put_u64(o, b->user_data), put_char(o, '\n');
    for (s = b->first_shape; s != PG_NULL_INDEX && s < world->def.max_shapes && n < 64u; s = world->shapes[s].next, ++n)
        write_shape(o, &world->shapes[s]);
    put_str(o, "end\n");
}

/* The file number of the body in `slot`: bodies are written in slot order, compacted. */
static uint32_t body_number(const pg_world *world, uint32_t slot)
{
    uint32_t i, n = 0;
    for (i = 0; i < slot && i < world->body_high; ++i)
        if ((world->bodies[i].flags & PG_BODY_FLAG_USED) != 0) ++n;
    return n;
}

static void put_jfix(text_out *o, const char *name, pg_fix v, pg_fix dflt)
{
    if (v == dflt) return;
    put_char(o, ' ');
    put_str(o, name);
    put_char(o, ' ');
    put_fix(o, v);
}

static void put_jvec(text_out *o, const char *name, pg_vec2 v, pg_vec2 dflt)
{
    if (v.x == dflt.x && v.y == dflt.y) return;
    put_char(o, ' ');
    put_str(o, name);
    put_point(o, v);
}

static void put_jflag(text_out *o, const pg_joint *j, uint32_t flag, const char *name)
{
    if ((j->flags & flag) != 0) put_char(o, ' '), put_str(o, name), put_str(o, " 1");
}

static void put_reference_angle(text_out *o, pg_angle a)
{
    pg_fix degrees = degrees_from_angle(a);
    if (a == 0) return;
    if (pg_scene_angle_from_degrees(degrees) == a) put_str(o, " reference_angle "), put_fix(o, degrees);
    else put_str(o, " reference_angle_bits "), put_hex(o, a);
}

/* joint KIND A B with the fields that differ from the kind's defaults */
static void write_joint(text_out *o, const pg_world *world, const pg_joint *j)
{
    const pg_vec2 zero = pg_v2_zero();
    put_str(o, "joint ");
    put_str(o, joint_kind_names[j->type < PG_JOINT_TYPE_COUNT ? j->type : 0]);
    if (j->type != PG_JOINT_MOUSE) put_char(o, ' '), put_u64(o, body_number(world, j->body_a));
    put_char(o, ' ');
    put_u64(o, body_number(world, j->body_b));
    if (j->type != PG_JOINT_MOUSE) put_jvec(o, "local_anchor_a", j->anchor_a, zero);
    put_jvec(o, "local_anchor_b", j->anchor_b, zero);
    switch (j->type) {
    case PG_JOINT_DISTANCE:
        put_jfix(o, "length", j->length, PG_FIX_ONE);
        put_jflag(o, j, PG_JOINT_FLAG_SPRING, "enable_spring");
        put_jfix(o, "hertz", j->hertz, 0);
        put_jfix(o, "damping_ratio", j->damping, 0);
        put_jflag(o, j, PG_JOINT_FLAG_LIMIT, "enable_limit");
        put_jfix(o, "min_length", j->lower, 0);
        put_jfix(o, "max_length", j->upper, JOINT_LENGTH_MAX);
        break;
    case PG_JOINT_REVOLUTE:
        put_reference_angle(o, j->reference_angle);
        put_jflag(o, j, PG_JOINT_FLAG_LIMIT, "enable_limit");
        put_jfix(o, "lower_angle", j->lower, 0);
        put_jfix(o, "upper_angle", j->upper, 0);
        put_jflag(o, j, PG_JOINT_FLAG_MOTOR, "enable_motor");
        put_jfix(o, "motor_speed", j->motor_speed, 0);
        put_jfix(o, "max_motor_torque", j->max_motor, 0);
        break;
    case PG_JOINT_WELD:
        put_reference_angle(o, j->reference_angle);
        put_jfix(o, "linear_hertz", j->hertz, 0);
        put_jfix(o, "linear_damping_ratio", j->damping, 0);
        put_jfix(o, "angular_hertz", j->hertz2, 0);
        put_jfix(o, "angular_damping_ratio", j->damping2, 0);
        break;
    case PG_JOINT_PRISMATIC:
        put_jvec(o, "local_axis_a", j->axis, pg_v2(PG_FIX_ONE, 0));
        put_reference_angle(o, j->reference_angle);
        put_jflag(o, j, PG_JOINT_FLAG_LIMIT, "enable_limit");
        put_jfix(o, "lower_translation", j->lower, 0);
        put_jfix(o, "upper_translation", j->upper, 0);
        put_jflag(o, j, PG_JOINT_FLAG_MOTOR, "enable_motor");
        put_jfix(o, "motor_speed", j->motor_speed, 0);
        put_jfix(o, "max_motor_force", j->max_motor, 0);
        break;
    default: {
        pg_mouse_joint_def md = pg_default_mouse_joint_def();
        put_char(o, ' ');
        put_str(o, "target");
        put_point(o, j->target);
        put_jfix(o, "hertz", j->hertz, md.hertz);
        put_jfix(o, "damping_ratio", j->damping, md.damping_ratio);
        put_jfix(o, "max_force", j->max_motor, md.max_force);
        break;
    }
    }
    if (j->type != PG_JOINT_MOUSE) put_jflag(o, j, PG_JOINT_FLAG_COLLIDE, "collide_connected");
    if (j->user_data != 0) put_str(o, " user_data "), put_u64(o, j->user_data);
    put_char(o, '\n');
}

size_t pg_scene_write(const pg_world *world, char *buffer, size_t capacity)
{
    text_out o;
    uint32_t i;
    o.buf = buffer;
    o.cap = buffer != NULL ? capacity : 0;
    o.len = 0;
    if (world != NULL) {
        write_settings(&o, &world->def);
        for (i = 0; i < world->body_high; ++i)
            if ((world->bodies[i].flags & PG_BODY_FLAG_USED) != 0) write_body(&o, world, &world->bodies[i]);
        for (i = 0; i < world->joint_high && i < world->def.max_joints; ++i)
            if ((world->joints[i].flags & PG_JOINT_FLAG_USED) != 0) write_joint(&o, world, &world->joints[i]);
    }
    finish_out(&o);
    return o.len;
}
