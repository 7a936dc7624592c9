using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    // The header's callback types as Cdecl delegates. Unity's IL2CPP accepts only delegates made from
    // static methods marked [AOT.MonoPInvokeCallback(typeof(TheDelegate))], with the context passed through
    // the `user` pointer (a GCHandle as IntPtr), as World does. Keep each delegate instance alive (a static
    // field) for as long as native code may call it: the GC does not see native references.
    public static class NativeCallbacks
    {
        /// <summary>nl_log_fn.</summary>
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        public delegate void LogFn(IntPtr user, LogLevel level, StatusCode status, IntPtr message);

        /// <summary>nl_task_fn: runs items [begin, end) of a task NavLink enqueued (call it through
        /// Marshal.GetDelegateForFunctionPointer of the pointer TaskEnqueueFn receives).</summary>
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        public delegate void TaskFn(IntPtr taskContext, uint begin, uint end, uint workerIndex);

        /// <summary>nl_task_enqueue_fn: `task` is an nl_task_fn pointer; returns the host's handle, or
        /// IntPtr.Zero when every range already ran.</summary>
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        public delegate IntPtr TaskEnqueueFn(IntPtr user, IntPtr task, IntPtr taskContext, uint itemCount, uint minRange);

        /// <summary>nl_task_finish_fn.</summary>
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        public delegate void TaskFinishFn(IntPtr user, IntPtr hostTask);

        /// <summary>nl_progress_fn: return 0 to cancel.</summary>
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        public delegate int ProgressFn(IntPtr user, float fraction, IntPtr stage);

        /// <summary>nl_path_callback.</summary>
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        public delegate void PathCallback(IntPtr user, PathTicket ticket, PathOutcome outcome);

        /// <summary>nl_plugin_entry_fn (hostAbiVersion, const nl_plugin_host*, nl_plugin_info*).</summary>
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        public delegate StatusCode PluginEntryFn(uint hostAbiVersion, IntPtr host, IntPtr outInfo);

        /// <summary>nl_navmesh_builder.build (state, const nl_plugin_host*, const nl_navmesh_build_def*,
        /// nl_navmesh_sink_fn*, sink_context).</summary>
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        public delegate StatusCode NavmeshBuildFn(IntPtr state, IntPtr host, IntPtr def, IntPtr sink, IntPtr sinkContext);

        /// <summary>nl_navmesh_sink_fn (sink_context, const nl_navmesh_def*).</summary>
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        public delegate StatusCode NavmeshSinkFn(IntPtr sinkContext, IntPtr navmesh);

        /// <summary>nl_link_kind_provider.generate.</summary>
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        public delegate StatusCode LinkGenerateFn(IntPtr state, IntPtr host, NavmeshId navmesh, IntPtr settingsJson,
                                            UIntPtr settingsJsonLength, IntPtr sink, IntPtr sinkContext);

        /// <summary>nl_link_sink_fn (sink_context, const nl_link_def*).</summary>
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        public delegate StatusCode LinkSinkFn(IntPtr sinkContext, IntPtr link);

        /// <summary>nl_plugin_info.destroy.</summary>
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        public delegate void PluginDestroyFn(IntPtr state);

        /// <summary>nl_plugin_host.log.</summary>
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        public delegate void HostLogFn(IntPtr context, LogLevel level, IntPtr message);

        /// <summary>nl_plugin_host.set_error.</summary>
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        public delegate void HostSetErrorFn(IntPtr context, IntPtr message);

        /// <summary>nl_plugin_host.record_build_settings (context, settings_json, length).</summary>
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        public delegate StatusCode HostRecordBuildSettingsFn(IntPtr context, IntPtr settingsJson, UIntPtr length);

        /// <summary>nl_plugin_host.get_level_triangles.</summary>
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        public unsafe delegate StatusCode HostGetLevelTrianglesFn(IntPtr context, float* vertices, uint vertexCapacity,
                                                            uint* outVertexCount, uint* indices, uint triangleCapacity,
                                                            uint* outTriangleCount);

        /// <summary>nl_plugin_host.get_build_triangles: as get_level_triangles, with each triangle's area
        /// (Limits.BuildAreaObstacle for an obstacle's) in areas (room for triangleCapacity).</summary>
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        public unsafe delegate StatusCode HostGetBuildTrianglesFn(IntPtr context, float* vertices, uint vertexCapacity,
                                                            uint* outVertexCount, uint* indices, byte* areas,
                                                            uint triangleCapacity, uint* outTriangleCount);

        /// <summary>nl_plugin_host.report_build_progress (context, fraction, stage): Cancelled when the
        /// build's caller asked to stop (return that status from the builder at once).</summary>
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        public delegate StatusCode HostReportBuildProgressFn(IntPtr context, float fraction, IntPtr stage);
    }
}
