/*
 * What the cases of navlink-abi-hostile-test share (hostile_fixtures.c): the bad values, the two
 * worlds every group runs against, and the shapes the cases take (defs made bad field by field,
 * sizes, ids, lists, paths, savers). Each hostile_<part>_tests.c includes it and holds the cases of
 * the functions its part of the headers declares. Strict C11 through the C ABI only.
 */
#ifndef NAVLINK_ABI_HOSTILE_FIXTURES_H
#define NAVLINK_ABI_HOSTILE_FIXTURES_H

#include "hostile.h"

#include <stddef.h>
#include <stdint.h>

/* ---------------------------------------------------------------------------------------------
 * Bad values
 * ------------------------------------------------------------------------------------------- */

typedef struct bad_float {
    const char* name;
    float value;
} bad_float;
extern const bad_float k_bad_floats[3]; /* NaN, inf, -inf */
#define BAD_FLOAT_COUNT (sizeof k_bad_floats / sizeof *k_bad_floats)

/* Ids by value, whatever their type: every nl_*_id is {index1, revision}. */
typedef struct raw_id {
    uint32_t index1, revision;
} raw_id;
#define RAW(id) ((raw_id){(id).index1, (id).revision})
#define AS(type, r) ((type){(r).index1, (r).revision})

typedef struct bad_id {
    char what[64]; /* "null", "stale", "garbage {1, 2}", "foreign" */
    raw_id id;
} bad_id;
#define MAX_BAD_IDS 12

/* The ids that must be refused where `live` is accepted. `stale` is {0, 0} where no id can go stale. */
size_t bad_ids(raw_id live, raw_id stale, raw_id foreign, bad_id* out);

