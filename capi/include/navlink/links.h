/*
 * navlink/links.h: Links: jumps, drops and manual traversals on a navmesh; their generation and their files.
 * A part of navlink/navlink.h, which includes every part; its opening comment has the conventions.
 */
#ifndef NAVLINK_LINKS_H
#define NAVLINK_LINKS_H

#include "navlink/navmesh.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------------------------------------
 * Links: jumps, drops and manual traversals, each belonging to a navmesh. Generated links are
 * replaced by each generation; manual links are never touched by it.
 * ------------------------------------------------------------------------------------------- */

/** The first link kind a plugin may use (nl_link_kind). */
#define NL_LINK_FIRST_PLUGIN_KIND 256u

/** Link kinds. Plugin kinds are numbered from NL_LINK_FIRST_PLUGIN_KIND. */
typedef uint32_t nl_link_kind;
#define NL_LINK_JUMP 1u   /**< Edge to edge across a gap, along a parabolic arc. */
#define NL_LINK_DROP 2u   /**< Off an edge down to the floor below. */
#define NL_LINK_MANUAL 3u /**< Placed by the host. */

/** What taking a link asks of an agent, going from its start to its end. Going the other way over
 *  a bidirectional link swaps rise and drop. */
typedef struct nl_link_requirements {
    float gap;             /**< Horizontal distance covered in the air, metres: rim to rim for a
                                generated jump, rim to landing for a generated drop; for other links
                                the ends' horizontal distance (their rims are not known).
                                nl_agent_capabilities.max_jump_distance is compared with it. */
    float rise;            /**< How far the end is above the start (0 if below), floor to floor for
                                generated links. */
    float drop;            /**< How far the end is below the start (0 if above), floor to floor for
                                generated links. */
    float clearance_width; /**< Widest body found clear along the link (0: not measured). */
    uint64_t abilities;    /**< Ability bits the agent must have (plugin kinds). */
    float length;          /**< Horizontal distance between the ends, metres. */
    uint32_t reserved;     /**< 0. */
} nl_link_requirements;

/** A link as the world holds it. An array element that may grow: set `size` of the first element of
 *  an output array (nl_link_init). */
typedef struct nl_link {
    uint32_t size;             /**< sizeof(nl_link) as the host knows it; written back. */
    nl_link_kind kind;
    nl_link_id id;
    nl_navmesh_id navmesh;
    float start[3];
    float end[3];
    float apex[3];             /**< Top of a jump's arc; for a generated drop, where its fall leaves
                                    the ground (0.2 m past the rim on the fall's heading, at the
                                    start's height); for other kinds the higher end. */
    uint8_t bidirectional;
    uint8_t generated;         /**< 1 if made by nl_navmesh_generate_links. */
    uint8_t enabled;
    uint8_t reserved;
    float cost_modifier;       /**< Multiplies the link's traversal cost (>= 0; 1 by default). */
    uint32_t start_polygon;    /**< Navmesh polygons under the ends (NL_NO_POLYGON if unknown). */
    uint32_t end_polygon;
    uint32_t reserved2;        /**< 0. (Keeps user_data 8-aligned with no hidden padding.) */
    uint64_t user_data;
    nl_link_requirements requirements;
    nl_navmesh_id landing_navmesh; /**< For a link to another navmesh (a cross link), the navmesh its
                                        end is on (end_polygon is one of its polygons); the null id
                                        for a link within `navmesh`. Added in 0.3. */
    float tolerance;           /**< A cross link's: how far its end may move, seen from its start,
                                    before it stops holding; 0 for other links. */
    uint8_t holds;             /**< 1 if the link can be taken as the navmeshes stand now: for a link
                                    within one navmesh, while both its ends' tiles are loaded (always on
                                    a solo navmesh); for a cross link, also while its end is within
                                    `tolerance` of where it was, seen from its start. */
    uint8_t reserved3[3];
} nl_link;

NL_DEFINE_OUTPUT_INIT(nl_link, nl_link_init)

