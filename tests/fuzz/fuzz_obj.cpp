// libFuzzer target: OBJ text through nl_mesh_add_obj_memory (the record check, tinyobjloader, mesh
// validation, Embree). A mesh that loads is removed again.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    nl_world* world = nl::fuzz::shared_world();
    nl_mesh_id mesh{};
    const nl_status status = nl_mesh_add_obj_memory(world, reinterpret_cast<const char*>(data), size, nullptr, &mesh);
    nl::fuzz::require_reasoned(status);
    if (NL_SUCCEEDED(status)) nl_mesh_remove(world, mesh);
    return 0;
}
