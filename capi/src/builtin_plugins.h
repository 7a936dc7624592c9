// The plugins compiled into libnavlink.so, registered in every world when it is created. The list
// is the plugins' own (plugins/builtin_plugins.cpp); this layer only registers what it names.
#pragma once

#include <cstddef>

#include "navlink/plugin.h"

extern "C" {
extern nl_plugin_entry_fn* const navlink_builtin_plugins[];
extern const size_t navlink_builtin_plugin_count;
}
