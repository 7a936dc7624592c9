/*
 * The hostile cases of navlink/navmesh_file.h: baked navmesh files saved, loaded and described; baked
 * tiles saved, added and hashed (on A's tiled navmesh, the host's tiles (0, 0) and (1, 0) of 8 m from
 * (60, -4), and on a tiled navmesh Recast builds over A's platforms in a group, with its links).
 */
#include "hostile_fixtures.h"

#include <navlink/recast.h>

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A's navmesh as a file, malloc'ed. */
static unsigned char* saved_navmesh(size_t* size) {
    unsigned char* file;
    if (NL_FAILED(nl_navmesh_save(A.world, A.navmesh, NULL, 0, size))) fixture_failed("nl_navmesh_save");
    file = (unsigned char*)malloc(*size);
    if (!file || NL_FAILED(nl_navmesh_save(A.world, A.navmesh, file, *size, size))) fixture_failed("nl_navmesh_save");
    return file;
}

static void group_navmesh_save(void) {
    size_t needed = 0;
    unsigned char* file = saved_navmesh(&needed);
    saver_cases("nl_navmesh_save", "out_size", nl_navmesh_save, file, needed, 0);
    free(file);
}

static char g_save_path[256];
static nl_status save_file_id_call(nl_world* w, raw_id id, void* out) {
    (void)out;
    return nl_navmesh_save_file(w, AS(nl_navmesh_id, id), g_save_path);
}

static void group_navmesh_save_file(void) {
    static const id_function f = {"nl_navmesh_save_file", "navmesh", NULL, 0, 0, 0, save_file_id_call, 0};
    static const char* made[] = {"saved.nlnav"};
    make_tmp();
    snprintf(g_save_path, sizeof g_save_path, "%s/saved.nlnav", g_tmp);
    id_cases(&f, RAW(A.navmesh), RAW(A.stale_navmesh), RAW(B.navmesh));
    CASE("nl_navmesh_save_file", "path NULL") {
        EXPECT_INVALID(A.world, nl_navmesh_save_file(A.world, A.navmesh, NULL), "path");
    }
    CASE("nl_navmesh_save_file", "path empty") {
        EXPECT_INVALID(A.world, nl_navmesh_save_file(A.world, A.navmesh, ""), "path");
    }
    CASE("nl_navmesh_save_file", "path in a missing folder") {
        char path[300];
        snprintf(path, sizeof path, "%s/no-such-folder/x.nlnav", g_tmp);
        EXPECT_FAILURE(A.world, nl_navmesh_save_file(A.world, A.navmesh, path), NL_STATUS_IO_ERROR, "no-such-folder");
    }
    CASE("nl_navmesh_save_file", "path a directory") {
        char path[300];
        snprintf(path, sizeof path, "%s/dir.obj", g_tmp);
        EXPECT_FAILURE(A.world, nl_navmesh_save_file(A.world, A.navmesh, path), NL_STATUS_IO_ERROR, "dir.obj");
    }
    CASE("nl_navmesh_save_file", "path writable (allowed: the file is the buffer's)") {
        size_t size = 0;
        unsigned char* file = saved_navmesh(&size);
        FILE* f2;
        unsigned char* read = (unsigned char*)malloc(size + 1);
        size_t got = 0;
        EXPECT_OK(nl_navmesh_save_file(A.world, A.navmesh, g_save_path));
        f2 = fopen(g_save_path, "rb");
        if (f2 && read) {
            got = fread(read, 1, size + 1, f2);
            fclose(f2);
        }
        EXPECT(got == size && memcmp(read, file, size) == 0, "the file holds %u bytes, not the %u saved", (unsigned)got,
               (unsigned)size);
        free(read);
        free(file);
    }
    remove_tmp(made, 1);
}

/* ---------------------------------------------------------------------------------------------
 * Baked tiles
 * ------------------------------------------------------------------------------------------- */

/* A tile of a navmesh of A as a file, malloc'ed. */
static unsigned char* saved_tile(nl_navmesh_id navmesh, nl_tile_coord tile, size_t* size) {
    unsigned char* file;
    if (NL_FAILED(nl_navmesh_save_tile(A.world, navmesh, tile, NULL, 0, size))) fixture_failed("nl_navmesh_save_tile");
    file = (unsigned char*)malloc(*size);
    if (!file || NL_FAILED(nl_navmesh_save_tile(A.world, navmesh, tile, file, *size, size)))
        fixture_failed("nl_navmesh_save_tile");
    return file;
}

/* A tile's file as another host's navmesh gives it: `def` added to A as a navmesh of one tile (its
   links generated when `generate`), its tile saved, the navmesh removed again. */
static unsigned char* lone_tile_file(nl_navmesh_def def, int generate, size_t* size) {
    nl_navmesh_id id;
    unsigned char* file;
    if (NL_FAILED(nl_navmesh_add(A.world, &def, &id))) fixture_failed("a lone tile's navmesh");
    if (generate && NL_FAILED(nl_navmesh_generate_links(A.world, id, NULL, NULL, NULL, NULL)))
        fixture_failed("a lone tile's links");
    file = saved_tile(id, (nl_tile_coord){def.tile_x, def.tile_z}, size);
    if (NL_FAILED(nl_navmesh_remove(A.world, id))) fixture_failed("nl_navmesh_remove");
    return file;
}

/* Writes `size` bytes to `path` (exit code 4 if it cannot). */
static void write_bytes(const char* path, const void* data, size_t size) {
    FILE* f = fopen(path, "wb");
    if (!f || fwrite(data, 1, size, f) != size) {
        fprintf(stderr, "cannot write %s\n", path);
        exit(4);
    }
    fclose(f);
}

/* The bytes of the file at `path`, malloc'ed (NULL if there is none). */
static unsigned char* read_bytes(const char* path, size_t* size) {
    FILE* f = fopen(path, "rb");
    unsigned char* bytes = NULL;
    size_t room = 0, n;
    *size = 0;
    if (!f) return NULL;
    do {
        room = room ? 2 * room : 4096;
        bytes = (unsigned char*)realloc(bytes, room);
        if (!bytes) exit(2);
        n = fread(bytes + *size, 1, room - *size, f);
        *size += n;
    } while (*size == room);
    fclose(f);
    return bytes;
}

/* What a navmesh of A holds: its info, tiles and links (in the order listed, ids and all). A refused
   call leaves all of it as it was. */
typedef struct navmesh_state {
    nl_navmesh_info info;
    nl_tile_coord tiles[64];
    uint32_t tile_count, link_count;
    nl_link* links;
} navmesh_state;

static navmesh_state state_of(nl_navmesh_id id) {
    navmesh_state s;
    memset(&s, 0, sizeof s);
    s.info = navmesh_info(&A, id);
    s.tile_count = navmesh_tiles(&A, id, s.tiles, 64);
    if (NL_FAILED(nl_navmesh_get_links(A.world, id, NULL, 0, &s.link_count))) fixture_failed("nl_navmesh_get_links");
    s.links = (nl_link*)calloc(s.link_count + 1u, sizeof *s.links);
    if (!s.links) exit(2);
    s.links[0] = nl_link_init();
    if (NL_FAILED(nl_navmesh_get_links(A.world, id, s.links, s.link_count, &s.link_count)))
        fixture_failed("nl_navmesh_get_links");
    return s;
}

static void expect_state_at(const char* file, int line, const navmesh_state* before, nl_navmesh_id id) {
    navmesh_state now = state_of(id);
    if (memcmp(&now.info, &before->info, sizeof now.info) != 0)
        case_failed(file, line, "the navmesh's info changed (%u polygons, %u tiles; were %u, %u)",
                    (unsigned)now.info.polygon_count, (unsigned)now.info.tile_count,
                    (unsigned)before->info.polygon_count, (unsigned)before->info.tile_count);
    if (now.tile_count != before->tile_count || memcmp(now.tiles, before->tiles, sizeof now.tiles) != 0)
        case_failed(file, line, "the navmesh's tiles changed (%u; were %u)", (unsigned)now.tile_count,
                    (unsigned)before->tile_count);
    if (now.link_count != before->link_count ||
        memcmp(now.links, before->links, now.link_count * sizeof *now.links) != 0)
        case_failed(file, line, "the navmesh's links changed (%u; were %u)", (unsigned)now.link_count,
                    (unsigned)before->link_count);
    free(now.links);
}
/* The navmesh holds what it held in `before`. */
#define EXPECT_STATE(before, id) expect_state_at(__FILE__, __LINE__, (before), (id))

/* A link where it is, by kind and ends: what a tile's file brings back. */
typedef struct link_place {
    uint32_t kind;
    float start[3], end[3];
    uint32_t holds;
} link_place;

static int compare_places(const void* a, const void* b) { return memcmp(a, b, sizeof(link_place)); }

/* The navmesh's links by place, sorted (malloc'ed; `count` of them). */
static link_place* places_of(nl_navmesh_id id, uint32_t* count) {
    navmesh_state s = state_of(id);
    link_place* places = (link_place*)calloc(s.link_count + 1u, sizeof *places);
    uint32_t i;
    if (!places) exit(2);
    for (i = 0; i < s.link_count; ++i) {
        places[i].kind = (uint32_t)s.links[i].kind;
        memcpy(places[i].start, s.links[i].start, sizeof places[i].start);
        memcpy(places[i].end, s.links[i].end, sizeof places[i].end);
        places[i].holds = s.links[i].holds;
    }
    qsort(places, s.link_count, sizeof *places, compare_places);
    *count = s.link_count;
    free(s.links);
    return places;
}

