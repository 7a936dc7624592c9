/*
 * navlink/plugins.h: Plugins as the host loads them (capi/include/navlink/plugin.h is the plugin's side).
 * A part of navlink/navlink.h, which includes every part; its opening comment has the conventions.
 */
#ifndef NAVLINK_PLUGINS_H
#define NAVLINK_PLUGINS_H

#include "navlink/agents.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------------------------------------
 * Plugins (capi/include/navlink/plugin.h has the plugin side of the ABI).
 * ------------------------------------------------------------------------------------------- */

/** Plugin kinds (bits of nl_plugin_description.kinds and nl_plugin_info.kinds). */
#define NL_PLUGIN_NAVMESH_BUILDER 0x1u
#define NL_PLUGIN_LINK_KIND 0x2u

/** Loads a plugin from a shared library (`path`, borrowed NUL-terminated UTF-8) into the world: finds
 *  its entry symbol, negotiates the ABI version and registers what it provides. The library stays
 *  loaded until the world is destroyed.
 *  Returns SUCCESS, or a failure with NOT_FOUND (no such file, or no entry symbol: the message says
 *  which), IO_ERROR (the file is not a loadable library; the loader's message is included),
 *  VERSION_MISMATCH (the plugin speaks no ABI version this library does), INVALID_ARGUMENT (a plugin
 *  with that name is already loaded, or the plugin described itself wrongly). Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] path  The shared library.
 *  @param[out] out_id  Receives the plugin's id. */
NL_API nl_status nl_plugin_load(nl_world* world, const char* path, nl_plugin_id* out_id);

/** What a loaded plugin is. Strings are owned by the world and live until it is destroyed. */
typedef struct nl_plugin_description {
    uint32_t size;          /**< Set by the caller to sizeof(nl_plugin_description). */
    uint32_t abi_version;   /**< The ABI version agreed with the plugin. */
    uint32_t kinds;         /**< NL_PLUGIN_* bits. */
    uint32_t builtin;       /**< 1 for plugins compiled into the library. */
    const char* name;
    const char* version;
    const char* description;
} nl_plugin_description;

NL_DEFINE_OUTPUT_INIT(nl_plugin_description, nl_plugin_description_init)

/** Describes a plugin. Returns SUCCESS, INVALID_HANDLE or INVALID_ARGUMENT. Thread-safe.
 *  @param[in] world  The world.
 *  @param[in] plugin  The plugin.
 *  @param[out] out_description  Receives its description. */
NL_API nl_status nl_plugin_get_description(const nl_world* world, nl_plugin_id plugin,
                                           nl_plugin_description* out_description);

/** Lists the world's plugins, built-in ones first (two-call pattern as nl_world_get_meshes).
 *  @param[in] world  The world.
 *  @param[out,opt] out_ids  Receives the ids, or NULL to count only.
 *  @param[in] capacity  Entries `out_ids` has room for.
 *  @param[out] out_count  Receives the number of plugins. */
NL_API nl_status nl_world_get_plugins(const nl_world* world, nl_plugin_id* out_ids, uint32_t capacity,
                                      uint32_t* out_count);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* NAVLINK_PLUGINS_H */
