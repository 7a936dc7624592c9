/*
 * NavLink: engine-agnostic navigation with generated jump and drop links.
 *
 * The one C header a host includes. It includes every part of the C ABI in the order data flows:
 * navlink/base.h (ids, statuses, the version: all a game's component header may need), then world,
 * level, navmesh, links, navmesh_file, paths, queries, agents and plugins. It compiles as C11 and as
 * C++; every type is blittable (fixed-width integers, floats, pointers), so C#, Rust and Python bind
 * it as is.
 *
 * Conventions (docs/c-api.md explains them with examples):
 * - Functions return an nl_status. On failure they write nothing to their outputs (except the count
 *   of a list that did not fit), change no state, and leave a message naming the failing argument
 *   in the calling thread's last error
 *   (nl_get_last_error_message) and, if the world has one, pass it to the world's log callback.
 * - Objects are referred to by ids passed by value: {index1, revision}; the all-zero id is null.
 *   An id whose object was removed is stale: using it returns NL_STATUS_INVALID_HANDLE, never crashes,
 *   and never reaches another object: a slot is retired before its generation could repeat, and no
 *   two live worlds tag their ids alike (docs/c-api.md, "Ids").
 * - Input pointers are borrowed for the duration of the call and copied where NavLink keeps the
 *   data; output pointers are caller-owned buffers. Each function says which: its comment ends with
 *   one @param[in], @param[out] or @param[in,out] line per parameter, with ",opt" after the direction
 *   where the pointer may be NULL (@param[in,opt] def).
 * - Unless a function says otherwise, all functions that take a world are safe to call from several
 *   threads at once on the same world; nl_world_destroy must not race with any other call on it.
 * - Callbacks (task, progress, log, plugin) run while the call that made them holds some of the
 *   world's locks, on the calling thread. A callback may call NavLink, except for what would take
 *   again a lock its caller holds: such a call fails at once with NL_STATUS_INTERNAL_ERROR and a
 *   message naming the lock (never waits for itself, never breaks the lock); a call from another
 *   thread waits for the lock as any call does, so a callback must not wait for such a thread. So,
 *   from a task callback during nl_world_step: no nl_agent_* function, nl_world_step or
 *   nl_world_get_agent*; from any task callback no level query or edit (nl_world_cast_rays,
 *   nl_mesh_*...: refused from every task); from a generation's progress callback or a link-kind
 *   plugin no other generation or update (INVALID_ARGUMENT, nl_navmesh_generate_links). Path
 *   requests, link edits and reads of navmeshes and links are meant to be called from callbacks.
 * - Structs that may grow start with `uint32_t size`. Inputs: fill them from the nl_default_*_def()
 *   functions, which set it, then change the fields you need; a library newer than the header a
 *   host was built with reads only the `size` bytes the host has and gives later fields their
 *   defaults. Outputs, single or in arrays: set `size` with the nl_*_init() functions below (inline,
 *   no library call: plugins use them too); the library writes only the `size` bytes the host has.
 *   An output array of such elements (nl_link, nl_path_point, nl_ray_hit...) is laid out with the
 *   host's element size, read from its FIRST element's `size`: set at least that one (the library
 *   writes every element's `size` back), e.g. `links[0] = nl_link_init();` (also after malloc: an
 *   unset `size` is garbage). A `size` smaller than the element's first release, over 4096 or not
 *   a multiple of the element's alignment is INVALID_ARGUMENT.
 * - Coordinates are metres; every position passed in must be finite and within
 *   +-NL_COORDINATE_LIMIT, or the call fails with NL_STATUS_INVALID_ARGUMENT.
 */
#ifndef NAVLINK_NAVLINK_H
#define NAVLINK_NAVLINK_H

#include "navlink/base.h"
#include "navlink/world.h"
#include "navlink/level.h"
#include "navlink/navmesh.h"
#include "navlink/links.h"
#include "navlink/navmesh_file.h"
#include "navlink/paths.h"
#include "navlink/queries.h"
#include "navlink/agents.h"
#include "navlink/plugins.h"

#endif /* NAVLINK_NAVLINK_H */
