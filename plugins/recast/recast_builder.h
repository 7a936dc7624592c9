// The Recast navmesh builder, a plugin compiled into libnavlink.so and registered in every world with
// nl_plugin_register(world, nl::recast::plugin_entry, ...). It builds one solo navmesh from the level's
// triangles, as RecastDemo's Sample_SoloMesh does, or square tiles of it, as Sample_TileMesh does, and
// hands them to the host as nl_navmesh_defs. Stateless: any number of builds may run at once.
#pragma once

#include <cstdint>

#include "navlink/navlink.h"
#include "navlink/plugin.h"
#include "navlink/recast.h"

namespace nl::recast {

// Recast's usual settings (RecastDemo's solo mesh); what nl_default_recast_settings() returns.
nl_recast_settings default_settings() noexcept;

// The plugin's entry function (nl_plugin_entry_fn): speaks NL_PLUGIN_ABI_VERSION (or the host's, if
// lower), names itself "recast" and provides a navmesh builder. Refuses a host speaking version 0 with
// NL_STATUS_FAILURE | NL_STATUS_VERSION_MISMATCH.
nl_status plugin_entry(uint32_t host_abi_version, const nl_plugin_host* host, nl_plugin_info* out_info) noexcept;

}  // namespace nl::recast