/* The tile of a navmesh's grid that holds (x, z). */
static nl_tile_coord tile_holding(const nl_navmesh_info* info, float x, float z) {
    nl_tile_coord t;
    t.x = (int32_t)floorf((x - info->tile_origin[0]) / info->tile_width);
    t.z = (int32_t)floorf((z - info->tile_origin[1]) / info->tile_width);
    return t;
}

/* A tiled navmesh Recast builds over A's platforms, with its links generated: tiles of 20 cells of
   0.3 m (6 m) from the pit's corner (-12, -6), so the gap's middle (x = 0) is a line between tiles and
   the jumps across it start on one tile (`owner`, which owns them) and land on the next (`landing`).
   With `take_out`, tile `landing` is removed (the jumps that land on it wait, parked) and the worlds
   as they are then are the reference. */
typedef struct baked_navmesh {
    nl_navmesh_id id;
    nl_navmesh_info info; /* with every tile in */
    nl_tile_coord owner, landing;
    unsigned char *owner_file, *landing_file;
    size_t owner_size, landing_size;
    uint32_t owner_links; /* the links tile `owner` owns: those that start on it */
    link_place* places;   /* every link with every tile in, sorted */
    uint32_t place_count;
} baked_navmesh;
static baked_navmesh g_baked;

static void make_baked(int take_out) {
    nl_navmesh_build_def build = nl_default_navmesh_build_def();
    nl_recast_settings recast = nl_default_recast_settings();
    navmesh_state s;
    uint32_t i;
    int found = 0;
    memset(&g_baked, 0, sizeof g_baked);
    recast.tile_size = 20u;
    build.settings = &recast;
    if (NL_FAILED(nl_navmesh_build(A.world, &build, &g_baked.id))) fixture_failed("the baked navmesh");
    if (NL_FAILED(nl_navmesh_generate_links(A.world, g_baked.id, NULL, NULL, NULL, NULL)))
        fixture_failed("the baked navmesh's links");
    g_baked.info = navmesh_info(&A, g_baked.id);
    if (g_baked.info.tile_count < 4u || g_baked.info.tile_width != 6.0f) fixture_failed("the baked navmesh's tiles");
    s = state_of(g_baked.id);
    for (i = 0; i < s.link_count && !found; ++i) {
        const nl_tile_coord a = tile_holding(&g_baked.info, s.links[i].start[0], s.links[i].start[2]);
        const nl_tile_coord b = tile_holding(&g_baked.info, s.links[i].end[0], s.links[i].end[2]);
        if (s.links[i].generated && (a.x != b.x || a.z != b.z)) {
            g_baked.owner = a;
            g_baked.landing = b;
            found = 1;
        }
    }
    if (!found) fixture_failed("no generated link of the baked navmesh goes from one tile to another");
    for (i = 0; i < s.link_count; ++i) {
        const nl_tile_coord a = tile_holding(&g_baked.info, s.links[i].start[0], s.links[i].start[2]);
        g_baked.owner_links += a.x == g_baked.owner.x && a.z == g_baked.owner.z;
    }
    free(s.links);
    g_baked.places = places_of(g_baked.id, &g_baked.place_count);
    g_baked.owner_file = saved_tile(g_baked.id, g_baked.owner, &g_baked.owner_size);
    g_baked.landing_file = saved_tile(g_baked.id, g_baked.landing, &g_baked.landing_size);
    if (take_out) {
        if (NL_FAILED(nl_navmesh_remove_tile(A.world, g_baked.id, g_baked.landing))) fixture_failed("the tile out");
        fixture_refresh();
    }
}

static void free_baked(void) {
    free(g_baked.owner_file);
    free(g_baked.landing_file);
    free(g_baked.places);
    memset(&g_baked, 0, sizeof g_baked);
}

/* A tiled navmesh of one tile riding the movable lift: the quad on its top as tile (0, 0) of 4 m from
   (40, -2), in the lift's space. */
static nl_navmesh_def riding_tile_def(void) {
    nl_navmesh_def def = quad_navmesh_def();
    def.tile_width = 4.0f;
    def.tile_origin_x = 40.0f;
    def.tile_origin_z = -2.0f;
    def.carrier = A.movable;
    return def;
}

/* What nl_navmesh_file_describe reads of a file (fixture_failed if it cannot). */
static nl_navmesh_file_info file_info(const unsigned char* file, size_t size) {
    nl_navmesh_file_info info;
    memset(&info, 0, sizeof info);
    info.size = sizeof info;
    if (NL_FAILED(nl_navmesh_file_describe(file, size, &info, NULL, 0, NULL))) fixture_failed("describe");
    return info;
}

static uint64_t tile_hash(nl_navmesh_id navmesh, nl_tile_coord tile) {
    uint64_t hash = 0;
    if (NL_FAILED(nl_navmesh_get_tile_hash(A.world, navmesh, tile, &hash))) fixture_failed("nl_navmesh_get_tile_hash");
    return hash;
}

/* nl_navmesh_save_tile of tile g_saved_tile, as a saver of the navmesh it is given. */
static nl_tile_coord g_saved_tile;
static nl_status save_tile_saver(const nl_world* world, nl_navmesh_id navmesh, void* buffer, size_t capacity,
                                 size_t* out_size) {
    return nl_navmesh_save_tile(world, navmesh, g_saved_tile, buffer, capacity, out_size);
}

/* Refused with `detail` naming `needle`: nothing written, the navmesh as it was. */
static void save_tile_fails_with(nl_navmesh_id navmesh, nl_tile_coord tile, nl_status detail, const char* needle) {
    unsigned char buffer[256];
    size_t size;
    navmesh_state before = state_of(navmesh);
    fill(buffer, sizeof buffer);
    fill(&size, sizeof size);
    EXPECT_FAILURE(A.world, nl_navmesh_save_tile(A.world, navmesh, tile, buffer, sizeof buffer, &size), detail, needle);
    EXPECT_UNTOUCHED(buffer, sizeof buffer, "buffer");
    EXPECT_UNTOUCHED(&size, sizeof size, "out_size");
    fill(&size, sizeof size);
    EXPECT_FAILURE(A.world, nl_navmesh_save_tile(A.world, navmesh, tile, NULL, 0, &size), detail, needle);
    EXPECT_UNTOUCHED(&size, sizeof size, "out_size (measuring)");
    EXPECT_STATE(&before, navmesh);
    free(before.links);
}

/* Tiles no navmesh of the fixture has loaded (A's tiled navmesh holds (0, 0) and (1, 0)). */
static const nl_tile_coord k_missing_tiles[] = {
    {2, 0}, {0, 1}, {-1, 0}, {INT32_MAX, INT32_MAX}, {INT32_MIN, INT32_MIN}};
static const char* k_missing_what[] = {"(2, 0): never loaded", "(0, 1): never loaded", "(-1, 0): never loaded",
                                       "huge (INT32_MAX, INT32_MAX)", "huge negative (INT32_MIN, INT32_MIN)"};
#define MISSING_TILE_COUNT (sizeof k_missing_tiles / sizeof *k_missing_tiles)