/** A link to add, or the new state of one to update. Get one from nl_default_link_def(). */
typedef struct nl_link_def {
    uint32_t size;             /**< sizeof(nl_link_def). */
    nl_link_kind kind;         /**< NL_LINK_MANUAL by default. */
    float start[3];
    float end[3];
    uint8_t bidirectional;     /**< 0 by default. */
    uint8_t enabled;           /**< 1 by default. */
    uint8_t requirements_as_given; /**< 0 (default, and what a zeroed def says): requirements.gap,
                                        length, rise and drop are measured from the ends (gap =
                                        length: the rims are not known), and the values given for
                                        them are ignored; 1: all of `requirements` is taken as given
                                        (e.g. a link that asks only for an ability; a length of 0 is
                                        measured). clearance_width and abilities are always taken as
                                        given. */
    uint8_t reserved;
    float cost_modifier;       /**< 1 by default; >= 0. */
    uint64_t user_data;
    nl_link_requirements requirements;
    nl_navmesh_id landing_navmesh; /**< The null id (default): both ends on the link's navmesh. Another
                                        navmesh: a cross link from the link's navmesh to that one (a
                                        ledge to a moving platform, a platform to a ledge), `end` on it.
                                        Both ends are given in the world as the navmeshes stand now, and
                                        each is kept in its navmesh's space; the link holds while the
                                        end, seen from the start, stays within `tolerance` of where it
                                        is now (agents wait at its start until it does: a ferry). Cross
                                        links are one-way and are not saved in links files. Added in 0.3. */
    float tolerance;           /**< Of a cross link, metres; 0.25 by default; >= 0. */
    uint32_t reserved2;
} nl_link_def;

/** A manual link from (0,0,0) to (0,0,0), one-way, enabled, cost modifier 1, requirements measured
 *  from its ends (requirements_as_given 0). Thread-safe. */
NL_API nl_link_def nl_default_link_def(void);

/** Adds a link to a navmesh. Its ends must each lie within 1 m of the navmesh (they are kept as given;
 *  the polygons under them are recorded), or, with def->landing_navmesh, the start within 1 m of
 *  `navmesh` and the end within 1 m of the landing navmesh. Ends are given in the world; on a navmesh
 *  that rides a moving mesh they are kept in its space (nl_link_get reads them where it is now).
 *  Returns SUCCESS, or a failure with INVALID_HANDLE (navmesh, landing_navmesh),
 *  INVALID_ARGUMENT (null pointer, a coordinate not finite or beyond the limit, an end off the navmesh,
 *  a negative cost modifier, requirement or tolerance, a two-way cross link, landing_navmesh equal to
 *  navmesh, size too small). Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The navmesh the link starts on.
 *  @param[in] def  The link to add.
 *  @param[out] out_id  Receives the link's id. */
NL_API nl_status nl_link_add(nl_world* world, nl_navmesh_id navmesh, const nl_link_def* def, nl_link_id* out_id);

/** Replaces a link's fields with `def`'s (any link, generated ones too: to disable one, for instance).
 *  It stays on its navmesh and keeps whether it was generated; a generation replaces generated links,
 *  edited or not. Errors as nl_link_add, and INVALID_HANDLE for the link. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] link  The link to change.
 *  @param[in] def  Its new fields. */
NL_API nl_status nl_link_update(nl_world* world, nl_link_id link, const nl_link_def* def);

/** Removes a link. Returns SUCCESS or INVALID_HANDLE. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] link  The link to remove. */
NL_API nl_status nl_link_remove(nl_world* world, nl_link_id link);

/** Nonzero if `link` is a link of `world`. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] link  The id to check. */
NL_API int32_t nl_link_is_valid(const nl_world* world, nl_link_id link);

/** Fills `*out_link` (caller-owned, `size` set). Returns SUCCESS, INVALID_HANDLE or INVALID_ARGUMENT
 *  (null pointer, `size` too small). Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] link  The link.
 *  @param[out] out_link  Receives the link. */
NL_API nl_status nl_link_get(const nl_world* world, nl_link_id link, nl_link* out_link);

/** Lists a navmesh's links, in the order they were added (two-call pattern as nl_world_get_meshes;
 *  out_links[0].size set when out_links is not NULL).
 *  Thread-safe: the list is one consistent moment even while other threads edit.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The navmesh.
 *  @param[out,opt] out_links  Receives the links, or NULL to count only.
 *  @param[in] capacity  Entries `out_links` has room for.
 *  @param[out] out_count  Receives the number of links. */