/* Runs the block once per bad id, with `bad` naming the current one. */
#define FOR_BAD_IDS(bad, live, stale, foreign)                                                                   \
    for (bad_id bad##_all_[MAX_BAD_IDS],                                                                         \
         *bad = bad##_all_, *bad##_end_ = bad##_all_ + bad_ids(RAW(live), RAW(stale), RAW(foreign), bad##_all_); \
         bad < bad##_end_; ++bad)

/* A buffer aligned for any struct, for defs copied and made bad. */
typedef union aligned_buffer {
    max_align_t align;
    unsigned char bytes[2048];
} aligned_buffer;

/* Area costs made bad, for path requests and query filters. */
extern const float k_costs_nan[3], k_costs_inf[3], k_costs_minus_inf[3], k_costs_negative[3];
extern float k_costs_257[257];

/* ---------------------------------------------------------------------------------------------
 * The worlds: A is under test; B, built the same way, issues the foreign ids
 * ------------------------------------------------------------------------------------------- */

typedef struct world_fixture {
    nl_world* world;
    nl_mesh_id mesh, movable, stale_mesh;                     /* mesh took stale_mesh's slot */
    nl_navmesh_id navmesh, host_navmesh, stale_navmesh;       /* navmesh took stale_navmesh's */
    nl_link_id link, stale_link;                              /* the manual link; a generated one took stale_link's */
    nl_plugin_id plugin;                                      /* the built-in Recast builder */
    nl_path_ticket done_ticket, pending_ticket, stale_ticket; /* pending took stale_ticket's */
    nl_agent_id agent, flyer, stale_agent; /* agent walks (took stale_agent's slot); flyer is in the air */
    nl_navmesh_id tiled;   /* a host's tiled navmesh: tiles (0, 0) and (1, 0) of tile_navmesh_def's grid */
    uint32_t agent_events; /* the events of the fixture's last step */
    unsigned char* fingerprint;
    size_t fingerprint_size;
} world_fixture;

extern world_fixture A, B;

/* The runner's fixture: builds A and B in the child, compares everything they hold after each case
   with how it was when the group started (or last refreshed), destroys them after the group. */
extern const hostile_fixture hostile_worlds;

/* The top of the movable box (the lift), handed over as a navmesh: one quad, counter-clockwise from
   above, with its height detail. */
nl_navmesh_def quad_navmesh_def(void);
/* The tiled navmesh's grid: tiles of TILE_WIDTH m from (TILE_ORIGIN_X, TILE_ORIGIN_Z), beyond the
   lift (x 60 and up), TILE_COLUMNS by TILE_ROWS of them with polygons at hand. */
#define TILE_WIDTH 8.0f
#define TILE_ORIGIN_X 60.0f
#define TILE_ORIGIN_Z -4.0f
#define TILE_COLUMNS 4
#define TILE_ROWS 2
/* Tile (tile_x, tile_z) of that grid (0 <= tile_x < TILE_COLUMNS, 0 <= tile_z < TILE_ROWS; others
   are fixture_failed): one quad filling its square, counter-clockwise from above, with its height
   detail, as quad_navmesh_def. Its arrays are the fixture's, for the life of the child. */
nl_navmesh_def tile_navmesh_def(int32_t tile_x, int32_t tile_z);
/* The tiles a navmesh of `f` has loaded (at most `capacity`); fixture_failed if they cannot be read. */
uint32_t navmesh_tiles(const world_fixture* f, nl_navmesh_id id, nl_tile_coord* out, uint32_t capacity);
/* The manual link across the gap, 1.5 m inside each rim. */
nl_link_def gap_link_def(void);
/* From one platform to the other for an agent that jumps 6 m: it takes a link. */
nl_path_request_def gap_request(nl_navmesh_id navmesh);
/* An agent that jumps what the known path needs, on `navmesh` at (x, 0, z). */
nl_agent_def jumper_def(nl_navmesh_id navmesh, float x, float z);
/* Jumping, falling or traversing a link. */
int in_the_air(nl_agent_state state);
/* What a group needed from the worlds failed: says so and ends the child (exit code 4). */
void fixture_failed(const char* what);
/* A navmesh's info, read outside a case's checks (fixture_failed if it cannot be read). */
nl_navmesh_info navmesh_info(const world_fixture* f, nl_navmesh_id id);

/* The command line's paths (NULL when not given): libnavlink.so, a library without
   nl_plugin_entry, and the climb plugin. */
extern const char* g_library_path;
extern const char* g_plugin_path;

/* ---------------------------------------------------------------------------------------------
 * Calls by id and lists of a world
 * ------------------------------------------------------------------------------------------- */

/* Calls that describe one object, or list a world's: the fingerprint's, and the cases'. */
typedef nl_status id_call_fn(nl_world* world, raw_id id, void* out);
typedef nl_status world_list_fn(const nl_world* world, void* out, uint32_t capacity, uint32_t* out_count);

/* Adapters of the id-taking functions to id_call_fn: with no output, with an output of a type, and
   the nl_*_is_valid functions (answered() turns the 0 they must return into the recorded status). */
#define ID_CALL_THROUGH(name, id_type, function, through)      \
    static nl_status name(nl_world* w, raw_id id, void* out) { \
        (void)out;                                             \
        return through(function(w, AS(id_type, id)));          \
    }
#define ID_CALL(name, id_type, function) ID_CALL_THROUGH(name, id_type, function, )
#define ID_VALID_CALL(name, id_type, function) ID_CALL_THROUGH(name, id_type, function, answered)
#define ID_OUT_CALL(name, id_type, out_type, function) \
    static nl_status name(nl_world* w, raw_id id, void* out) { return function(w, AS(id_type, id), (out_type*)out); }
/* What an nl_*_is_valid returned, as the recorded status; a 1 for a bad id is reported. */
nl_status answered(int32_t valid);

/* The ones the fingerprint uses too. */
nl_status mesh_get_info_call(nl_world* w, raw_id id, void* out);
nl_status navmesh_get_info_call(nl_world* w, raw_id id, void* out);
nl_status description_call(nl_world* w, raw_id id, void* out);
nl_status get_meshes(const nl_world* w, void* out, uint32_t capacity, uint32_t* count);
nl_status get_navmeshes(const nl_world* w, void* out, uint32_t capacity, uint32_t* count);
nl_status get_plugins(const nl_world* w, void* out, uint32_t capacity, uint32_t* count);

/* ---------------------------------------------------------------------------------------------
 * Defs made bad field by field
 * ------------------------------------------------------------------------------------------- */

/* A copy of a def in an aligned buffer, the bytes after it SENTINEL. */
void* copy_def(aligned_buffer* buffer, const void* def, size_t size);
void set_size(void* def, uint32_t size);

/* Calls the function under test with `def` and checks it failed with `detail` naming `needle`,
   its outputs untouched. */
typedef void refuse_fn(const void* def, nl_status detail, const char* needle);
/* Calls it with `def`, checks it succeeded, and undoes what it did (or takes the worlds as they
   are now as the reference, where the change cannot be undone, as a generation's new link ids). */
typedef void accept_fn(const void* def);

/* One field of a def set to a value: offset and size of the member, and the value's bytes. */
typedef struct field_value {
    size_t offset, size; /* size 0: no change */
    union {
        uint32_t u32;
        int32_t i32;
        size_t length;
        float f32;
        const void* pointer;
    } as;
} field_value;
#define SET_U32(type, member, v)                                 \
    {                                                            \
        offsetof(type, member), sizeof(uint32_t), { .u32 = (v) } \
    }
#define SET_I32(type, member, v)                                \
    {                                                           \
        offsetof(type, member), sizeof(int32_t), { .i32 = (v) } \
    }
#define SET_LENGTH(type, member, v)                               \
    {                                                             \
        offsetof(type, member), sizeof(size_t), { .length = (v) } \
    }
#define SET_F32(type, member, v)                              \
    {                                                         \
        offsetof(type, member), sizeof(float), { .f32 = (v) } \
    }
#define SET_PTR(type, member, v)                                        \
    {                                                                   \
        offsetof(type, member), sizeof(const void*), { .pointer = (v) } \
    }

/* A def made bad (or unusual but allowed) by up to six fields: detail 0 means it is accepted. */
typedef struct def_case {
    const char* description;
    nl_status detail;
    const char* needle;
    field_value set[6];
} def_case;
#define ALLOWED 0u
#define INVALID NL_STATUS_INVALID_ARGUMENT

/* Each case a copy of `valid` with its fields set, refused or accepted as the case says. */
void def_cases(const char* function, const void* valid, size_t size, const def_case* cases, size_t count,
               refuse_fn* refuse, accept_fn* accept);

/* A text a function reads, (data, length) as given (OBJ, JSON), and how it must refuse it. */
typedef struct text_case {
    const char* what;
    const char* data;
    size_t length;
    nl_status detail;
    const char* needle;
} text_case;
#define TEXT(literal) literal, sizeof literal - 1

/* A float field of a def (or of an array element): its name as the message spells it, its offset,
   how many floats it has. */
typedef struct float_field {
    const char* name;
    size_t offset;
    unsigned count;
} float_field;
#define FLOAT_FIELD(type, member, n) \
    { #member, offsetof(type, member), (n) }

/* Each float of each field set to each bad value in turn ("def->start[1] NaN"), refused naming it. */
void bad_float_fields(const char* function, const char* param, const void* valid, size_t size,
                      const float_field* fields, size_t field_count, refuse_fn* refuse);

/* A def's `size` 0, too small (4: the size field alone) and larger than the library's struct (the
   bytes past it are garbage the library must not read as fields). */
void def_sizes(const char* function, const char* param, const void* valid, size_t size, refuse_fn* refuse,
               accept_fn* accept);

/* A function that makes something from a def: `call` runs it on `world` with `def`, writing the
   new object's id (or world) to `out`; `undo` checks an accepted def's object and removes it. */
typedef nl_status def_call_fn(nl_world* world, const void* def, void* out);
typedef struct def_function {
    const char* function;
    def_call_fn* call;
    size_t out_size;
    void (*undo)(const void* out);
    int def_optional;         /* a NULL def means the defaults */
    int no_world;             /* nl_world_create: no world to pass (nor log) */
    int world_null_elsewhere; /* its world NULL case is its id cases' */
} def_function;
extern const def_function* g_def; /* the function the def cases run now */

/* g_def's refuse_fn and accept_fn. */
void def_refuses(const void* def, nl_status detail, const char* needle);
void def_accepts(const void* def);

/* The world, the def and the output NULL, and the def's size. */
void def_function_cases(const def_function* f, const void* valid, size_t size);

/* What every geometry def has (nl_mesh_def, nl_navmesh_def): vertex and index arrays. Their rows
   are the same for each, made from the def's offsets and its vertices made bad. */
typedef struct geometry_fields {
    size_t vertices, vertex_count, vertex_stride, indices;
    const float* bad_vertices[3]; /* NaN, inf and -inf at the vertex `bad_vertex` names */
    const char* bad_vertex;
} geometry_fields;
#define GEOMETRY_FIELDS(type) \
    offsetof(type, vertices), offsetof(type, vertex_count), offsetof(type, vertex_stride), offsetof(type, indices)
void geometry_cases(const char* function, const void* valid, size_t size, const geometry_fields* g);

/* A def's optional id at `offset`, named `field` ("def->carrier"): the null id is allowed (the
   def's default), every other bad id is INVALID_HANDLE naming the field. */
void optional_id_cases(const def_function* f, const void* valid, size_t size, size_t offset, const char* field,
                       raw_id live, raw_id stale, raw_id foreign);

/* A navmesh added (built, loaded) as documented is valid, and is removed: an undo of def_function. */
void remove_navmesh_out(const void* out);

/* Progress callbacks: one that cancels at once (counting its calls in *(int*)user), one that
   notes the user it was passed in g_user_seen and goes on. */
int32_t cancel_at_once(void* user, float fraction, const char* stage);
int32_t note_user(void* user, float fraction, const char* stage);
extern void* g_user_seen;

/* ---------------------------------------------------------------------------------------------
 * Outputs: sizes, ids, lists, savers
 * ------------------------------------------------------------------------------------------- */

/* An output struct with a `size` field: `call` runs the function with `out` and returns its
   status. Size 0 and 4 are refused with nothing written; sizeof - 1 is either refused or written
   only up to that size; a larger size is accepted and nothing past the library's struct is written. */
typedef nl_status out_call_fn(void* out);
void out_sizes(const char* function, const char* param, size_t size, out_call_fn* call);

/* An output of growable elements (an array laid out by its first element's `size`, or one such
   struct): `call` runs the function with `out` (room for 256 elements of sizeof + 64 bytes) and
   says how many elements a success wrote. Size 0, 4 and sizeof - 1 (no element's size: not a multiple
   of its alignment) are refused with nothing written; a larger size (a newer header's elements) lays
   the array out with that stride, sets each element's size to it and writes nothing past the
   library's part of each. */
typedef nl_status element_call_fn(void* out, uint32_t* written);
void out_element_sizes(const char* function, const char* param, size_t size, element_call_fn* call);

/* A function that takes an id: `call` runs it on `world` with `id` and the output `out` (NULL when
   the case passes none); for an nl_*_is_valid function it returns the recorded status and
   reports a 1. */
typedef struct id_function {
    const char* function;
    const char* param;    /* the id's parameter, and the word the message names it by */
    const char* out_name; /* NULL: no output */
    size_t out_size;
    int growable; /* the output starts with `size`, set by the caller */
    int answers;  /* an nl_*_is_valid: a bad id is an answer (0), not an error */
    id_call_fn* call;
    int out_null_elsewhere; /* the output NULL has cases of its own (optional, or a list's) */
} id_function;

/* The world NULL, the output NULL, and every bad id (named in the message by the last word of
   the parameter: "navmesh" for def->navmesh). */
void id_cases(const id_function* f, raw_id live, raw_id stale, raw_id foreign);

/* The two-call list pattern: `call` runs the function with (out, capacity, out_count). A list of
   growable elements (nl_link...) is laid out with its first element's `size`: set
   g_growable_items around its cases. */
typedef nl_status list_call_fn(void* out, uint32_t capacity, uint32_t* out_count);
extern int g_growable_items;
void list_cases(const char* function, const char* out_name, size_t item_size, uint32_t expected, list_call_fn* call);

/* A list with a world of its own: the world NULL too. */
void world_list_cases(const char* function, const char* out_name, size_t item_size, uint32_t expected,
                      world_list_fn* call);

/* The list functions of a navmesh, with their id cases: `call` lists from A's navmesh. */
typedef nl_status navmesh_list_fn(const nl_world* world, nl_navmesh_id navmesh, void* out, uint32_t capacity,
                                  uint32_t* out_count);
void navmesh_list_cases(const char* function, const char* out_name, size_t item_size, uint32_t expected,
                        navmesh_list_fn* call);
/* The same from another of A's navmeshes (`live`; `foreign` is B's in its slot). */
void navmesh_list_cases_on(const char* function, const char* out_name, size_t item_size, uint32_t expected,
                           navmesh_list_fn* call, nl_navmesh_id live, nl_navmesh_id foreign);

/* A navmesh's savers (nl_navmesh_save_links_json, nl_navmesh_save): they write into a caller's
   buffer with the two-call pattern and a size_t length (the list cases of uint32_t counts do not
   apply). Every case of a saver: its ids, its output, its buffer. `expected` is what it writes
   (`needed` bytes, then `terminator` more: the NUL of a text). */
typedef nl_status navmesh_saver(const nl_world* world, nl_navmesh_id navmesh, void* buffer, size_t capacity,
                                size_t* out_length);
void saver_cases(const char* function, const char* out_name, navmesh_saver* saver, const unsigned char* expected,
                 size_t needed, size_t terminator);
/* The same on another of A's navmeshes (`live`; `foreign` is B's in its slot): a tile's saver saves
   from the tiled navmesh. */
void saver_cases_on(const char* function, const char* out_name, navmesh_saver* saver, const unsigned char* expected,
                    size_t needed, size_t terminator, nl_navmesh_id live, nl_navmesh_id foreign);

/* ---------------------------------------------------------------------------------------------
 * Files: a folder of the child's own, and the paths every loader refuses
 * ------------------------------------------------------------------------------------------- */

/* A quad as OBJ text, written as quad.obj into the folder. */
extern const char k_obj[];
extern char g_tmp[64];       /* the folder */
extern char g_obj_path[128]; /* k_obj as a file */

/* Writes `text` to `path` (exit code 4 if it cannot). */
void write_file(const char* path, const char* text);
/* Makes the folder, with quad.obj and an empty folder dir.obj in it. */
void make_tmp(void);
/* Removes the folder and the files the group made in it. */
void remove_tmp(const char* const* names, size_t count);

/* A path a loader must refuse: `name` in the group's folder, or `path` as it is. */
typedef struct bad_path {
    const char* what;
    const char* name; /* under the folder; NULL: the path as given */
    const char* path;
    nl_status detail;
    const char* needle;
} bad_path;
void bad_path_cases(const char* function, nl_status (*load)(const char* path, void* out), size_t out_size,
                    const bad_path* paths, size_t count);

/* Paths every loader refuses (an OBJ file, a plugin), with the folder of make_tmp. */
extern const bad_path k_bad_paths[4];
#define BAD_PATH_COUNT (sizeof k_bad_paths / sizeof *k_bad_paths)

/* ---------------------------------------------------------------------------------------------
 * The last error record
 * ------------------------------------------------------------------------------------------- */

/* Something failed first, so the record holds a failure a call that must not touch it could clear. */
void fail_on_purpose(void);
/* The record still holds fail_on_purpose's failure. */
int record_is_the_failure(void);

#endif /* NAVLINK_ABI_HOSTILE_FIXTURES_H */
