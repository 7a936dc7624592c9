// Compile check: <navlink/navlink.h> must build as C++ (-Wall -Wextra -pedantic -Werror), with every
// declaration inside extern "C" (the link fails on a mangled name) and every struct trivially copyable
// and standard-layout (blittable for bindings).
#include <navlink/navlink.h>

#include <cstdio>
#include <type_traits>

namespace {

template <typename T>
constexpr bool blittable() {
    return std::is_trivially_copyable<T>::value && std::is_standard_layout<T>::value;
}

static_assert(blittable<nl_version>(), "nl_version");
static_assert(blittable<nl_world_def>(), "nl_world_def");
static_assert(blittable<nl_mesh_id>(), "nl_mesh_id");
static_assert(blittable<nl_mesh_def>(), "nl_mesh_def");
static_assert(blittable<nl_mesh_info>(), "nl_mesh_info");
static_assert(blittable<nl_ray>(), "nl_ray");
static_assert(blittable<nl_ray_hit>(), "nl_ray_hit");
static_assert(blittable<nl_segment>(), "nl_segment");
static_assert(std::is_same<nl_status, uint32_t>::value, "nl_status is uint32_t");

void log_sink(void*, nl_log_level, nl_status, const char*) {}

}  // namespace

int main() {
    nl_log_fn* log = log_sink;
    (void)log;
    nl_world_def def = nl_default_world_def();
    def.worker_count = 1;
    nl_world* world = nullptr;
    if (NL_FAILED(nl_world_create(&def, &world))) {
        std::fprintf(stderr, "nl_world_create: %s\n", nl_get_last_error_message());
        return 1;
    }
    const nl_version v = nl_get_version();
    const bool ok = v.major == NL_VERSION_MAJOR && v.minor == NL_VERSION_MINOR && v.patch == NL_VERSION_PATCH &&
                    nl_world_get_worker_count(world) == 1;
    nl_world_destroy(world);
    return ok ? 0 : 1;
}
