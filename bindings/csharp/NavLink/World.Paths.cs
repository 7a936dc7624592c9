using System;
using System.Runtime.InteropServices;

namespace NavLink
{
    public sealed partial class World
    {
        /// <summary>A walker: radius 0.6, no jumps, no drops.</summary>
        public static AgentCapabilities DefaultAgentCapabilities() { return Native.nl_default_agent_capabilities(); }

        // Points fetched in one go when a path has no more than this; longer ones take a second call.
        private const int FirstPointCapacity = 64;

        /// <summary>Plans a path now on the calling thread (for tools and tests; games queue requests).</summary>
        public unsafe PathResult FindPath(PathQuery query)
        {
            float[] costs = query.AreaCosts;
            fixed (float* c = costs)
            using (var w = Enter())
            {
                PathRequestDef def = ToDef(query, c);
                var points = new PathPoint[FirstPointCapacity];
                while (true)
                {
                    PathResultInfo info = default(PathResultInfo);
                    info.Size = (uint)sizeof(PathResultInfo);
                    uint count, status;
                    fixed (PathPoint* p = points)
                        status = Native.nl_path_find(w.Pointer, &def, &info, p, (uint)points.Length, &count);
                    if (StatusBits.Failed(status) && (status & StatusBits.BufferTooSmall) != 0u)
                    {
                        // nl_path_find cannot hand back points it had no room for: plan again with room.
                        points = new PathPoint[count];
                        continue;
                    }
                    Status.Check(status);
                    Array.Resize(ref points, (int)count);
                    return new PathResult(info, points);
                }
            }
        }

        /// <summary>Queues a request; onFinished (optional) runs once when it finishes, on a NavLink path
        /// worker, in ProcessPaths, in CancelPath or in Dispose. Release the ticket when done with it.</summary>
        public unsafe PathTicket RequestPath(PathQuery query, PathFinishedHandler onFinished = null)
        {
            float[] costs = query.AreaCosts;
            GCHandle context = onFinished == null ? default(GCHandle) : GCHandle.Alloc(onFinished);
            PathTicket ticket;
            uint status;
            fixed (float* c = costs)
            using (var w = Enter())
            {
                PathRequestDef def = ToDef(query, c);
                if (onFinished != null)
                {
                    def.Callback = Trampolines.PathPointer;
                    def.User = GCHandle.ToIntPtr(context);
                }
                status = Native.nl_path_request(w.Pointer, &def, &ticket);
            }
            if (StatusBits.Failed(status))
            {
                string message = Status.LastErrorMessage();
                if (context.IsAllocated) context.Free();  // a refused request never calls back
                throw new NavLinkException(status, message);
            }
            return ticket;
        }

        /// <summary>The request's outcome; PathOutcome.Pending while it runs.</summary>
        public unsafe PathOutcome PollPath(PathTicket ticket)
        {
            PathOutcome outcome;
            using (var w = Enter()) Status.Check(Native.nl_path_poll(w.Pointer, ticket, &outcome));
            return outcome;
        }

        /// <summary>The finished request's result, or false while it is still pending.</summary>
        public unsafe bool TryGetPathResult(PathTicket ticket, out PathResult result)
        {
            result = null;
            using (var w = Enter())
            {
                while (true)
                {
                    PathResultInfo info = default(PathResultInfo);
                    info.Size = (uint)sizeof(PathResultInfo);
                    uint count;
                    uint status = Native.nl_path_get_result(w.Pointer, ticket, &info, null, 0, &count);
                    if ((status & StatusBits.InProgress) != 0u) return false;
                    if (!(StatusBits.Failed(status) && (status & StatusBits.BufferTooSmall) != 0u)) Status.Check(status);
                    var points = new PathPoint[count];
                    fixed (PathPoint* p = points)
                        status = Native.nl_path_get_result(w.Pointer, ticket, &info, p, count, &count);
                    if (StatusBits.Failed(status) && (status & StatusBits.BufferTooSmall) != 0u) continue;
                    Status.Check(status);
                    result = new PathResult(info, points);
                    return true;
                }
            }
        }

        /// <summary>Asks a request to stop (a queued one finishes at once as Cancelled).</summary>
        public void CancelPath(PathTicket ticket)
        {
            using (var w = Enter()) Status.Check(Native.nl_path_cancel(w.Pointer, ticket));
        }

        /// <summary>Frees a request's result; the ticket becomes invalid (an unfinished one is cancelled).</summary>
        public void ReleasePath(PathTicket ticket)
        {
            using (var w = Enter()) Status.Check(Native.nl_path_release(w.Pointer, ticket));
        }

        /// <summary>Plans queued requests on this thread (maxRequests 0 and maxMilliseconds &lt;= 0: no
        /// limit); returns how many finished here. How a world with PathWorkerCount 0 runs its queue.</summary>
        public unsafe uint ProcessPaths(uint maxRequests = 0, double maxMilliseconds = 0)
        {
            uint processed;
            using (var w = Enter()) Status.Check(Native.nl_path_process(w.Pointer, maxRequests, maxMilliseconds, &processed));
            return processed;
        }

        public unsafe PathQueueStats GetPathQueueStats()
        {
            PathQueueStats stats = default(PathQueueStats);
            stats.Size = (uint)sizeof(PathQueueStats);
            using (var w = Enter()) Status.Check(Native.nl_path_get_queue_stats(w.Pointer, &stats));
            return stats;
        }

        private static unsafe PathRequestDef ToDef(PathQuery query, float* areaCosts)
        {
            PathRequestDef def = Native.nl_default_path_request_def();
            def.Navmesh = query.Navmesh;
            def.Start = query.Start;
            def.Goal = query.Goal;
            def.SearchHalfExtents = query.SearchHalfExtents;
            def.Agent = query.Agent;
            def.AreaCosts = (IntPtr)areaCosts;
            def.AreaCostCount = (uint)(query.AreaCosts == null ? 0 : query.AreaCosts.Length);
            def.LinkCost = query.LinkCost;
            def.MaxNodes = query.MaxNodes;
            def.AcceptPartial = (byte)(query.AcceptPartial ? 1 : 0);
            return def;
        }
    }
}