static void group_navmesh_save_tile(void) {
    size_t needed = 0, k;
    unsigned char* file;
    g_saved_tile = (nl_tile_coord){1, 0};
    file = saved_tile(A.tiled, g_saved_tile, &needed);
    saver_cases_on("nl_navmesh_save_tile", "out_size", save_tile_saver, file, needed, 0, A.tiled, B.tiled);
    for (k = 0; k < MISSING_TILE_COUNT; ++k) {
        CASE("nl_navmesh_save_tile", "tile not loaded %s", k_missing_what[k]) {
            save_tile_fails_with(A.tiled, k_missing_tiles[k], NL_STATUS_NOT_FOUND, "is loaded");
        }
    }
    CASE("nl_navmesh_save_tile", "tile not loaded, named (2, 0)") {
        save_tile_fails_with(A.tiled, (nl_tile_coord){2, 0}, NL_STATUS_NOT_FOUND, "(2, 0)");
    }
    CASE("nl_navmesh_save_tile", "navmesh solo (built whole: not tiled, save it whole)") {
        save_tile_fails_with(A.navmesh, (nl_tile_coord){0, 0}, NL_STATUS_INVALID_ARGUMENT, "not tiled");
    }
    CASE("nl_navmesh_save_tile", "navmesh solo (the host's quad: not tiled)") {
        save_tile_fails_with(A.host_navmesh, (nl_tile_coord){0, 0}, NL_STATUS_INVALID_ARGUMENT, "not tiled");
    }
    CASE("nl_navmesh_save_tile", "navmesh riding the movable lift (a tiled navmesh of one tile on it: save it whole)") {
        const nl_navmesh_def def = riding_tile_def();
        nl_navmesh_id riding;
        size_t size = 0;
        memset(&riding, 0, sizeof riding);
        EXPECT_OK(nl_navmesh_add(A.world, &def, &riding));
        EXPECT(navmesh_info(&A, riding).tile_count == 1u, "the riding navmesh is not tiled");
        save_tile_fails_with(riding, (nl_tile_coord){0, 0}, NL_STATUS_INVALID_ARGUMENT, "moving mesh");
        EXPECT_OK(nl_navmesh_save(A.world, riding, NULL, 0, &size)); /* saved whole, as the message says */
        EXPECT_OK(nl_navmesh_remove(A.world, riding));
    }
    CASE("nl_navmesh_save_tile", "tile (0, 0) and (1, 0) (allowed: each its own tile's file, with its hash)") {
        int t;
        for (t = 0; t < 2; ++t) {
            const nl_tile_coord tile = {t, 0};
            size_t size = 0;
            unsigned char* bytes = saved_tile(A.tiled, tile, &size);
            const nl_navmesh_file_info info = file_info(bytes, size);
            EXPECT(info.is_tile == 1u && info.tile.x == t && info.tile.z == 0,
                   "tile (%d, 0): is_tile %u, tile (%d, %d)", t, (unsigned)info.is_tile, (int)info.tile.x,
                   (int)info.tile.z);
            EXPECT(info.tile_width == TILE_WIDTH && info.tile_origin_x == TILE_ORIGIN_X &&
                       info.tile_origin_z == TILE_ORIGIN_Z,
                   "tile (%d, 0): the grid %g m from (%g, %g)", t, (double)info.tile_width, (double)info.tile_origin_x,
                   (double)info.tile_origin_z);
            EXPECT(info.polygon_count == 1u && info.link_count == 0u && info.rides_carrier == 0u,
                   "tile (%d, 0): %u polygons, %u links", t, (unsigned)info.polygon_count, (unsigned)info.link_count);
            EXPECT(info.content_hash != 0u && info.content_hash == tile_hash(A.tiled, tile),
                   "tile (%d, 0): content_hash %016llx, nl_navmesh_get_tile_hash %016llx", t,
                   (unsigned long long)info.content_hash, (unsigned long long)tile_hash(A.tiled, tile));
            free(bytes);
        }
    }
    free(file);
    make_baked(0);
    fixture_refresh();
    CASE("nl_navmesh_save_tile",
         "tile owning links (allowed: the baked navmesh's; its file holds those that start on it)") {
        const nl_navmesh_file_info info = file_info(g_baked.owner_file, g_baked.owner_size);
        const nl_navmesh_file_info landing = file_info(g_baked.landing_file, g_baked.landing_size);
        EXPECT(info.is_tile == 1u && info.tile.x == g_baked.owner.x && info.tile.z == g_baked.owner.z,
               "is_tile %u, tile (%d, %d)", (unsigned)info.is_tile, (int)info.tile.x, (int)info.tile.z);
        EXPECT(info.link_count == g_baked.owner_links && info.generated_link_count == g_baked.owner_links &&
                   g_baked.owner_links > 0u,
               "%u links in the file (%u generated), the tile owns %u", (unsigned)info.link_count,
               (unsigned)info.generated_link_count, (unsigned)g_baked.owner_links);
        EXPECT(landing.link_count == 0u, "the tile the jumps land on holds %u links in its file, owning none",
               (unsigned)landing.link_count);
        EXPECT(info.tile_width == g_baked.info.tile_width && info.tile_origin_x == g_baked.info.tile_origin[0] &&
                   info.tile_origin_z == g_baked.info.tile_origin[1],
               "the grid %g m from (%g, %g)", (double)info.tile_width, (double)info.tile_origin_x,
               (double)info.tile_origin_z);
        EXPECT(info.content_hash == tile_hash(g_baked.id, g_baked.owner) &&
                   landing.content_hash == tile_hash(g_baked.id, g_baked.landing) &&
                   info.content_hash != landing.content_hash,
               "content_hash %016llx and %016llx are not the tiles' hashes", (unsigned long long)info.content_hash,
               (unsigned long long)landing.content_hash);
        EXPECT(info.level_hash != 0u, "level_hash 0 for a tile Recast built from the level");
    }
    CASE("nl_navmesh_save_tile", "navmesh with a host link on the tile (allowed: the host's links are not in it)") {
        nl_link_def def = nl_default_link_def();
        nl_link_id link;
        size_t size = 0;
        unsigned char* bytes;
        const float x = g_baked.info.tile_origin[0] + ((float)g_baked.owner.x + 0.5f) * g_baked.info.tile_width;
        const float z = g_baked.info.tile_origin[1] + ((float)g_baked.owner.z + 0.5f) * g_baked.info.tile_width;
        def.start[0] = x, def.start[1] = -20.0f, def.start[2] = z;
        def.end[0] = x + 0.5f, def.end[1] = -20.0f, def.end[2] = z;
        memset(&link, 0, sizeof link);
        EXPECT_OK(nl_link_add(A.world, g_baked.id, &def, &link));
        bytes = saved_tile(g_baked.id, g_baked.owner, &size);
        EXPECT(size == g_baked.owner_size && memcmp(bytes, g_baked.owner_file, size) == 0,
               "the tile's file changed with a host link on it");
        free(bytes);
        EXPECT_OK(nl_link_remove(A.world, link));
    }
    free_baked();
}

static nl_status save_tile_file_id_call(nl_world* w, raw_id id, void* out) {
    (void)out;
    return nl_navmesh_save_tile_file(w, AS(nl_navmesh_id, id), (nl_tile_coord){1, 0}, g_save_path);
}

static void group_navmesh_save_tile_file(void) {
    static const id_function f = {"nl_navmesh_save_tile_file", "navmesh", NULL, 0, 0, 0, save_tile_file_id_call, 0};
    static const char* made[] = {"saved.nlnav", "kept.nlnav"};
    char kept[300];
    make_tmp();
    snprintf(g_save_path, sizeof g_save_path, "%s/saved.nlnav", g_tmp);
    snprintf(kept, sizeof kept, "%s/kept.nlnav", g_tmp);
    id_cases(&f, RAW(A.tiled), RAW(A.stale_navmesh), RAW(B.tiled));
    CASE("nl_navmesh_save_tile_file", "path NULL") {
        EXPECT_INVALID(A.world, nl_navmesh_save_tile_file(A.world, A.tiled, (nl_tile_coord){0, 0}, NULL), "path");
    }
    CASE("nl_navmesh_save_tile_file", "path empty") {
        EXPECT_INVALID(A.world, nl_navmesh_save_tile_file(A.world, A.tiled, (nl_tile_coord){0, 0}, ""), "path");
    }
    CASE("nl_navmesh_save_tile_file", "path in a missing folder") {
        char path[300];
        snprintf(path, sizeof path, "%s/no-such-folder/x.nlnav", g_tmp);
        EXPECT_FAILURE(A.world, nl_navmesh_save_tile_file(A.world, A.tiled, (nl_tile_coord){0, 0}, path),
                       NL_STATUS_IO_ERROR, "no-such-folder");
    }
    CASE("nl_navmesh_save_tile_file", "path a directory") {
        char path[300];
        snprintf(path, sizeof path, "%s/dir.obj", g_tmp);
        EXPECT_FAILURE(A.world, nl_navmesh_save_tile_file(A.world, A.tiled, (nl_tile_coord){0, 0}, path),
                       NL_STATUS_IO_ERROR, "dir.obj");
    }
    {
        /* Refused before anything is written: a file at the path stays as it was. */
        static const struct {
            const char* what;
            int navmesh; /* 0: the tiled one, 1: the solo one */
            nl_tile_coord tile;
            nl_status detail;
            const char* needle;
        } refused[] = {
            {"tile not loaded (2, 0): the file at the path kept", 0, {2, 0}, NL_STATUS_NOT_FOUND, "(2, 0)"},
            {"tile not loaded huge (INT32_MIN, INT32_MAX): the file at the path kept",
             0,
             {INT32_MIN, INT32_MAX},
             NL_STATUS_NOT_FOUND,
             "is loaded"},
            {"navmesh solo (built whole: not tiled; the file at the path kept)",
             1,
             {0, 0},
             NL_STATUS_INVALID_ARGUMENT,
             "not tiled"},
        };
        size_t k;
        for (k = 0; k < sizeof refused / sizeof *refused; ++k) {
            CASE("nl_navmesh_save_tile_file", "%s", refused[k].what) {
                static const char old[] = "an old file";
                size_t size = 0;
                unsigned char* bytes;
                write_bytes(kept, old, sizeof old - 1);
                EXPECT_FAILURE(
                    A.world,
                    nl_navmesh_save_tile_file(A.world, refused[k].navmesh ? A.navmesh : A.tiled, refused[k].tile, kept),
                    refused[k].detail, refused[k].needle);
                bytes = read_bytes(kept, &size);
                EXPECT(bytes && size == sizeof old - 1 && memcmp(bytes, old, size) == 0,
                       "the file at the path changed (%u bytes)", (unsigned)size);
                free(bytes);
            }
        }
    }
    CASE("nl_navmesh_save_tile_file", "path writable (allowed: the file is nl_navmesh_save_tile's bytes)") {
        size_t size = 0, got = 0;
        unsigned char* file = saved_tile(A.tiled, (nl_tile_coord){1, 0}, &size);
        unsigned char* read;
        EXPECT_OK(nl_navmesh_save_tile_file(A.world, A.tiled, (nl_tile_coord){1, 0}, g_save_path));
        read = read_bytes(g_save_path, &got);
        EXPECT(read && got == size && memcmp(read, file, size) == 0, "the file holds %u bytes, not the %u saved",
               (unsigned)got, (unsigned)size);
        free(read);
        free(file);
    }
    remove_tmp(made, 2);
}

