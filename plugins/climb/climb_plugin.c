/*
 * The "climb" link kind: a plugin library (loaded with nl_plugin_load) that links the foot of a wall
 * to the walkable top of it, for agents with the climbing ability bit. Written against
 * navlink/plugin.h only: it needs no symbol of libnavlink.so.
 *
 * For each navmesh boundary edge, every `sample_spacing` metres: if a wall stands just past the edge
 * (a blocked segment at chest height), a ray from above the wall's far side finds its top; if the top
 * is min_height..max_height above the edge, on the navmesh, with headroom to climb, the plugin
 * proposes a bidirectional link from the edge to the top that requires the ability bit.
 *
 * Settings (JSON object under "climb" in nl_link_settings.plugin_settings_json), with defaults:
 *   max_height 3.0, min_height 1.0, ability_bit 0 (the link requires 1 << ability_bit),
 *   sample_spacing 1.0, reach 1.5 (how far past the edge the wall may stand)
 */
#include <navlink/plugin.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if defined(__GNUC__)
#define EXPORT __attribute__((visibility("default")))
#else
#define EXPORT
#endif

#define CLIMB_KIND (NL_LINK_FIRST_PLUGIN_KIND + 0u)

typedef struct climb_settings {
    float max_height;
    float min_height;
    unsigned ability_bit;
    float sample_spacing;
    float reach;
} climb_settings;

/* Reads `"key": number` from a flat JSON object; absent keys keep their value. Returns 0 when the
   text has a key this plugin does not know (so a typo is an error, not a silent default). */
static int read_settings(const char* json, size_t length, climb_settings* s, char* error, size_t error_size) {
    static const char* const keys[] = {"max_height", "min_height", "ability_bit", "sample_spacing", "reach"};
    char* text;
    const char* p;
    if (!json) return 1;
    text = (char*)malloc(length + 1);
    if (!text) return 0;
    memcpy(text, json, length);
    text[length] = '\0';
    for (p = strchr(text, '"'); p; p = strchr(p, '"')) {
        const char* end = strchr(p + 1, '"');
        const char* colon;
        double value;
        size_t k, n;
        int known = 0;
        if (!end) break;
        n = (size_t)(end - p - 1);
        colon = strchr(end, ':');
        if (!colon || sscanf(colon + 1, "%lf", &value) != 1) {
            snprintf(error, error_size, "climb settings: '%.*s' needs a number", (int)n, p + 1);
            free(text);
            return 0;
        }
        for (k = 0; k < sizeof keys / sizeof keys[0]; ++k) {
            if (strlen(keys[k]) == n && strncmp(keys[k], p + 1, n) == 0) {
                known = 1;
                if (k == 0) s->max_height = (float)value;
                if (k == 1) s->min_height = (float)value;
                if (k == 2) s->ability_bit = (unsigned)value;
                if (k == 3) s->sample_spacing = (float)value;
                if (k == 4) s->reach = (float)value;
            }
        }
        if (!known) {
            snprintf(error, error_size, "climb settings: '%.*s' is not a setting", (int)n, p + 1);
            free(text);
            return 0;
        }
        p = colon + 1;
    }
    free(text);
    if (!(s->max_height > s->min_height && s->min_height >= 0.0f && s->ability_bit < 64 && s->sample_spacing >= 0.1f &&
          s->reach > 0.0f)) {
        snprintf(error, error_size,
                 "climb settings: need max_height > min_height >= 0, ability_bit < 64, "
                 "sample_spacing >= 0.1, reach > 0");
        return 0;
    }
    return 1;
}

