// The plugins compiled into libnavlink.so: every world registers them when it is created, in this
// order (capi/src/builtin_plugins.h declares the list).
#include <cstddef>

#include "navlink/plugin.h"
#include "recast/recast_builder.h"

extern "C" {
extern nl_plugin_entry_fn* const navlink_builtin_plugins[] = {nl::recast::plugin_entry};
extern const size_t navlink_builtin_plugin_count = sizeof(navlink_builtin_plugins) / sizeof(navlink_builtin_plugins[0]);
}
