#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <utility>

#include "builtin_plugins.h"
#include "entry_guard.h"
#include "first_sizes.h"
#include "plugin_adapter.h"
#include "util/host_task_system.h"
#include "world.h"

using nl::ErrorCode;
using nl::fail;
using nl::capi::guarded;

namespace {

// The task callbacks come as a group: a size that ends inside it is no header's sizeof.
constexpr size_t kWorldDefTasksBegin = offsetof(nl_world_def, task_enqueue_fn);
constexpr size_t kWorldDefTasksEnd = offsetof(nl_world_def, task_user) + sizeof(void*);

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

// The host's task callbacks as the core's scheduler: NavLink's task is the core's HostTask, run
// through one C function.
extern "C" {
static void run_host_task(void* task_context, uint32_t begin, uint32_t end, uint32_t worker_index) {
    static_cast<nl::HostTask*>(task_context)->run(begin, end, worker_index);
}
}

std::unique_ptr<nl::TaskSystem> host_tasks_of(const nl_world_def& def) {
    nl_task_enqueue_fn* const enqueue = def.task_enqueue_fn;
    nl_task_finish_fn* const finish = def.task_finish_fn;
    void* const user = def.task_user;
    nl::HostScheduler scheduler;
    scheduler.worker_count = def.worker_count;
    scheduler.enqueue = [enqueue, user](nl::HostTask& task, uint32_t count, uint32_t min_range) {
        return enqueue(user, run_host_task, &task, count, min_range);
    };
    scheduler.finish = [finish, user](void* host_task) { finish(user, host_task); };
    return nl::make_host_task_system(std::move(scheduler));
}

// Both task callbacks or neither; with them, worker_count counts the host's workers.
void check_task_callbacks(const nl_world_def& def) {
    const bool enqueue = def.task_enqueue_fn != nullptr, finish = def.task_finish_fn != nullptr;
    if (enqueue != finish)
        fail(ErrorCode::InvalidArgument, "def->", enqueue ? "task_finish_fn" : "task_enqueue_fn", " is NULL but def->",
             enqueue ? "task_enqueue_fn" : "task_finish_fn", " is set (set both task callbacks or neither)");
    if (enqueue && def.worker_count < 1)
        fail(ErrorCode::InvalidArgument, "def->worker_count is ", def.worker_count,
             " (with task callbacks it is the number of the host's workers: 1 to NL_MAX_WORKERS = ", NL_MAX_WORKERS,
             ")");
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
    def.task_enqueue_fn = nullptr;
    def.task_finish_fn = nullptr;
    def.task_user = nullptr;
    def.agent_paths_per_step = nl::AgentsSettings{}.max_paths_per_step;
    return def;
}

NL_API nl_status nl_world_create(const nl_world_def* def, nl_world** out_world) {
    return guarded("nl_world_create", nullptr, [&] {
        nl::capi::require(out_world, "out_world");
        const nl_world_def settings =
            def ? nl::capi::read_growable(*def, nl_default_world_def(), nl::capi::kFirstSize<nl_world_def>, "def")
                : nl_default_world_def();
        if (def && def->size > kWorldDefTasksBegin && def->size < kWorldDefTasksEnd)
            fail(ErrorCode::InvalidArgument, "def->size is ", def->size,
                 ", which ends inside the task callbacks (bytes ", kWorldDefTasksBegin, " to ", kWorldDefTasksEnd,
                 "; initialise it from nl_default_world_def or with sizeof)");
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
        check_task_callbacks(settings);
        if (settings.agent_paths_per_step == 0)
            fail(ErrorCode::InvalidArgument, "def->agent_paths_per_step is 0 (at least 1)");
        nl::WorldSettings core;
        core.agents.max_paths_per_step = settings.agent_paths_per_step;
        core.worker_count = resolve_worker_count(settings.worker_count);
        if (settings.task_enqueue_fn) core.tasks = host_tasks_of(settings);  // else TBB with worker_count threads
        core.path_worker_count = settings.path_worker_count == 0
                                     ? 0u
                                     : static_cast<unsigned>(resolve_worker_count(settings.path_worker_count));
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
