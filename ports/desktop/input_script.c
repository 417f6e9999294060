/* input_script.c — parse and apply input scripts (format in input_script.h). */
#include "input_script.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_WORDS 8

typedef struct word {
    const char *text;
    size_t length;
    size_t column;
} word;

static int word_is(const word *w, const char *s) { return strlen(s) == w->length && memcmp(w->text, s, w->length) == 0; }

static int parse_fix(const word *w, pg_fix *out) { return pg_fix_parse(w->text, w->length, out) == PG_FIX_OK; }

static int parse_u32(const word *w, uint32_t *out, int base)
{
    char buf[24];
    char *end;
    unsigned long v;
    if (w->length == 0 || w->length >= sizeof buf || w->text[0] == '-') return 0;
    memcpy(buf, w->text, w->length);
    buf[w->length] = '\0';
    v = strtoul(buf, &end, base);
    if (*end != '\0' || v > 0xffffffffUL) return 0;
    *out = (uint32_t)v;
    return 1;
}

static int effect_bit(const word *w, size_t from, size_t to, uint32_t *bit)
{
    uint32_t i;
    for (i = 0; i < pga_effect_count(); ++i) {
        const char *name = pga_effect_name(i);
        if (strlen(name) == to - from && memcmp(w->text + from, name, to - from) == 0) {
            *bit = pga_effect_bit(i);
            return 1;
        }
    }
    return 0;
}

static int parse_effects(const word *w, uint32_t *bits)
{
    size_t start = 0, i;
    if (word_is(w, "all")) { *bits = PG_EFFECTS_ALL; return 1; }
    if (word_is(w, "none")) { *bits = 0; return 1; }
    *bits = 0;
    for (i = 0; i <= w->length; ++i) {
        if (i == w->length || w->text[i] == '+') {
            uint32_t bit;
            if (!effect_bit(w, start, i, &bit)) return 0;
            *bits |= bit;
            start = i + 1;
        }
    }
    return 1;
}

static const char *const tool_words[] = {"move", "delete", "ball", "capsule", "box", "triangle", "star", "wall",
                                         "pin", "rod", "spring"};
static const char *const key_words[] = {"left", "right", "up", "down", "ccw", "cw"};
static const char *const preset_words[] = {"fast", "balanced", "accurate"};
static const char *const param_words[] = {"radius", "width", "height", "density", "friction", "restitution", "color",
                                          "spring_hertz", "spring_damping"};

static int lookup(const word *w, const char *const *names, uint32_t count, uint32_t *out)
{
    uint32_t i;
    for (i = 0; i < count; ++i)
        if (word_is(w, names[i])) { *out = i; return 1; }
    return 0;
}

#define COUNT(a) ((uint32_t)(sizeof(a) / sizeof((a)[0])))

