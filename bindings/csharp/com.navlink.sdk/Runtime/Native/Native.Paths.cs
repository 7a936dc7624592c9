using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    public static unsafe partial class Native
    {
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern AgentCapabilities nl_default_agent_capabilities();

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern PathRequestDef nl_default_path_request_def();

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_path_find(IntPtr world, PathRequestDef* def, PathResultInfo* outResult,
                                               PathPoint* outPoints, uint capacity, uint* outCount);

        /// <summary>outShortfall: Native.nl_path_shortfall_init() (Size set). Plans the request as nl_path_find
        /// does and, for a Partial or NoPath outcome, says why (PathShortfallReason.None otherwise).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_path_explain(IntPtr world, PathRequestDef* def, PathShortfallInfo* outShortfall);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_path_request(IntPtr world, PathRequestDef* def, PathTicket* outTicket);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_path_poll(IntPtr world, PathTicket ticket, PathOutcome* outOutcome);

        /// <summary>timeoutMs: 0 only looks; Limits.PathWaitForever never times out. InProgress (with
        /// PathOutcome.Pending) on a timeout; InvalidArgument from inside a path callback.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_path_wait(IntPtr world, PathTicket ticket, uint timeoutMs, PathOutcome* outOutcome);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_path_get_result(IntPtr world, PathTicket ticket, PathResultInfo* outResult,
                                                     PathPoint* outPoints, uint capacity, uint* outCount);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_path_cancel(IntPtr world, PathTicket ticket);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_path_release(IntPtr world, PathTicket ticket);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern PathBudget nl_default_path_budget();

        /// <summary>budget may be null (no limits).</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_path_process(IntPtr world, PathBudget* budget, uint* outProcessed);

        /// <summary>outFinished[0].Size set (nl_path_finished_init) when capacity &gt; 0; outRemaining may be null.</summary>
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_path_take_finished(IntPtr world, PathFinished* outFinished, uint capacity,
                                                        uint* outCount, uint* outRemaining);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl)]
        public static extern StatusCode nl_path_get_queue_stats(IntPtr world, PathQueueStats* outStats);
    }
}
