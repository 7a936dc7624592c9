#include <cstddef>
#include <optional>
#include <string>
#include <thread>
#include <utility>

#include "builtin_plugins.h"
#include "entry_guard.h"
#include "plugin_adapter.h"
#include "world.h"

using nl::ErrorCode;
using nl::fail;
using nl::capi::guarded;

namespace {

constexpr size_t kWorldDefFirstSize = offsetof(nl_world_def, log_level) + sizeof(nl_log_level);

int resolve_worker_count(int32_t requested) {
    if (requested == NL_WORKERS_AUTO) return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    return std::max(1, static_cast<int>(requested));
}

// The host's log callback as the core's sink: a failure's code becomes its status.
nl::Logger logger_of(const nl_world_def& def) {
    if (!def.log_fn) return nl::Logger();
    nl_log_fn* const fn = def.log_fn;
    void* const user = def.log_user;
    return nl::Logger(
        [fn, user](nl::LogLevel level, std::optional<nl::ErrorCode> failure, const std::string& message) {
            const nl_status status = failure ? NL_STATUS_FAILURE | nl::capi::to_status(*failure) : NL_STATUS_SUCCESS;
            fn(user, static_cast<nl_log_level>(level), status, message.c_str());
        },
        static_cast<nl::LogLevel>(def.log_level));
}

}  // namespace

extern "C" {

NL_API nl_world_def nl_default_world_def(void) {
    nl_world_def def{};
    def.size = sizeof(nl_world_def);
    def.worker_count = NL_WORKERS_AUTO;
    def.log_fn = nullptr;
    def.log_user = nullptr;
    def.log_level = NL_LOG_WARNING;
    def.path_worker_count = NL_WORKERS_AUTO;
    return def;
}

NL_API nl_status nl_world_create(const nl_world_def* def, nl_world** out_world) {
    return guarded("nl_world_create", nullptr, [&] {
        nl::capi::require(out_world, "out_world");
        const nl_world_def settings =
            def ? nl::capi::read_growable(*def, nl_default_world_def(), kWorldDefFirstSize, "def") : nl_default_world_def();
        // Bounded above too: TBB sizes an arena by its count (2^31 slots crash its first use), and
        // the path queue starts one thread each.
        for (const auto& [count, name] : {std::pair{settings.worker_count, "worker_count"},
                                          std::pair{settings.path_worker_count, "path_worker_count"}}) {
            if (count < NL_WORKERS_AUTO || count > NL_MAX_WORKERS)
                fail(ErrorCode::InvalidArgument, "def->", name, " is ", count,
                     " (use NL_WORKERS_AUTO, 0 or a positive count up to NL_MAX_WORKERS = ", NL_MAX_WORKERS, ")");
        }
        if (settings.log_level > NL_LOG_DEBUG)
            fail(ErrorCode::InvalidArgument, "def->log_level is ", settings.log_level, " (at most NL_LOG_DEBUG)");
        nl::WorldSettings core;
        core.worker_count = resolve_worker_count(settings.worker_count);
        core.path_worker_count =
            settings.path_worker_count == 0 ? 0u : static_cast<unsigned>(resolve_worker_count(settings.path_worker_count));
        core.logger = logger_of(settings);
        auto world = std::make_unique<nl_world>();
        world->core = std::make_unique<nl::World>(std::move(core));
        for (size_t i = 0; i < navlink_builtin_plugin_count; ++i)
            nl::capi::add_c_plugin(*world->core, navlink_builtin_plugins[i], nullptr, true, "(built in)");
        *out_world = world.release();
    });
}

NL_API void nl_world_destroy(nl_world* world) {
    guarded("nl_world_destroy", nullptr, [&] {
        if (!world) return;
        // First, with the world whole: callbacks of the requests it ends may still call into it.
        world->core->paths().shutdown();
        delete world;
    });
}

NL_API int32_t nl_world_get_worker_count(const nl_world* world) {
    int32_t count = 0;
    guarded("nl_world_get_worker_count", world, [&] { count = nl::capi::deref(world).tasks().thread_count(); });
    return count;
}

}  // extern "C"