NL_API nl_status nl_navmesh_get_links(const nl_world* world, nl_navmesh_id navmesh, nl_link* out_links,
                                      uint32_t capacity, uint32_t* out_count);

/** Removes the navmesh's generated links; manual ones stay. `out_removed` (optional) receives how many
 *  went. The last generation is forgotten with them: nl_navmesh_update_links_in_box then returns
 *  NOT_FOUND until the next nl_navmesh_generate_links (an update never brings removed links back).
 *  Returns SUCCESS or INVALID_HANDLE. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The navmesh.
 *  @param[out,opt] out_removed  Receives how many links went, or NULL. */
NL_API nl_status nl_navmesh_remove_generated_links(nl_world* world, nl_navmesh_id navmesh, uint32_t* out_removed);

/** How links are generated (docs/link-generation.md explains each). Get one from
 *  nl_default_link_settings(); defaults work with Recast's default agent on the shared levels. */
typedef struct nl_link_settings {
    uint32_t size;                  /**< sizeof(nl_link_settings). */
    float min_edge_length;          /**< Shorter boundary edges are grouped with those they touch (0.4 m). */
    uint32_t min_group_size;        /**< Groups of fewer short edges are dropped (2). */
    uint32_t max_group_size;        /**< Longer chains of short edges are split (8). */
    float sample_spacing;           /**< Take-off samples along a long edge (1 m). */
    float falloff_distance;         /**< How far past an edge the ground must fall away (1.5 m). */
    float max_jump_gap;        /**< Widest gap a jump crosses, rim to rim (4 m). */
    float min_link_distance;        /**< Narrower gaps are walked, not jumped (0.3 m). */
    float short_link_distance;      /**< Shorter links use the permissive angles (2 m). */
    float max_jump_up;              /**< Highest rise of a jump, floor to floor; drops this low work
                                         both ways (1.5 m). */
    float jump_arc_height;          /**< Arc apex above the higher end (1 m). */
    float strict_forward_angle;     /**< Between a link and an edge's outward direction, degrees (35). */
    float permissive_forward_angle; /**< The same for short links (60). */
    float strict_incline_angle;     /**< Between a link and the take-off surface, degrees (45). */
    float permissive_incline_angle; /**< The same for short links (70). */
    float max_drop_distance;        /**< Deepest drop, floor to floor (5 m). */
    float drop_angles[16];          /**< Rotations of the outward direction probed for drops, degrees. */
    uint32_t drop_angle_count;      /**< Entries used in drop_angles (3: 0, -30, 30). */
    float drop_steepness;           /**< Landing probes fall this steeply, degrees below horizontal (60). */
    float merge_distance;           /**< Links with both ends this close are one (0.6 m). */
    float clearance_margin;         /**< Fraction of a path left out of the clearance test at each end (0.1). */
    uint32_t arc_segments;          /**< Pieces of a jump arc in the clearance test (12). */
    const char* plugin_settings_json;   /**< Optional JSON object of link-kind plugins' settings, one
                                             object per kind name: {"climb": {"max_height": 3}}
                                             (every value an object). Borrowed for the call; NULL =
                                             none (the length must then be 0). */
    size_t plugin_settings_json_length;
    float walk_factor;              /**< No jump whose ends are joined on foot by a walk of at most
                                         walk_factor x its length + walk_distance (1.5). */
    float walk_distance;            /**< (2 m). */
} nl_link_settings;

/** The defaults. Thread-safe; never fails. */
NL_API nl_link_settings nl_default_link_settings(void);

/** Applies a JSON object's keys (the field names above; drop_angles as an array) to `*settings`
 *  (caller-owned, in and out) and validates the result. On failure `*settings` is unchanged.
 *  Returns SUCCESS, or a failure with PARSE_ERROR (malformed JSON, with the position) or
 *  INVALID_ARGUMENT (an unknown key, a wrong type or value, nesting deeper than 64 levels: the key is
 *  named). Thread-safe.
 *  @param[in] json  The JSON object, `length` bytes.
 *  @param[in] length  The bytes of `json`.
 *  @param[in,out] settings  The settings to change. */