/* The tile files the add cases give: the host's tile (2, 0) of A's tiled navmesh's grid (accepted),
   tiles of other grids, bodies and link settings, A's own tiles (loaded already), and a whole
   navmesh's file. */
typedef struct tile_files {
    unsigned char *third, *first, *second, *other_grid, *other_body, *other_links, *whole;
    size_t third_size, first_size, second_size, other_grid_size, other_body_size, other_links_size, whole_size;
} tile_files;
static tile_files g_files;

static void make_tile_files(void) {
    nl_navmesh_def def = tile_navmesh_def(2, 0);
    memset(&g_files, 0, sizeof g_files);
    g_files.third = lone_tile_file(def, 0, &g_files.third_size);
    g_files.first = saved_tile(A.tiled, (nl_tile_coord){0, 0}, &g_files.first_size);
    g_files.second = saved_tile(A.tiled, (nl_tile_coord){1, 0}, &g_files.second_size);
    def.tile_origin_x = 61.0f; /* tile (2, 0) of a grid 1 m over */
    g_files.other_grid = lone_tile_file(def, 0, &g_files.other_grid_size);
    def = tile_navmesh_def(2, 0);
    def.agent_type.radius *= 0.5f;
    g_files.other_body = lone_tile_file(def, 0, &g_files.other_body_size);
    g_files.other_links = lone_tile_file(tile_navmesh_def(2, 0), 1, &g_files.other_links_size);
    g_files.whole = saved_navmesh(&g_files.whole_size);
}

static void free_tile_files(void) {
    free(g_files.third);
    free(g_files.first);
    free(g_files.second);
    free(g_files.other_grid);
    free(g_files.other_body);
    free(g_files.other_links);
    free(g_files.whole);
    memset(&g_files, 0, sizeof g_files);
}

static nl_status add_tile_bytes_id_call(nl_world* w, raw_id id, void* out) {
    (void)out;
    return nl_navmesh_add_tile_bytes(w, AS(nl_navmesh_id, id), g_files.third, g_files.third_size);
}

/* Refused with `detail` naming `needle`: the navmesh's info, tiles and links as they were. */
static void add_bytes_fails_with(nl_navmesh_id navmesh, const void* data, size_t size, nl_status detail,
                                 const char* needle) {
    navmesh_state before = state_of(navmesh);
    EXPECT_FAILURE(A.world, nl_navmesh_add_tile_bytes(A.world, navmesh, data, size), detail, needle);
    EXPECT_STATE(&before, navmesh);
    free(before.links);
}

/* A copy of `file` with byte `at` xored with `mask` (at past the end: none changed), malloc'ed. */
static unsigned char* changed_copy(const unsigned char* file, size_t size, size_t at, unsigned char mask) {
    unsigned char* copy = (unsigned char*)malloc(size + 1);
    if (!copy) exit(2);
    memcpy(copy, file, size);
    if (at < size) copy[at] ^= mask;
    return copy;
}

/* An accepted tile on A's tiled navmesh: one tile and polygon more, then removed: as it was. */
static void expect_added_then_remove(nl_tile_coord tile, const navmesh_state* before) {
    nl_navmesh_info after = navmesh_info(&A, A.tiled);
    nl_tile_coord tiles[8];
    const uint32_t count = navmesh_tiles(&A, A.tiled, tiles, 8);
    EXPECT(after.tile_count == 3u && count == 3u && after.polygon_count == before->info.polygon_count + 1u,
           "tile_count %u, %u tiles listed, polygons %u (before %u)", (unsigned)after.tile_count, (unsigned)count,
           (unsigned)after.polygon_count, (unsigned)before->info.polygon_count);
    EXPECT_OK(nl_navmesh_remove_tile(A.world, A.tiled, tile));
    EXPECT_STATE(before, A.tiled);
}

