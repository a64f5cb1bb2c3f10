/* procedural.c - "builtin:" spec parsing and dispatch. */
#include "procedural.h"

#include "procgen.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char* scn_builtin_help(void)
{
    return "Built-in scenes: builtin:<name>[?key=value[&key=value...]]\n"
           "  builtin:city      streets and buildings; keys: seed=<u64> (default 1),\n"
           "                    tris=<10000..16000000> target triangles (default 150000),\n"
           "                    movers=<0..10000> vehicles and pedestrians on the streets (default 0)\n"
           "  builtin:interior  rooms, corridor, doorways, columns; keys: seed=<u64>,\n"
           "                    movers=<0..10000> swinging doors, carts, objects crossing rooms (default 0)\n"
           "  builtin:house     two-storey house with windows, doors, stairs and furniture\n"
           "                    (detailed, CAD/BIM-like parts); keys: seed=<u64>\n"
           "  builtin:unit      wall, boxes and ground with analytic visibility; no keys\n"
           "Examples: builtin:city?seed=3&tris=500000  builtin:interior?seed=2&movers=12\n";
}

typedef struct builtin_params {
    uint64_t seed;
    uint64_t tris, movers;
    bool has_seed, has_tris, has_movers;
} builtin_params;

static bool _scn_parse_u64(const char* text, size_t len, uint64_t* out)
{
    char buf[32];
    if (len == 0 || len >= sizeof buf || text[0] == '-' || text[0] == '+')
        return false;
    memcpy(buf, text, len);
    buf[len] = '\0';
    char* end;
    errno = 0;
    unsigned long long v = strtoull(buf, &end, 10);
    if (errno || *end != '\0')
        return false;
    *out = v;
    return true;
}

static bool _scn_parse_params(const char* spec, const char* query, builtin_params* p, char* err, size_t err_size)
{
    while (query && *query) {
        const char* amp = strchr(query, '&');
        size_t len = amp ? (size_t)(amp - query) : strlen(query);
        const char* eq = memchr(query, '=', len);
        if (!eq) {
            snprintf(err, err_size, "%s: parameter '%.*s' needs the form key=value", spec, (int)len, query);
            return false;
        }
        size_t key_len = (size_t)(eq - query), value_len = len - key_len - 1;
        uint64_t value = 0;
        bool ok = _scn_parse_u64(eq + 1, value_len, &value);
        bool is_seed = key_len == 4 && strncmp(query, "seed", 4) == 0;
        bool is_tris = key_len == 4 && strncmp(query, "tris", 4) == 0;
        bool is_movers = key_len == 6 && strncmp(query, "movers", 6) == 0;
        if ((is_seed && p->has_seed) || (is_tris && p->has_tris) || (is_movers && p->has_movers)) {
            snprintf(err, err_size, "%s: parameter '%.*s' given twice", spec, (int)key_len, query);
            return false;
        }
        if (is_seed && ok) {
            p->seed = value, p->has_seed = true;
        } else if (is_tris && ok) {
            p->tris = value, p->has_tris = true;
        } else if (is_movers && ok && value <= 10000) {
            p->movers = value, p->has_movers = true;
        } else {
            snprintf(err, err_size, "%s: bad parameter '%.*s' (expected seed=<u64>, tris=<count> or movers=<0..10000>)",
                     spec, (int)len, query);
            return false;
        }
        query = amp ? amp + 1 : NULL;
    }
    return true;
}

bool scn_load_builtin(const char* spec, scn_scene* out, char* err, size_t err_size)
{
    memset(out, 0, sizeof *out);
    const char* name = spec + strlen("builtin:");
    const char* q = strchr(name, '?');
    size_t name_len = q ? (size_t)(q - name) : strlen(name);
    builtin_params p = { .seed = 1, .tris = SCN_CITY_DEFAULT_TRIS };
    if (!_scn_parse_params(spec, q ? q + 1 : NULL, &p, err, err_size))
        return false;
    scn_builder b;
    scn_builder_init(&b, out, false);
    if (name_len == 4 && strncmp(name, "city", 4) == 0) {
        if (p.tris < 10000 || p.tris > 16000000) {
            snprintf(err, err_size, "%s: tris=%llu out of range (10000..16000000)", spec, (unsigned long long)p.tris);
            return false;
        }
        scn_gen_city(&b, p.seed, (uint32_t)p.tris, (uint32_t)p.movers);
    } else if (name_len == 8 && strncmp(name, "interior", 8) == 0 && !p.has_tris) {
        scn_gen_interior(&b, p.seed, (uint32_t)p.movers);
    } else if (name_len == 5 && strncmp(name, "house", 5) == 0 && !p.has_tris && !p.has_movers) {
        scn_gen_house(&b, p.seed);
    } else if (name_len == 4 && strncmp(name, "unit", 4) == 0 && !p.has_tris && !p.has_seed && !p.has_movers) {
        scn_gen_unit(&b);
    } else {
        snprintf(err, err_size, "%s: unknown built-in scene or parameter not accepted by it (see scn_builtin_help)", spec);
        return false;
    }
    if (!scn_builder_finish(&b, spec, err, err_size))
        return false;
    snprintf(out->name, sizeof out->name, "%s", spec);
    return true;
}