NL_API nl_status nl_link_settings_from_json(const char* json, size_t length, nl_link_settings* settings);

/** What a generation did: answers "why is there no link here?". */
typedef struct nl_link_generation_report {
    uint32_t size;               /**< Set by the caller to sizeof(nl_link_generation_report). */
    uint32_t edges;              /**< Boundary edges of the navmesh. */
    uint32_t groups;             /**< Groups of short edges. */
    uint32_t samples;            /**< Take-off samples on edges. */
    uint32_t takeoff_points;     /**< Samples that hang over a drop or gap. */
    uint32_t jump_candidates;    /**< Edge pairs that met the gap, rise, angle and walk limits. */
    uint32_t drop_candidates;    /**< Landings found below take-off points. */
    uint32_t jump_links;
    uint32_t drop_links;
    uint32_t plugin_links;         /**< Links of kinds from link-kind plugins. */
    uint32_t rejected_wall;        /**< Something solid between the edge and the rim. */
    uint32_t rejected_not_ledge;   /**< Walkable ground a step below the edge: no ledge there. */
    uint32_t rejected_distance;    /**< A jump's gap too wide or too narrow. */
    uint32_t rejected_rise;        /**< A jump higher than max_jump_up. */
    uint32_t rejected_angle;       /**< Not facing the other edge, or too steep. */
    uint32_t rejected_no_landing;  /**< No navmesh where the agent would land. */
    uint32_t rejected_clearance;   /**< The body would touch geometry on the way. */
    uint32_t rejected_duplicate;   /**< The same traversal as a link already kept. */
    uint64_t rays_cast;            /**< Rays and occlusion segments sent to Embree. */
    double milliseconds_edges;
    double milliseconds_takeoff;
    double milliseconds_jumps;
    double milliseconds_drops;
    double milliseconds_merge;
    double milliseconds_total;
    uint64_t box_queries;          /**< Boxes around straight runs of clearance sweeps asked whether
                                        any triangle touches them; an untouched one is clear without
                                        testing its pieces. Written when `size` covers it. */
    uint64_t body_tests;           /**< Pieces of clearance sweeps tested exactly against the
                                        triangles near them. The fields from here on are written
                                        when `size` covers them. */
    uint32_t rejected_walkable;    /**< Jumps whose ends are about as near on foot (walk_factor). */
    uint32_t rejected_too_shallow; /**< Drops no deeper than the agent's max_climb, floor to floor:
                                        a step, walked. */
    uint32_t rejected_too_deep;    /**< Drops deeper than max_drop_distance, floor to floor. */
    uint32_t reserved;
} nl_link_generation_report;

NL_DEFINE_OUTPUT_INIT(nl_link_generation_report, nl_link_generation_report_init)

/** Generates the navmesh's jump and drop links against the level geometry, and the links of every
 *  loaded link-kind plugin, and replaces its generated links with them; manual links are untouched.
 *  On a tiled navmesh each tile's links are those of a generation over the tiles within link reach of
 *  it (they start on it and end on any of them), and the tiles added or built later get theirs with
 *  these settings (nl_navmesh_add_tile); plugin links are generated over the whole navmesh.
 *  A plugin's refused link (a wrong kind, an end off the navmesh) fails the call with INTERNAL_ERROR
 *  and the plugin's name. `settings` is borrowed (NULL = defaults); `progress`
 *  is optional (`user` is passed back to it); `out_report` is optional (caller-owned, `size` set).
 *  Returns SUCCESS, or a failure with INVALID_HANDLE (also when the navmesh was removed while the
 *  links were being generated: nothing is stored), INVALID_ARGUMENT (a setting, named; also a sample_spacing that
 *  would put more than 4,000,000 take-off samples on this navmesh's boundary; plugin_settings_json
 *  nested deeper than 64 levels, or with a value that is not an object, or naming a kind no loaded
 *  link-kind plugin provides: the key named, with the kinds loaded),
 *  PARSE_ERROR (malformed plugin_settings_json, found before any work), CANCELLED (progress
 *  returned 0: the navmesh's links are as they were), OUT_OF_MEMORY.
 *  Generations and updates of one navmesh run one after the other; other navmeshes' run at the same
 *  time. From inside a generation, update or cross-link generation (its progress callback, a
 *  link-kind plugin) links cannot be generated or updated, on any navmesh and of either kind
 *  (nl_navmesh_generate_links, nl_navmesh_update_links_in_box, nl_navmesh_generate_cross_links): such
 *  a call fails with INVALID_ARGUMENT (two threads each doing so for the other's navmesh would wait
 *  for each other forever).
 *  Thread-safe; parallel over the world's workers; the result does not depend on their number.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The navmesh.
 *  @param[in,opt] settings  How to generate them, or NULL for the defaults.
 *  @param[in,opt] progress  Told of the progress and may cancel, or NULL.
 *  @param[in,opt] user  Passed back to `progress`.
 *  @param[out,opt] out_report  Receives what the generation did, or NULL. */