static void group_navmesh_add_tile_bytes(void) {
    static const id_function f = {"nl_navmesh_add_tile_bytes", "navmesh", NULL, 0, 0, 0, add_tile_bytes_id_call, 0};
    size_t i;
    make_tile_files();
    id_cases(&f, RAW(A.tiled), RAW(A.stale_navmesh), RAW(B.tiled));
    CASE("nl_navmesh_add_tile_bytes", "data NULL (size 10)") {
        add_bytes_fails_with(A.tiled, NULL, 10, NL_STATUS_INVALID_ARGUMENT, "data");
    }
    CASE("nl_navmesh_add_tile_bytes", "size huge (data NULL: not read)") {
        add_bytes_fails_with(A.tiled, NULL, SIZE_MAX, NL_STATUS_INVALID_ARGUMENT, "data");
    }
    CASE("nl_navmesh_add_tile_bytes", "size 0 (empty: not a navmesh file)") {
        add_bytes_fails_with(A.tiled, g_files.third, 0, NL_STATUS_VERSION_MISMATCH, "not a NavLink navmesh file");
    }
    CASE("nl_navmesh_add_tile_bytes", "data NULL with size 0 (empty: not a navmesh file)") {
        add_bytes_fails_with(A.tiled, NULL, 0, NL_STATUS_VERSION_MISMATCH, "not a NavLink navmesh file");
    }
    CASE("nl_navmesh_add_tile_bytes", "size short (cut in the middle)") {
        add_bytes_fails_with(A.tiled, g_files.third, g_files.third_size / 2, NL_STATUS_PARSE_ERROR, "truncated");
    }
    CASE("nl_navmesh_add_tile_bytes", "size short (one byte short)") {
        add_bytes_fails_with(A.tiled, g_files.third, g_files.third_size - 1, NL_STATUS_PARSE_ERROR, "truncated");
    }
    CASE("nl_navmesh_add_tile_bytes", "size long (a byte past the file)") {
        unsigned char* bad = changed_copy(g_files.third, g_files.third_size, SIZE_MAX, 0);
        bad[g_files.third_size] = 0;
        add_bytes_fails_with(A.tiled, bad, g_files.third_size + 1, NL_STATUS_PARSE_ERROR, "extra bytes");
        free(bad);
    }
    CASE("nl_navmesh_add_tile_bytes", "data garbage (pseudo-random bytes)") {
        unsigned char garbage[512];
        uint32_t x = 0x9e3779b9u;
        for (i = 0; i < sizeof garbage; ++i) {
            x ^= x << 13, x ^= x >> 17, x ^= x << 5;
            garbage[i] = (unsigned char)x;
        }
        add_bytes_fails_with(A.tiled, garbage, sizeof garbage, NL_STATUS_VERSION_MISMATCH,
                             "not a NavLink navmesh file");
    }
    CASE("nl_navmesh_add_tile_bytes", "data a links JSON file") {
        add_bytes_fails_with(A.tiled, "{\"format\": \"navlink-links\"}", 27, NL_STATUS_VERSION_MISMATCH,
                             "not a NavLink navmesh file");
    }
    CASE("nl_navmesh_add_tile_bytes", "data of a newer format version") {
        unsigned char* bad = changed_copy(g_files.third, g_files.third_size, SIZE_MAX, 0);
        bad[8] = 9;
        add_bytes_fails_with(A.tiled, bad, g_files.third_size, NL_STATUS_VERSION_MISMATCH, "newer");
        free(bad);
    }
    for (i = 40; i < g_files.third_size; i += g_files.third_size / 7) {
        CASE("nl_navmesh_add_tile_bytes", "data with byte %u changed (corrupted)", (unsigned)i) {
            unsigned char* bad = changed_copy(g_files.third, g_files.third_size, i, 0x5a);
            add_bytes_fails_with(A.tiled, bad, g_files.third_size, NL_STATUS_PARSE_ERROR, "corrupted");
            free(bad);
        }
    }
    CASE("nl_navmesh_add_tile_bytes", "data a whole navmesh's file (not a tile)") {
        add_bytes_fails_with(A.tiled, g_files.whole, g_files.whole_size, NL_STATUS_INVALID_ARGUMENT, "not a tile");
    }
    CASE("nl_navmesh_add_tile_bytes", "data a tile loaded already (tile (0, 0)'s own file)") {
        add_bytes_fails_with(A.tiled, g_files.first, g_files.first_size, NL_STATUS_INVALID_ARGUMENT, "loaded already");
    }
    CASE("nl_navmesh_add_tile_bytes", "data a tile loaded already (tile (1, 0)'s own file)") {
        add_bytes_fails_with(A.tiled, g_files.second, g_files.second_size, NL_STATUS_INVALID_ARGUMENT,
                             "(1, 0) is loaded already");
    }
    CASE("nl_navmesh_add_tile_bytes", "data a tile of another grid (tiles of 8 m from (61, -4))") {
        add_bytes_fails_with(A.tiled, g_files.other_grid, g_files.other_grid_size, NL_STATUS_INVALID_ARGUMENT,
                             "another grid");
    }
    CASE("nl_navmesh_add_tile_bytes", "data a tile of another agent type (half the radius)") {
        add_bytes_fails_with(A.tiled, g_files.other_body, g_files.other_body_size, NL_STATUS_INVALID_ARGUMENT,
                             "agent type");
    }
    CASE("nl_navmesh_add_tile_bytes", "data a tile made with link settings (the navmesh's tiles had none)") {
        add_bytes_fails_with(A.tiled, g_files.other_links, g_files.other_links_size, NL_STATUS_INVALID_ARGUMENT,
                             "link settings");
    }
    CASE("nl_navmesh_add_tile_bytes", "navmesh solo (the host's quad: not tiled)") {
        add_bytes_fails_with(A.host_navmesh, g_files.third, g_files.third_size, NL_STATUS_INVALID_ARGUMENT,
                             "not tiled");
    }
    CASE("nl_navmesh_add_tile_bytes", "navmesh solo (built whole by Recast: not tiled)") {
        add_bytes_fails_with(A.navmesh, g_files.third, g_files.third_size, NL_STATUS_INVALID_ARGUMENT, "not tiled");
    }
    CASE("nl_navmesh_add_tile_bytes", "navmesh B's tiled navmesh (foreign), data valid for it") {
        nl_tile_coord tiles[4];
        EXPECT_BAD_HANDLE(A.world, nl_navmesh_add_tile_bytes(A.world, B.tiled, g_files.third, g_files.third_size),
                          "navmesh");
        EXPECT(navmesh_tiles(&B, B.tiled, tiles, 4) == 2u, "B's tiled navmesh changed");
    }
    CASE("nl_navmesh_add_tile_bytes", "data tile (2, 0)'s file (allowed: joined, then removed)") {
        navmesh_state before = state_of(A.tiled);
        EXPECT_OK(nl_navmesh_add_tile_bytes(A.world, A.tiled, g_files.third, g_files.third_size));
        expect_added_then_remove((nl_tile_coord){2, 0}, &before);
        free(before.links);
    }
    CASE("nl_navmesh_add_tile_bytes",
         "data tile (1, 0)'s file once it is out (allowed: the navmesh as it was, bit for bit)") {
        navmesh_state before = state_of(A.tiled);
        EXPECT_OK(nl_navmesh_remove_tile(A.world, A.tiled, (nl_tile_coord){1, 0}));
        EXPECT_OK(nl_navmesh_add_tile_bytes(A.world, A.tiled, g_files.second, g_files.second_size));
        EXPECT_STATE(&before, A.tiled);
        free(before.links);
    }
    CASE("nl_navmesh_add_tile_bytes", "data the same file twice (the second time loaded already)") {
        navmesh_state before = state_of(A.tiled), added;
        EXPECT_OK(nl_navmesh_add_tile_bytes(A.world, A.tiled, g_files.third, g_files.third_size));
        added = state_of(A.tiled);
        EXPECT_FAILURE(A.world, nl_navmesh_add_tile_bytes(A.world, A.tiled, g_files.third, g_files.third_size),
                       NL_STATUS_INVALID_ARGUMENT, "(2, 0) is loaded already");
        EXPECT_STATE(&added, A.tiled);
        expect_added_then_remove((nl_tile_coord){2, 0}, &before);
        free(added.links);
        free(before.links);
    }
    /* The baked navmesh: Recast's tiles with their links, tile `landing` out (the jumps landing on it
       parked). */
    make_baked(1);
    CASE("nl_navmesh_add_tile_bytes", "data the baked tile out, cut in the middle (truncated)") {
        add_bytes_fails_with(g_baked.id, g_baked.landing_file, g_baked.landing_size / 2, NL_STATUS_PARSE_ERROR,
                             "truncated");
    }
    CASE("nl_navmesh_add_tile_bytes", "size 0 (the baked tile out: empty)") {
        add_bytes_fails_with(g_baked.id, g_baked.landing_file, 0, NL_STATUS_VERSION_MISMATCH,
                             "not a NavLink navmesh file");
    }
    for (i = 40; i < g_baked.landing_size; i += g_baked.landing_size / 9) {
        CASE("nl_navmesh_add_tile_bytes", "data the baked tile out with byte %u changed (corrupted)", (unsigned)i) {
            unsigned char* bad = changed_copy(g_baked.landing_file, g_baked.landing_size, i, 0x01);
            add_bytes_fails_with(g_baked.id, bad, g_baked.landing_size, NL_STATUS_PARSE_ERROR, "corrupted");
            free(bad);
        }
    }
    CASE("nl_navmesh_add_tile_bytes", "data a baked tile loaded already (the one owning the jumps)") {
        add_bytes_fails_with(g_baked.id, g_baked.owner_file, g_baked.owner_size, NL_STATUS_INVALID_ARGUMENT,
                             "loaded already");
    }
    CASE("nl_navmesh_add_tile_bytes", "data a host's tile on the baked navmesh (another builder)") {
        add_bytes_fails_with(g_baked.id, g_files.third, g_files.third_size, NL_STATUS_INVALID_ARGUMENT, "builder");
    }
    CASE("nl_navmesh_add_tile_bytes", "data a whole navmesh's file on the baked navmesh (not a tile)") {
        add_bytes_fails_with(g_baked.id, g_files.whole, g_files.whole_size, NL_STATUS_INVALID_ARGUMENT, "not a tile");
    }
    CASE("nl_navmesh_add_tile_bytes", "data a baked tile on the host's tiled navmesh (another builder)") {
        add_bytes_fails_with(A.tiled, g_baked.landing_file, g_baked.landing_size, NL_STATUS_INVALID_ARGUMENT,
                             "builder");
    }
    CASE("nl_navmesh_add_tile_bytes",
         "data the baked tile out (allowed: the parked jumps hold again, the full build's links; then out again)") {
        navmesh_state before = state_of(g_baked.id), back;
        uint32_t count = 0, parked = 0, k;
        link_place* places;
        for (k = 0; k < before.link_count; ++k) parked += before.links[k].holds == 0u;
        EXPECT(parked > 0u, "no link waits for the tile out");
        EXPECT_OK(nl_navmesh_add_tile_bytes(A.world, g_baked.id, g_baked.landing_file, g_baked.landing_size));
        back = state_of(g_baked.id);
        EXPECT(
            back.info.tile_count == g_baked.info.tile_count && back.info.polygon_count == g_baked.info.polygon_count &&
                back.info.vertex_count == g_baked.info.vertex_count,
            "%u tiles, %u polygons and %u vertices; the full build had %u, %u and %u", (unsigned)back.info.tile_count,
            (unsigned)back.info.polygon_count, (unsigned)back.info.vertex_count, (unsigned)g_baked.info.tile_count,
            (unsigned)g_baked.info.polygon_count, (unsigned)g_baked.info.vertex_count);
        places = places_of(g_baked.id, &count);
        EXPECT(count == g_baked.place_count && memcmp(places, g_baked.places, count * sizeof *places) == 0,
               "the links are not the full build's (%u; it had %u)", (unsigned)count, (unsigned)g_baked.place_count);
        for (k = 0; k < count; ++k) EXPECT(places[k].holds == 1u, "link %u still parked", (unsigned)k);
        free(places);
        EXPECT_OK(nl_navmesh_remove_tile(A.world, g_baked.id, g_baked.landing));
        EXPECT_STATE(&before, g_baked.id);
        free(back.links);
        free(before.links);
    }
    CASE("nl_navmesh_add_tile_bytes",
         "data the tile owning the jumps, out and back (allowed: its links back, parked; new ids)") {
        uint32_t before_count = 0, out_count = 0, back_count = 0;
        link_place* before = places_of(g_baked.id, &before_count);
        link_place* out;
        link_place* back;
        EXPECT_OK(nl_navmesh_remove_tile(A.world, g_baked.id, g_baked.owner));
        out = places_of(g_baked.id, &out_count);
        EXPECT(out_count + g_baked.owner_links == before_count, "%u links with the tile out, %u before, it owns %u",
               (unsigned)out_count, (unsigned)before_count, (unsigned)g_baked.owner_links);
        EXPECT_OK(nl_navmesh_add_tile_bytes(A.world, g_baked.id, g_baked.owner_file, g_baked.owner_size));
        back = places_of(g_baked.id, &back_count);
        EXPECT(back_count == before_count && memcmp(back, before, back_count * sizeof *back) == 0,
               "the links are not those before (%u; were %u)", (unsigned)back_count, (unsigned)before_count);
        free(before);
        free(out);
        free(back);
        fixture_refresh(); /* its links' new ids */
    }
    free_baked();
    free_tile_files();
}

static char g_tile_path[256];
static nl_status add_tile_file_id_call(nl_world* w, raw_id id, void* out) {
    (void)out;
    return nl_navmesh_add_tile_file(w, AS(nl_navmesh_id, id), g_tile_path);
}

static void add_file_fails_with(const char* name, nl_status detail, const char* needle) {
    char path[300];
    navmesh_state before = state_of(A.tiled);
    snprintf(path, sizeof path, "%s/%s", g_tmp, name);
    EXPECT_FAILURE(A.world, nl_navmesh_add_tile_file(A.world, A.tiled, path), detail, needle);
    EXPECT_FAILURE(A.world, nl_navmesh_add_tile_file(A.world, A.tiled, path), detail, name); /* the file named */
    EXPECT_STATE(&before, A.tiled);
    free(before.links);
}