static nl_status generate(void* state, const nl_plugin_host* host, nl_navmesh_id navmesh, const char* settings_json,
                          size_t settings_length, nl_link_sink_fn* sink, void* sink_context) {
    climb_settings s = {3.0f, 1.0f, 0u, 1.0f, 1.5f};
    char error[160];
    nl_navmesh_info info;
    nl_boundary_edge* edges;
    uint32_t count = 0, e;
    nl_status status;
    (void)state;

    if (!read_settings(settings_json, settings_length, &s, error, sizeof error)) {
        host->set_error(host->context, error);
        return NL_STATUS_FAILURE | NL_STATUS_INVALID_ARGUMENT;
    }
    memset(&info, 0, sizeof info);
    info.size = sizeof info;
    status = host->navmesh_get_info(host->context, navmesh, &info);
    if (NL_FAILED(status)) return status;
    status = host->navmesh_get_boundary_edges(host->context, navmesh, NULL, 0, &count);
    if (NL_FAILED(status) || count == 0) return status;
    edges = (nl_boundary_edge*)malloc(count * sizeof *edges);
    if (!edges) return NL_STATUS_FAILURE | NL_STATUS_OUT_OF_MEMORY;
    status = host->navmesh_get_boundary_edges(host->context, navmesh, edges, count, &count);

    for (e = 0; e < count && NL_SUCCEEDED(status); ++e) {
        const nl_boundary_edge* edge = &edges[e];
        const float dx = edge->end[0] - edge->start[0], dz = edge->end[2] - edge->start[2];
        const float length = sqrtf(dx * dx + dz * dz);
        float ox = edge->outward[0], oz = edge->outward[2];
        const float flat = sqrtf(ox * ox + oz * oz);
        unsigned samples, k;
        if (flat < 1e-3f || length <= 0.0f) continue;
        ox /= flat;
        oz /= flat;
        samples = (unsigned)(length / s.sample_spacing + 0.5f);
        if (samples == 0) samples = 1;
        for (k = 0; k < samples && NL_SUCCEEDED(status); ++k) {
            const float t = (k + 0.5f) / (float)samples;
            const float p[3] = {edge->start[0] + t * dx, edge->start[1] + t * (edge->end[1] - edge->start[1]),
                                edge->start[2] + t * dz};
            nl_segment chest, headroom;
            nl_ray down;
            nl_ray_hit hit = nl_ray_hit_init();
            uint8_t blocked[2] = {0, 0};
            nl_nav_point top;
            const float extents[3] = {info.agent_type.radius * 2.0f + 0.5f, 1.0f, info.agent_type.radius * 2.0f + 0.5f};
            nl_link_def link;

            /* A wall just past the edge, at chest height. */
            chest.from[0] = p[0];
            chest.from[1] = p[1] + 0.5f * info.agent_type.height;
            chest.from[2] = p[2];
            chest.to[0] = p[0] + ox * s.reach;
            chest.to[1] = chest.from[1];
            chest.to[2] = p[2] + oz * s.reach;
            /* Room above the climber: straight up from the edge to above the top. */
            headroom.from[0] = p[0];
            headroom.from[1] = p[1] + 0.1f;
            headroom.from[2] = p[2];
            headroom.to[0] = p[0];
            headroom.to[1] = p[1] + s.max_height + 0.5f * info.agent_type.height;
            headroom.to[2] = p[2];
            {
                const nl_segment both[2] = {chest, headroom};
                status = host->segments_blocked(host->context, both, 2, blocked);
            }
            if (NL_FAILED(status) || !blocked[0] || blocked[1]) continue;

            /* The top: straight down from above the wall, a radius and a bit past its face. */
            memset(&down, 0, sizeof down);
            down.origin[0] = p[0] + ox * (s.reach + info.agent_type.radius);
            down.origin[1] = p[1] + s.max_height + 0.25f;
            down.origin[2] = p[2] + oz * (s.reach + info.agent_type.radius);
            down.direction[1] = -1.0f;
            down.max_distance = s.max_height + 0.25f;
            status = host->cast_rays(host->context, &down, 1, &hit);
            if (NL_FAILED(status) || !hit.hit || hit.point[1] - p[1] < s.min_height) continue;
            status = host->navmesh_find_nearest(host->context, navmesh, hit.point, 1, extents, &top);
            if (NL_FAILED(status) || !top.found || top.point[1] - p[1] < s.min_height ||
                top.point[1] - p[1] > s.max_height + 0.5f)
                continue;

            memset(&link, 0, sizeof link);
            link.size = sizeof link;
            link.kind = CLIMB_KIND;
            memcpy(link.start, p, sizeof p);
            memcpy(link.end, top.point, sizeof top.point);
            link.bidirectional = 1;
            link.enabled = 1;
            link.cost_modifier = 2.0f; /* climbing is slower than walking */
            /* A climb asks for the ability, not for a jump's or a drop's reach. */
            link.requirements_as_given = 1;
            link.requirements.abilities = 1ull << s.ability_bit;
            status = sink(sink_context, &link);
        }
    }
    free(edges);
    return status;
}

EXPORT nl_status nl_plugin_entry(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) {
    (void)host;
    if (host_abi_version < 1u) return NL_STATUS_FAILURE | NL_STATUS_VERSION_MISMATCH;
    out_info->abi_version = 1u;
    out_info->name = "climb";
    out_info->version = "1.0";
    out_info->description = "climb links from the foot of a wall to its top, for agents with the climbing ability";
    out_info->kinds = NL_PLUGIN_LINK_KIND;
    out_info->link_kind.kind = CLIMB_KIND;
    out_info->link_kind.kind_name = "climb";
    out_info->link_kind.generate = generate;
    return NL_STATUS_SUCCESS;
}
