// Which functions the host's table offers: a table from an older host is shorter, and a member past
// its `size` is not there to call.
#pragma once

#include <cstddef>

#include "navlink/plugin.h"

// True if `host` (an nl_plugin_host) has a non-null `member`.
#define NL_RECAST_HOST_OFFERS(host, member) \
    ((host).size >= offsetof(nl_plugin_host, member) + sizeof((host).member) && (host).member != nullptr)