/* One line's words into an event; 0 and the message on error. */
static int parse_event(const word *w, int n, desktop_event *e, const word **bad, const char **why)
{
    const word *ev = &w[1];
    *bad = ev;
    if (word_is(ev, "tool") || word_is(ev, "preset") || word_is(ev, "nudge") || word_is(ev, "effect") ||
        word_is(ev, "effects") || word_is(ev, "select")) {
        if (n != 3) { *why = "this event takes one argument"; return 0; }
        *bad = &w[2];
        if (word_is(ev, "tool")) {
            e->kind = DESKTOP_EV_TOOL;
            if (!lookup(&w[2], tool_words, COUNT(tool_words), &e->value)) { *why = "unknown tool"; return 0; }
        } else if (word_is(ev, "preset")) {
            e->kind = DESKTOP_EV_PRESET;
            if (!lookup(&w[2], preset_words, COUNT(preset_words), &e->value)) { *why = "unknown preset (fast, balanced, accurate)"; return 0; }
        } else if (word_is(ev, "nudge")) {
            e->kind = DESKTOP_EV_NUDGE;
            if (word_is(&w[2], "on")) e->value = 1;
            else if (word_is(&w[2], "off")) e->value = 0;
            else { *why = "nudge takes on or off"; return 0; }
        } else if (word_is(ev, "effect")) {
            e->kind = DESKTOP_EV_EFFECT;
            if (!effect_bit(&w[2], 0, w[2].length, &e->value)) { *why = "unknown effect"; return 0; }
        } else if (word_is(ev, "effects")) {
            e->kind = DESKTOP_EV_EFFECTS;
            if (!parse_effects(&w[2], &e->value)) { *why = "unknown effect in the list"; return 0; }
        } else {
            e->kind = DESKTOP_EV_SELECT_NONE;
            if (!word_is(&w[2], "none")) { *why = "select takes none"; return 0; }
        }
        return 1;
    }
    if (word_is(ev, "down") || word_is(ev, "move") || word_is(ev, "up") || word_is(ev, "click")) {
        e->kind = word_is(ev, "down") ? DESKTOP_EV_DOWN : word_is(ev, "move") ? DESKTOP_EV_MOVE
                : word_is(ev, "up") ? DESKTOP_EV_UP : DESKTOP_EV_CLICK;
        if (n != 4) { *why = "a pointer event takes X Y in metres"; return 0; }
        *bad = &w[2];
        if (!parse_fix(&w[2], &e->point.x)) { *why = "X is not a number"; return 0; }
        *bad = &w[3];
        if (!parse_fix(&w[3], &e->point.y)) { *why = "Y is not a number"; return 0; }
        return 1;
    }
    if (word_is(ev, "key")) {
        e->kind = DESKTOP_EV_KEY;
        if (n != 4) { *why = "key takes a key name and down or up"; return 0; }
        *bad = &w[2];
        if (!lookup(&w[2], key_words, COUNT(key_words), &e->value)) { *why = "unknown key (left right up down ccw cw)"; return 0; }
        *bad = &w[3];
        if (word_is(&w[3], "down")) e->down = 1;
        else if (word_is(&w[3], "up")) e->down = 0;
        else { *why = "a key goes down or up"; return 0; }
        return 1;
    }
    if (word_is(ev, "param")) {
        e->kind = DESKTOP_EV_PARAM;
        if (n != 4) { *why = "param takes a name and a value"; return 0; }
        *bad = &w[2];
        if (!lookup(&w[2], param_words, COUNT(param_words), &e->value)) { *why = "unknown parameter"; return 0; }
        *bad = &w[3];
        if (e->value == DESKTOP_PARAM_COLOR) {
            uint32_t c;
            if (w[3].length < 3 || w[3].text[0] != '0' || (w[3].text[1] != 'x' && w[3].text[1] != 'X')) { *why = "a colour is 0xRRGGBB"; return 0; }
            {
                word hex = w[3];
                hex.text += 2;
                hex.length -= 2;
                if (!parse_u32(&hex, &c, 16) || c > 0xffffffu) { *why = "a colour is 0xRRGGBB"; return 0; }
            }
            e->number = (pg_fix)c;
        } else if (!parse_fix(&w[3], &e->number)) {
            *why = "the value is not a number";
            return 0;
        }
        return 1;
    }
    if (word_is(ev, "gravity") || word_is(ev, "pause") || word_is(ev, "resume") || word_is(ev, "step")) {
        e->kind = word_is(ev, "gravity") ? DESKTOP_EV_GRAVITY : word_is(ev, "pause") ? DESKTOP_EV_PAUSE
                : word_is(ev, "resume") ? DESKTOP_EV_RESUME : DESKTOP_EV_STEP;
        if (n != 2) { *why = "this event takes no argument"; return 0; }
        return 1;
    }
    *why = "unknown event (tool down move up click key gravity effect effects pause resume step preset nudge param select)";
    return 0;
}