NL_API nl_status nl_navmesh_generate_links(nl_world* world, nl_navmesh_id navmesh, const nl_link_settings* settings,
                                           nl_progress_fn* progress, void* user, nl_link_generation_report* out_report);

/** Generates the jump and drop links between two navmeshes (a ledge and a platform; either may ride
 *  a moving mesh, nl_navmesh_def.carrier) for where they stand now, both ways, as cross links
 *  (nl_link_def.landing_navmesh) that hold while the two stay placed so, within `tolerance` metres
 *  (0.25 is a good start). They replace the generated cross links between the two that hold now
 *  (made for this placement); those made for another placement (the platform's other stop) stay for
 *  when it is back, and each navmesh's own links stay. Only the polygons within a link's reach of
 *  the other navmesh are looked at, so a platform's links cost what its neighbourhood does: call it
 *  when a carrier comes to rest, or when its links stop holding, as often as suits the host (nothing
 *  calls it for you). Links are proven against the level as it stands (the platform where it is).
 *  Both navmeshes must be made for the same agent radius and height. `settings`, `progress`, `user`
 *  and `out_report` as for nl_navmesh_generate_links (jump_links and drop_links count the cross
 *  links; link-kind plugins are not run: their links lie within one navmesh, though
 *  plugin_settings_json is checked as there). Returns SUCCESS, or a failure with INVALID_HANDLE (either
 *  navmesh), INVALID_ARGUMENT (the same navmesh twice, different bodies, a bad tolerance or setting,
 *  named; also when called from inside a generation, update or cross-link generation, as
 *  nl_navmesh_generate_links says), CANCELLED (nothing changed). Thread-safe; two calls for the same
 *  pair at once store one's result or the other's.
 *  @param[in] world  The world.
 *  @param[in] first  One navmesh.
 *  @param[in] second  The other navmesh.
 *  @param[in] tolerance  How far a link's end may move and the link hold, metres.
 *  @param[in,opt] settings  How to generate them, or NULL for the defaults.
 *  @param[in,opt] progress  Told of the progress and may cancel, or NULL.
 *  @param[in,opt] user  Passed back to `progress`.
 *  @param[out,opt] out_report  Receives what the generation did, or NULL. */
NL_API nl_status nl_navmesh_generate_cross_links(nl_world* world, nl_navmesh_id first, nl_navmesh_id second, float tolerance,
                                                 const nl_link_settings* settings, nl_progress_fn* progress, void* user,
                                                 nl_link_generation_report* out_report);

/** Regenerates only what level geometry inside the box [box_min, box_max] (3 floats each, borrowed)
 *  can have changed since the navmesh's last generation: call it after meshes were added, removed or
 *  moved there; the box must hold every change (for a moved mesh, its bounds before and after).
 *  Probes and sweeps that touch the box are cast again, everything else is reused, and the result
 *  equals what nl_navmesh_generate_links with the same settings would give now. Link-kind plugins
 *  keep no cache: their links are generated again in full. The navmesh itself must be the same (a
 *  rebuilt navmesh is a new one: generate its links in full). On a tiled navmesh the tiles whose links
 *  can reach into the box have theirs generated again; the plugins' links stay as they are.
 *  Returns SUCCESS, or a failure with NOT_FOUND (never generated, or the generated links were removed or
 *  replaced by a JSON load since or meanwhile: nothing is stored), INVALID_HANDLE, INVALID_ARGUMENT
 *  (a null, non-finite or inverted box; also when called from inside a generation or update, as
 *  nl_navmesh_generate_links says), CANCELLED (nothing changed). Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The navmesh.
 *  @param[in] box_min  The box's lower corner, 3 floats.
 *  @param[in] box_max  The box's upper corner, 3 floats.
 *  @param[in,opt] progress  Told of the progress and may cancel, or NULL.
 *  @param[in,opt] user  Passed back to `progress`.
 *  @param[out,opt] out_report  Receives what the generation did, or NULL. */