static void group_navmesh_add_tile_file(void) {
    static const id_function f = {"nl_navmesh_add_tile_file", "navmesh", NULL, 0, 0, 0, add_tile_file_id_call, 0};
    static const char* made[] = {"third.nltile", "first.nltile", "whole.nlnav",
                                 "short.nltile", "bad.nltile",   "grid.nltile"};
    char path[300];
    size_t k;
    make_tmp();
    make_tile_files();
    snprintf(g_tile_path, sizeof g_tile_path, "%s/third.nltile", g_tmp);
    write_bytes(g_tile_path, g_files.third, g_files.third_size);
    snprintf(path, sizeof path, "%s/first.nltile", g_tmp);
    write_bytes(path, g_files.first, g_files.first_size);
    snprintf(path, sizeof path, "%s/whole.nlnav", g_tmp);
    write_bytes(path, g_files.whole, g_files.whole_size);
    snprintf(path, sizeof path, "%s/short.nltile", g_tmp);
    write_bytes(path, g_files.third, g_files.third_size - 3);
    snprintf(path, sizeof path, "%s/bad.nltile", g_tmp);
    write_file(path, "NLNAV");
    snprintf(path, sizeof path, "%s/grid.nltile", g_tmp);
    write_bytes(path, g_files.other_grid, g_files.other_grid_size);
    id_cases(&f, RAW(A.tiled), RAW(A.stale_navmesh), RAW(B.tiled));
    for (k = 0; k < BAD_PATH_COUNT; ++k) {
        /* The paths every loader refuses (bad_path_cases'), the navmesh left as it was. */
        CASE("nl_navmesh_add_tile_file", "%s", k_bad_paths[k].what) {
            const char* p = k_bad_paths[k].path;
            navmesh_state before = state_of(A.tiled);
            if (k_bad_paths[k].name) {
                snprintf(path, sizeof path, "%s/%s", g_tmp, k_bad_paths[k].name);
                p = path;
            }
            EXPECT_FAILURE(A.world, nl_navmesh_add_tile_file(A.world, A.tiled, p), k_bad_paths[k].detail,
                           k_bad_paths[k].needle);
            EXPECT_STATE(&before, A.tiled);
            free(before.links);
        }
    }
    CASE("nl_navmesh_add_tile_file", "path an OBJ file (named in the message)") {
        add_file_fails_with("quad.obj", NL_STATUS_VERSION_MISMATCH, "not a NavLink navmesh file");
    }
    CASE("nl_navmesh_add_tile_file", "path a 5-byte file") {
        add_file_fails_with("bad.nltile", NL_STATUS_VERSION_MISMATCH, "not a NavLink navmesh file");
    }
    CASE("nl_navmesh_add_tile_file", "path a tile's file 3 bytes short (truncated)") {
        add_file_fails_with("short.nltile", NL_STATUS_PARSE_ERROR, "truncated");
    }
    CASE("nl_navmesh_add_tile_file", "path a whole navmesh's file (not a tile)") {
        add_file_fails_with("whole.nlnav", NL_STATUS_INVALID_ARGUMENT, "not a tile");
    }
    CASE("nl_navmesh_add_tile_file", "path a tile loaded already (tile (0, 0)'s own file)") {
        add_file_fails_with("first.nltile", NL_STATUS_INVALID_ARGUMENT, "loaded already");
    }
    CASE("nl_navmesh_add_tile_file", "path a tile of another grid") {
        add_file_fails_with("grid.nltile", NL_STATUS_INVALID_ARGUMENT, "another grid");
    }
    CASE("nl_navmesh_add_tile_file", "navmesh solo (the host's quad: not tiled)") {
        navmesh_state before = state_of(A.host_navmesh);
        EXPECT_INVALID(A.world, nl_navmesh_add_tile_file(A.world, A.host_navmesh, g_tile_path), "not tiled");
        EXPECT_STATE(&before, A.host_navmesh);
        free(before.links);
    }
    CASE("nl_navmesh_add_tile_file", "path tile (2, 0)'s file (allowed: joined, then removed)") {
        navmesh_state before = state_of(A.tiled);
        EXPECT_OK(nl_navmesh_add_tile_file(A.world, A.tiled, g_tile_path));
        expect_added_then_remove((nl_tile_coord){2, 0}, &before);
        free(before.links);
    }
    free_tile_files();
    remove_tmp(made, sizeof made / sizeof *made);
}

static nl_status get_tile_hash_id_call(nl_world* w, raw_id id, void* out) {
    return nl_navmesh_get_tile_hash(w, AS(nl_navmesh_id, id), (nl_tile_coord){0, 0}, (uint64_t*)out);
}

static void group_navmesh_get_tile_hash(void) {
    static const id_function f = {"nl_navmesh_get_tile_hash", "navmesh", "out_hash", sizeof(uint64_t), 0, 0,
                                  get_tile_hash_id_call,      0};
    const uint64_t first = tile_hash(A.tiled, (nl_tile_coord){0, 0});
    size_t k;
    id_cases(&f, RAW(A.tiled), RAW(A.stale_navmesh), RAW(B.tiled));
    CASE("nl_navmesh_get_tile_hash", "navmesh solo (built whole: not tiled)") {
        uint64_t hash;
        fill(&hash, sizeof hash);
        EXPECT_INVALID(A.world, nl_navmesh_get_tile_hash(A.world, A.navmesh, (nl_tile_coord){0, 0}, &hash),
                       "not tiled");
        EXPECT_UNTOUCHED(&hash, sizeof hash, "out_hash");
    }
    CASE("nl_navmesh_get_tile_hash", "navmesh solo (the host's quad: not tiled)") {
        uint64_t hash;
        fill(&hash, sizeof hash);
        EXPECT_INVALID(A.world, nl_navmesh_get_tile_hash(A.world, A.host_navmesh, (nl_tile_coord){0, 0}, &hash),
                       "not tiled");
        EXPECT_UNTOUCHED(&hash, sizeof hash, "out_hash");
    }
    for (k = 0; k < MISSING_TILE_COUNT; ++k) {
        const int huge = k_missing_tiles[k].x == INT32_MAX || k_missing_tiles[k].x == INT32_MIN ||
                         k_missing_tiles[k].z == INT32_MAX || k_missing_tiles[k].z == INT32_MIN;
        if (huge) {
            CASE("nl_navmesh_get_tile_hash", "tile %s: beyond the grid's tiles", k_missing_what[k]) {
                uint64_t hash;
                fill(&hash, sizeof hash);
                EXPECT_INVALID(A.world, nl_navmesh_get_tile_hash(A.world, A.tiled, k_missing_tiles[k], &hash), "2^30");
                EXPECT_UNTOUCHED(&hash, sizeof hash, "out_hash");
            }
            continue;
        }
        CASE("nl_navmesh_get_tile_hash", "tile not loaded %s (allowed: a hash, not 0, not tile (0, 0)'s)",
             k_missing_what[k]) {
            uint64_t hash = 0;
            EXPECT_OK(nl_navmesh_get_tile_hash(A.world, A.tiled, k_missing_tiles[k], &hash));
            EXPECT(hash != 0u && hash != first, "hash %016llx (tile (0, 0)'s %016llx)", (unsigned long long)hash,
                   (unsigned long long)first);
        }
    }
    CASE("nl_navmesh_get_tile_hash", "tile (0, 0) again (allowed: the same hash, and world B's)") {
        uint64_t again = 0, other = 0;
        EXPECT_OK(nl_navmesh_get_tile_hash(A.world, A.tiled, (nl_tile_coord){0, 0}, &again));
        EXPECT_OK(nl_navmesh_get_tile_hash(B.world, B.tiled, (nl_tile_coord){0, 0}, &other));
        EXPECT(again == first && other == first, "%016llx, then %016llx, in B %016llx", (unsigned long long)first,
               (unsigned long long)again, (unsigned long long)other);
    }
    CASE("nl_navmesh_get_tile_hash", "tile (1, 0) (allowed: its own hash, the one its file records)") {
        uint64_t hash = 0;
        size_t size = 0;
        unsigned char* file = saved_tile(A.tiled, (nl_tile_coord){1, 0}, &size);
        EXPECT_OK(nl_navmesh_get_tile_hash(A.world, A.tiled, (nl_tile_coord){1, 0}, &hash));
        EXPECT(hash != 0u && hash != first && hash == file_info(file, size).content_hash,
               "hash %016llx, tile (0, 0)'s %016llx, the file's %016llx", (unsigned long long)hash,
               (unsigned long long)first, (unsigned long long)file_info(file, size).content_hash);
        free(file);
    }
}

/* Loads of A's navmesh's file into A's world (the new navmesh removed again by the undo). */
static unsigned char* g_navmesh_file;
static size_t g_navmesh_file_size;
static nl_status load_navmesh_call(nl_world* world, const void* def, void* out) {
    return nl_navmesh_load(world, g_navmesh_file, g_navmesh_file_size, (const nl_navmesh_load_def*)def,
                           (nl_navmesh_id*)out);
}
static nl_status load_navmesh_file_call(nl_world* world, const void* def, void* out) {
    return nl_navmesh_load_file(world, g_save_path, (const nl_navmesh_load_def*)def, (nl_navmesh_id*)out);
}
static const def_function k_navmesh_load = {
    "nl_navmesh_load", load_navmesh_call, sizeof(nl_navmesh_id), remove_navmesh_out, 1, 0, 0};
