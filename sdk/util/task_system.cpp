#include "util/task_system.h"

namespace nl {
namespace {

// Bodies may nest (a body's parallel_for runs bodies on the same thread): a depth, not a flag.
thread_local int task_depth = 0;

}  // namespace

bool TaskSystem::inside_task() noexcept { return task_depth > 0; }

TaskSystem::TaskScope::TaskScope() noexcept { ++task_depth; }

TaskSystem::TaskScope::~TaskScope() { --task_depth; }

}  // namespace nl