int desktop_script_parse(const char *text, size_t length, desktop_script *out, char *error, size_t error_capacity)
{
    size_t pos = 0, cap = 0;
    int line = 0;
    uint32_t last_tick = 0;
    out->events = NULL;
    out->count = 0;
    while (pos < length) {
        size_t start = pos, end, i;
        word w[MAX_WORDS + 1];
        int n = 0;
        desktop_event e;
        const word *bad = NULL;
        const char *why = "";
        line++;
        while (pos < length && text[pos] != '\n') pos++;
        end = pos;
        pos++;
        for (i = start; i < end;) {
            if (text[i] == '#') break;
            if (text[i] == ' ' || text[i] == '\t' || text[i] == '\r') { i++; continue; }
            if (n == MAX_WORDS + 1) { n++; break; }
            w[n].text = text + i;
            w[n].column = i - start + 1;
            while (i < end && text[i] != ' ' && text[i] != '\t' && text[i] != '\r' && text[i] != '#') i++;
            w[n].length = (size_t)(text + i - w[n].text);
            n++;
        }
        if (n == 0) continue;
        memset(&e, 0, sizeof e);
        e.line = line;
        if (n > MAX_WORDS) {
            snprintf(error, error_capacity, "%d:1: too many words on the line", line);
            desktop_script_free(out);
            return 0;
        }
        if (!parse_u32(&w[0], &e.tick, 10)) {
            snprintf(error, error_capacity, "%d:%zu: a line starts with its tick (a whole number)", line, w[0].column);
            desktop_script_free(out);
            return 0;
        }
        if (e.tick < last_tick) {
            snprintf(error, error_capacity, "%d:%zu: tick %u comes after tick %u: ticks never go down", line, w[0].column,
                     e.tick, last_tick);
            desktop_script_free(out);
            return 0;
        }
        last_tick = e.tick;
        if (n < 2) {
            snprintf(error, error_capacity, "%d:%zu: an event name follows the tick", line, w[0].column + w[0].length);
            desktop_script_free(out);
            return 0;
        }
        if (!parse_event(w, n, &e, &bad, &why)) {
            snprintf(error, error_capacity, "%d:%zu: %s ('%.*s')", line, bad->column, why, (int)bad->length, bad->text);
            desktop_script_free(out);
            return 0;
        }
        if (out->count == cap) {
            size_t ncap = cap != 0 ? cap * 2 : 64;
            desktop_event *ne = (desktop_event *)realloc(out->events, ncap * sizeof *ne);
            if (ne == NULL) {
                snprintf(error, error_capacity, "%d:1: out of memory", line);
                desktop_script_free(out);
                return 0;
            }
            out->events = ne;
            cap = ncap;
        }
        out->events[out->count++] = e;
    }
    return 1;
}

void desktop_script_free(desktop_script *s)
{
    free(s->events);
    s->events = NULL;
    s->count = 0;
}

void desktop_event_apply(pga_app *app, const desktop_event *e)
{
    pga_params p;
    switch (e->kind) {
    case DESKTOP_EV_TOOL: pga_set_tool(app, (pga_tool)e->value); break;
    case DESKTOP_EV_DOWN: pga_pointer_down(app, e->point); break;
    case DESKTOP_EV_MOVE: pga_pointer_move(app, e->point); break;
    case DESKTOP_EV_UP: pga_pointer_up(app, e->point); break;
    case DESKTOP_EV_CLICK:
        pga_pointer_down(app, e->point);
        pga_pointer_up(app, e->point);
        break;
    case DESKTOP_EV_KEY: pga_key(app, (pga_key_code)e->value, e->down); break;
    case DESKTOP_EV_GRAVITY: pga_toggle_gravity(app); break;
    case DESKTOP_EV_EFFECT: pga_set_effects(app, pga_effects(app) ^ e->value); break;
    case DESKTOP_EV_EFFECTS: pga_set_effects(app, e->value); break;
    case DESKTOP_EV_PAUSE: pga_set_paused(app, 1); break;
    case DESKTOP_EV_RESUME: pga_set_paused(app, 0); break;
    case DESKTOP_EV_STEP: pga_step_once(app); break;
    case DESKTOP_EV_PRESET: pga_set_preset(app, (pga_preset)e->value); break;
    case DESKTOP_EV_SELECT_NONE: {
        pg_body_id none = {0, 0};
        pga_select(app, none);
        break;
    }
    case DESKTOP_EV_NUDGE:
    case DESKTOP_EV_PARAM:
        p = pga_get_params(app);
        if (e->kind == DESKTOP_EV_NUDGE) p.nudge = (int)e->value;
        else if (e->value == DESKTOP_PARAM_RADIUS) p.radius = e->number;
        else if (e->value == DESKTOP_PARAM_WIDTH) p.width = e->number;
        else if (e->value == DESKTOP_PARAM_HEIGHT) p.height = e->number;
        else if (e->value == DESKTOP_PARAM_DENSITY) p.density = e->number;
        else if (e->value == DESKTOP_PARAM_FRICTION) p.friction = e->number;
        else if (e->value == DESKTOP_PARAM_RESTITUTION) p.restitution = e->number;
        else if (e->value == DESKTOP_PARAM_SPRING_HERTZ) p.spring_hertz = e->number;
        else if (e->value == DESKTOP_PARAM_SPRING_DAMPING) p.spring_damping = e->number;
        else p.color = (uint32_t)e->number;
        pga_set_params(app, &p);
        break;
    }
}