static const def_function k_navmesh_load_file = {
    "nl_navmesh_load_file", load_navmesh_file_call, sizeof(nl_navmesh_id), remove_navmesh_out, 1, 0, 0};

static const def_case k_load_defs[] = {
    {"def->flags unknown bits", INVALID, "flags", {SET_U32(nl_navmesh_load_def, flags, 0x80u)}},
    {"def->flags NL_NAVMESH_LOAD_SAME_LEVEL (allowed: the level is the one it was built from)",
     ALLOWED,
     NULL,
     {SET_U32(nl_navmesh_load_def, flags, NL_NAVMESH_LOAD_SAME_LEVEL)}},
};

static void load_def_cases(const def_function* f) {
    const nl_navmesh_load_def valid = nl_default_navmesh_load_def();
    def_function_cases(f, &valid, sizeof valid);
    def_cases(f->function, &valid, sizeof valid, k_load_defs, sizeof k_load_defs / sizeof *k_load_defs, def_refuses,
              def_accepts);
    optional_id_cases(f, &valid, sizeof valid, offsetof(nl_navmesh_load_def, carrier), "def->carrier", RAW(A.movable),
                      RAW(A.stale_mesh), RAW(B.movable));
}

static void load_data_fails_with(const void* data, size_t size, nl_status detail, const char* needle) {
    nl_navmesh_id out;
    fill(&out, sizeof out);
    EXPECT_FAILURE(A.world, nl_navmesh_load(A.world, data, size, NULL, &out), detail, needle);
    EXPECT_UNTOUCHED(&out, sizeof out, "out_id");
}

static void group_navmesh_load(void) {
    size_t i;
    unsigned char* bad;
    g_navmesh_file = saved_navmesh(&g_navmesh_file_size);
    load_def_cases(&k_navmesh_load);
    CASE("nl_navmesh_load", "data NULL (size 10)") {
        load_data_fails_with(NULL, 10, NL_STATUS_INVALID_ARGUMENT, "data");
    }
    CASE("nl_navmesh_load", "size huge (data NULL: not read)") {
        load_data_fails_with(NULL, SIZE_MAX, NL_STATUS_INVALID_ARGUMENT, "data");
    }
    CASE("nl_navmesh_load", "size 0 (not a navmesh file)") {
        load_data_fails_with(g_navmesh_file, 0, NL_STATUS_VERSION_MISMATCH, "not a NavLink navmesh file");
    }
    CASE("nl_navmesh_load", "size short (cut in the middle)") {
        load_data_fails_with(g_navmesh_file, g_navmesh_file_size / 2, NL_STATUS_PARSE_ERROR, "truncated");
    }
    CASE("nl_navmesh_load", "size long (a byte past the file)") {
        bad = (unsigned char*)malloc(g_navmesh_file_size + 1);
        if (!bad) exit(2);
        memcpy(bad, g_navmesh_file, g_navmesh_file_size);
        bad[g_navmesh_file_size] = 0;
        load_data_fails_with(bad, g_navmesh_file_size + 1, NL_STATUS_PARSE_ERROR, "extra bytes");
        free(bad);
    }
    CASE("nl_navmesh_load", "data a links JSON file") {
        load_data_fails_with("{\"format\": \"navlink-links\"}", 27, NL_STATUS_VERSION_MISMATCH,
                             "not a NavLink navmesh file");
    }
    CASE("nl_navmesh_load", "data of a newer format version") {
        bad = (unsigned char*)malloc(g_navmesh_file_size);
        if (!bad) exit(2);
        memcpy(bad, g_navmesh_file, g_navmesh_file_size);
        bad[8] = 9;
        load_data_fails_with(bad, g_navmesh_file_size, NL_STATUS_VERSION_MISMATCH, "newer");
        free(bad);
    }
    for (i = 40; i < g_navmesh_file_size; i += g_navmesh_file_size / 7) {
        CASE("nl_navmesh_load", "data with byte %u changed (corrupted)", (unsigned)i) {
            bad = (unsigned char*)malloc(g_navmesh_file_size);
            if (!bad) exit(2);
            memcpy(bad, g_navmesh_file, g_navmesh_file_size);
            bad[i] ^= 0x5a;
            load_data_fails_with(bad, g_navmesh_file_size, NL_STATUS_PARSE_ERROR, "corrupted");
            free(bad);
        }
    }
    {
        size_t size = 0;
        unsigned char* tile = saved_tile(A.tiled, (nl_tile_coord){1, 0}, &size);
        CASE("nl_navmesh_load", "data a tile's file (allowed: a tiled navmesh of that one tile)") {
            nl_navmesh_id id;
            memset(&id, 0, sizeof id);
            EXPECT_OK(nl_navmesh_load(A.world, tile, size, NULL, &id));
            if (nl_navmesh_is_valid(A.world, id) == 1) {
                const nl_navmesh_info info = navmesh_info(&A, id);
                nl_tile_coord tiles[4];
                size_t again_size = 0;
                unsigned char* again;
                EXPECT(info.tile_count == 1u && info.polygon_count == 1u && info.tile_width == TILE_WIDTH &&
                           info.tile_origin[0] == TILE_ORIGIN_X && info.tile_origin[1] == TILE_ORIGIN_Z,
                       "tile_count %u, %u polygons, tiles of %g m from (%g, %g)", (unsigned)info.tile_count,
                       (unsigned)info.polygon_count, (double)info.tile_width, (double)info.tile_origin[0],
                       (double)info.tile_origin[1]);
                EXPECT(navmesh_tiles(&A, id, tiles, 4) == 1u && tiles[0].x == 1 && tiles[0].z == 0,
                       "the loaded navmesh does not hold tile (1, 0) alone");
                again = saved_tile(id, (nl_tile_coord){1, 0}, &again_size);
                EXPECT(again_size == size && memcmp(again, tile, size) == 0, "its tile saved again differs");
                free(again);
                EXPECT_OK(nl_navmesh_remove(A.world, id));
            }
        }
        CASE("nl_navmesh_load", "data a tile's file cut short (truncated)") {
            load_data_fails_with(tile, size - 1, NL_STATUS_PARSE_ERROR, "truncated");
        }
        CASE("nl_navmesh_load", "data a tile's file with byte 60 changed (corrupted)") {
            unsigned char* bad = changed_copy(tile, size, 60, 0x10);
            load_data_fails_with(bad, size, NL_STATUS_PARSE_ERROR, "corrupted");
            free(bad);
        }
        free(tile);
    }
    free(g_navmesh_file);
}

static nl_status load_navmesh_at(const char* path, void* out) {
    return nl_navmesh_load_file(A.world, path, NULL, (nl_navmesh_id*)out);
}

static void group_navmesh_load_file(void) {
    static const char* made[] = {"saved.nlnav", "bad.nlnav"};
    char path[300];
    make_tmp();
    snprintf(g_save_path, sizeof g_save_path, "%s/saved.nlnav", g_tmp);
    if (NL_FAILED(nl_navmesh_save_file(A.world, A.navmesh, g_save_path))) fixture_failed("nl_navmesh_save_file");
    load_def_cases(&k_navmesh_load_file);
    bad_path_cases("nl_navmesh_load_file", load_navmesh_at, sizeof(nl_navmesh_id), k_bad_paths, BAD_PATH_COUNT);
    CASE("nl_navmesh_load_file", "path an OBJ file (named in the message)") {
        nl_navmesh_id out;
        fill(&out, sizeof out);
        EXPECT_FAILURE(A.world, nl_navmesh_load_file(A.world, g_obj_path, NULL, &out), NL_STATUS_VERSION_MISMATCH,
                       "quad.obj");
        EXPECT_UNTOUCHED(&out, sizeof out, "out_id");
    }
    snprintf(path, sizeof path, "%s/bad.nlnav", g_tmp);
    write_file(path, "NLNAV");
    CASE("nl_navmesh_load_file", "path a 5-byte file") {
        nl_navmesh_id out;
        fill(&out, sizeof out);
        EXPECT_FAILURE(A.world, nl_navmesh_load_file(A.world, path, NULL, &out), NL_STATUS_VERSION_MISMATCH,
                       "bad.nlnav");
        EXPECT_UNTOUCHED(&out, sizeof out, "out_id");
    }
    remove_tmp(made, 2);
}

static void describe_fails_with(const void* data, size_t size, nl_navmesh_file_info* info, char* json, size_t capacity,
                                size_t* length, nl_status detail, const char* needle) {
    EXPECT_FAILURE(NULL, nl_navmesh_file_describe(data, size, info, json, capacity, length), detail, needle);
}

