// C plugins (capi/include/navlink/plugin.h) as the core's plugin interfaces (sdk/world/plugin.h):
// an adapter per plugin negotiates with its entry function, hands it a function table over the core
// world (plugin_host.cpp), and turns its builder and link-kind functions into NavMeshBuilder and
// LinkKindProvider.
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "navlink/plugin.h"
#include "os/dynamic_library.h"
#include "util/function_ref.h"
#include "util/handle.h"
#include "world/world.h"

namespace nl::capi {

// Starts a plugin through its entry function and adds it to the world. `library` (the loaded module,
// or null) belongs to the plugin from here on, also when this throws: VersionMismatch (no common ABI
// version), InvalidArgument (a bad or duplicate description), Internal or OutOfMemory (the plugin
// refused to start). `origin` names it in messages.
Handle add_c_plugin(World& world, nl_plugin_entry_fn* entry, std::unique_ptr<platform::DynamicLibrary> library,
                    bool builtin, const std::string& origin);

// Loads a plugin library (platform::DynamicLibrary) and adds the plugin it exports. Throws NotFound (no file, or no
// entry symbol), Io (the loader refused it), and as add_c_plugin.
Handle load_c_plugin(World& world, const std::string& path);

// The reason a plugin gave through host->set_error during the current call on this thread (empty if
// none); taking it clears it.
std::string take_plugin_error();

// The function table a plugin gets: `context` is the adapter (plugin_host.cpp).
nl_plugin_host make_plugin_host(void* context);
// What the table's functions need from their context.
World& world_of_plugin(void* context);
const std::string& name_of_plugin(void* context);
// Calls `use` with the level triangles a plugin is shown: during a navmesh build on this thread,
// what the build is for (Level::triangles_to_build: the static meshes, or the carrier mesh in its
// own space, with their areas), gathered once per build so that every call of the build (the count,
// the copy) sees the same level and the navmesh records the hash of what it was built from;
// otherwise every mesh in the world, each triangle of area 0.
void with_level_triangles(void* context, FunctionRef<void(const BuildTriangles&)> use);
// Calls `use` with what the build running on this thread for the plugin `context` is for, only the
// triangles that meet `columns` (Level::triangles_to_build_in_columns), and the bounds of all of it;
// gathered once per build for the same columns. InvalidArgument outside such a build.
void with_build_triangles_in_columns(void* context, const Columns& columns,
                                     FunctionRef<void(const BuildTriangles&, const Aabb& bounds)> use);
// Hands a builder's progress to the build running on this thread for the plugin `context`; false
// when its caller asked to stop. InvalidArgument outside such a build.
bool report_build_progress(void* context, float fraction, const char* stage);
// Keeps what the build running on this thread for the plugin `context` says it used (checked when
// the build ends); InvalidArgument outside such a build.
void record_build_settings(void* context, std::string_view settings_json);
// For the build running on this thread, calls task(i) for i in 0..count-1 on the world's task system;
// throws InvalidArgument outside a build of this plugin on this thread.
void run_build_tasks(void* context, uint32_t count, FunctionRef<void(uint32_t index)> task);

}  // namespace nl::capi