NL_API nl_status nl_navmesh_update_links_in_box(nl_world* world, nl_navmesh_id navmesh, const float* box_min,
                                                const float* box_max, nl_progress_fn* progress, void* user,
                                                nl_link_generation_report* out_report);

/** Writes the navmesh's links as JSON (schema "navlink-links" version 1, docs/link-generation.md)
 *  into `buffer` (caller-owned, `capacity` bytes, NUL-terminated on success), with what they were made
 *  for ("made_for": the navmesh's agent type, the settings of the generation that made its
 *  generated links, and the hash of the level a built navmesh came from, "level_hash"). `*out_length` always receives the length without the NUL; a NULL buffer only
 *  measures (two-call pattern). Returns SUCCESS, or a failure with BUFFER_TOO_SMALL (capacity must
 *  exceed the length), INVALID_HANDLE or INVALID_ARGUMENT. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The navmesh.
 *  @param[out,opt] buffer  Receives the JSON, or NULL to measure only.
 *  @param[in] capacity  The bytes `buffer` has room for.
 *  @param[out] out_length  Receives the JSON's length. */
NL_API nl_status nl_navmesh_save_links_json(const nl_world* world, nl_navmesh_id navmesh, char* buffer,
                                            size_t capacity, size_t* out_length);

/** Load links generated for another body than the navmesh's (see nl_navmesh_load_links_json). */
#define NL_LINKS_LOAD_ANY_BODY 0x1u

/** Replaces all of the navmesh's links with those in `json` (`length` bytes, borrowed); new ids are
 *  given. Each link is held to nl_link_add's rules: both ends within 1 m of the navmesh. A link
 *  without "requires" asks for what its ends measure; one with it for what it says (an absent key is
 *  0, an absent "length" the ends' horizontal distance). A file that says the body its links were
 *  generated for ("made_for".agent: radius and height) must say the navmesh's: links for another body
 *  are refused (INVALID_ARGUMENT, both bodies named), or, with NL_LINKS_LOAD_ANY_BODY in `flags`,
 *  loaded with a warning to the log callback. A file whose "level_hash" differs from the navmesh's
 *  was made for another level: a link end off the navmesh then fails saying so first, and links that
 *  all fit load with a warning. Files without "made_for" (written before 0.3) load as
 *  before. `out_count` (optional) receives how many were loaded. On failure nothing changes. On success
 *  the last generation is forgotten: nl_navmesh_update_links_in_box returns NOT_FOUND until the next
 *  nl_navmesh_generate_links.
 *  Returns SUCCESS, or a failure with PARSE_ERROR, VERSION_MISMATCH (another format or version),
 *  INVALID_ARGUMENT (a field missing or wrong, nesting deeper than 64 levels, an end off the navmesh,
 *  named by its path, e.g. "links[3].start"; links for another body; unknown flags), INVALID_HANDLE.
 *  Thread-safe. Changed in 0.3: `flags` was added.
 *  @param[in] world  The world.
 *  @param[in] navmesh  The navmesh.
 *  @param[in] json  The links file, `length` bytes.
 *  @param[in] length  The bytes of `json`.
 *  @param[in] flags  NL_LINKS_LOAD_* flags.
 *  @param[out,opt] out_count  Receives how many links were loaded, or NULL. */
NL_API nl_status nl_navmesh_load_links_json(nl_world* world, nl_navmesh_id navmesh, const char* json, size_t length,
                                            uint32_t flags, uint32_t* out_count);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* NAVLINK_LINKS_H */