static void group_navmesh_file_describe(void) {
    size_t size = 0, length, needed = 0;
    unsigned char* file = saved_navmesh(&size);
    nl_navmesh_file_info info;
    char json[4096];
    if (NL_FAILED(nl_navmesh_file_describe(file, size, NULL, NULL, 0, &needed)) || needed + 1 > sizeof json)
        fixture_failed("nl_navmesh_file_describe");
    CASE("nl_navmesh_file_describe", "data NULL (size 10)") {
        describe_fails_with(NULL, 10, NULL, NULL, 0, &length, NL_STATUS_INVALID_ARGUMENT, "data");
    }
    CASE("nl_navmesh_file_describe", "size huge (data NULL: not read)") {
        describe_fails_with(NULL, SIZE_MAX, NULL, NULL, 0, &length, NL_STATUS_INVALID_ARGUMENT, "data");
    }
    CASE("nl_navmesh_file_describe", "size 0 (not a navmesh file)") {
        describe_fails_with(file, 0, NULL, NULL, 0, &length, NL_STATUS_VERSION_MISMATCH, "not a NavLink navmesh file");
    }
    CASE("nl_navmesh_file_describe", "size short (truncated)") {
        describe_fails_with(file, size - 1, NULL, NULL, 0, &length, NL_STATUS_PARSE_ERROR, "truncated");
    }
    CASE("nl_navmesh_file_describe", "out_info NULL (allowed: the JSON only)") {
        EXPECT_OK(nl_navmesh_file_describe(file, size, NULL, json, sizeof json, &length));
        EXPECT(length == needed && strstr(json, "\"builder\"") != NULL, "the JSON: %s", json);
    }
    {
        static const char* what[3] = {"0", "small (4)", "large (sizeof + 64: nothing written past the struct)"};
        int k;
        for (k = 0; k < 3; ++k) {
            CASE("nl_navmesh_file_describe", "out_info->size %s", what[k]) {
                unsigned char buffer[sizeof(nl_navmesh_file_info) + 64];
                const uint32_t sizes[3] = {0u, 4u, (uint32_t)sizeof buffer};
                fill(buffer, sizeof buffer);
                memcpy(buffer, &sizes[k], sizeof sizes[k]);
                if (k < 2) {
                    describe_fails_with(file, size, (nl_navmesh_file_info*)buffer, NULL, 0, NULL,
                                        NL_STATUS_INVALID_ARGUMENT, "size");
                    EXPECT_UNTOUCHED(buffer + 4, sizeof buffer - 4, "out_info");
                } else {
                    nl_navmesh_file_info got;
                    EXPECT_OK(nl_navmesh_file_describe(file, size, (nl_navmesh_file_info*)buffer, NULL, 0, NULL));
                    memcpy(&got, buffer, sizeof got);
                    EXPECT(got.version == 1 && got.file_size == size && got.polygon_count > 0, "the info read back");
                    EXPECT_UNTOUCHED(buffer + sizeof got, 64, "the bytes past out_info");
                }
            }
        }
    }
    CASE("nl_navmesh_file_describe", "data a whole navmesh's file (allowed: is_tile 0, the tile fields 0)") {
        const nl_navmesh_file_info got = file_info(file, size);
        EXPECT(got.is_tile == 0u && got.content_hash == 0u && got.tile.x == 0 && got.tile.z == 0 &&
                   got.tile_width == 0.0f && got.tile_origin_x == 0.0f && got.tile_origin_z == 0.0f,
               "is_tile %u, content_hash %016llx, tile (%d, %d), tile_width %g", (unsigned)got.is_tile,
               (unsigned long long)got.content_hash, (int)got.tile.x, (int)got.tile.z, (double)got.tile_width);
    }
    {
        size_t tile_size = 0;
        unsigned char* tile = saved_tile(A.tiled, (nl_tile_coord){1, 0}, &tile_size);
        CASE("nl_navmesh_file_describe", "data a tile's file (allowed: is_tile, the tile, its grid and content hash)") {
            const nl_navmesh_file_info got = file_info(tile, tile_size);
            uint64_t hash = 0;
            EXPECT_OK(nl_navmesh_get_tile_hash(A.world, A.tiled, (nl_tile_coord){1, 0}, &hash));
            EXPECT(got.is_tile == 1u && got.tile.x == 1 && got.tile.z == 0 && got.tile_width == TILE_WIDTH &&
                       got.tile_origin_x == TILE_ORIGIN_X && got.tile_origin_z == TILE_ORIGIN_Z,
                   "is_tile %u, tile (%d, %d), tiles of %g m from (%g, %g)", (unsigned)got.is_tile, (int)got.tile.x,
                   (int)got.tile.z, (double)got.tile_width, (double)got.tile_origin_x, (double)got.tile_origin_z);
            EXPECT(got.content_hash == hash && hash != 0u, "content_hash %016llx, nl_navmesh_get_tile_hash %016llx",
                   (unsigned long long)got.content_hash, (unsigned long long)hash);
            EXPECT(got.file_size == tile_size && got.polygon_count == 1u && got.link_count == 0u,
                   "file_size %u, %u polygons, %u links", (unsigned)got.file_size, (unsigned)got.polygon_count,
                   (unsigned)got.link_count);
        }
        CASE("nl_navmesh_file_describe",
             "out_info->size small (0.2's: level_hash's end; the tile fields, added in 0.3, not written)") {
            unsigned char buffer[sizeof(nl_navmesh_file_info) + 64];
            const size_t first = offsetof(nl_navmesh_file_info, content_hash);
            const uint32_t old_size = (uint32_t)first;
            nl_navmesh_file_info got;
            fill(buffer, sizeof buffer);
            memcpy(buffer, &old_size, sizeof old_size);
            EXPECT_OK(nl_navmesh_file_describe(tile, tile_size, (nl_navmesh_file_info*)buffer, NULL, 0, NULL));
            memcpy(&got, buffer, first);
            EXPECT(got.size == old_size && got.file_size == tile_size && got.polygon_count == 1u,
                   "size %u, file_size %u, %u polygons", (unsigned)got.size, (unsigned)got.file_size,
                   (unsigned)got.polygon_count);
            EXPECT_UNTOUCHED(buffer + first, sizeof buffer - first, "the bytes past the caller's size");
        }
        CASE("nl_navmesh_file_describe", "size short (a tile's file, truncated)") {
            describe_fails_with(tile, tile_size - 1, NULL, NULL, 0, &length, NL_STATUS_PARSE_ERROR, "truncated");
        }
        free(tile);
    }
    CASE("nl_navmesh_file_describe", "made_for_json NULL (allowed with capacity 0: measures)") {
        fill(&length, sizeof length);
        EXPECT_OK(nl_navmesh_file_describe(file, size, NULL, NULL, 0, &length));
        EXPECT(length == needed, "out_length = %u", (unsigned)length);
    }
    CASE("nl_navmesh_file_describe", "capacity 0 (a buffer given)") {
        fill(json, sizeof json);
        describe_fails_with(file, size, NULL, json, 0, &length, NL_STATUS_BUFFER_TOO_SMALL, "capacity");
        EXPECT_UNTOUCHED(json, sizeof json, "made_for_json");
        EXPECT(length == needed, "out_length = %u, expected the %u needed", (unsigned)length, (unsigned)needed);
    }
    CASE("nl_navmesh_file_describe", "capacity small (the length: no room for the NUL)") {
        fill(json, sizeof json);
        describe_fails_with(file, size, NULL, json, needed, &length, NL_STATUS_BUFFER_TOO_SMALL, "capacity");
        EXPECT_UNTOUCHED(json, sizeof json, "made_for_json");
        EXPECT(length == needed, "out_length = %u, expected the %u needed", (unsigned)length, (unsigned)needed);
    }
    CASE("nl_navmesh_file_describe", "capacity huge (buffer NULL)") {
        describe_fails_with(file, size, NULL, NULL, SIZE_MAX, &length, NL_STATUS_INVALID_ARGUMENT, "made_for_json");
    }
    CASE("nl_navmesh_file_describe", "out_length NULL (a buffer given)") {
        fill(json, sizeof json);
        describe_fails_with(file, size, NULL, json, sizeof json, NULL, NL_STATUS_INVALID_ARGUMENT, "out_length");
        EXPECT_UNTOUCHED(json, sizeof json, "made_for_json");
    }
    CASE("nl_navmesh_file_describe", "out_info with out_length NULL (allowed: the info only)") {
        memset(&info, 0, sizeof info);
        info.size = sizeof info;
        EXPECT_OK(nl_navmesh_file_describe(file, size, &info, NULL, 0, NULL));
        EXPECT(info.quantum == 1.0f / 1024.0f && info.link_count > 0, "quantum %g, %u links", (double)info.quantum,
               (unsigned)info.link_count);
    }
    free(file);
}

/* This part's groups, in the order they run. */
static const hostile_group k_groups[] = {
    {"navmesh_save", group_navmesh_save},
    {"navmesh_save_file", group_navmesh_save_file},
    {"navmesh_save_tile", group_navmesh_save_tile},
    {"navmesh_save_tile_file", group_navmesh_save_tile_file},
    {"navmesh_add_tile_bytes", group_navmesh_add_tile_bytes},
    {"navmesh_add_tile_file", group_navmesh_add_tile_file},
    {"navmesh_get_tile_hash", group_navmesh_get_tile_hash},
    {"navmesh_load", group_navmesh_load},
    {"navmesh_load_file", group_navmesh_load_file},
    {"navmesh_file_describe", group_navmesh_file_describe},
};
const hostile_part hostile_navmesh_file_part = {k_groups, sizeof k_groups / sizeof *k_groups};
