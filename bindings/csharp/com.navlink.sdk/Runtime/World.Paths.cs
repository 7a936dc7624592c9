using System;
using System.Collections.Generic;
using System.Runtime.InteropServices;
using System.Threading;
using System.Threading.Tasks;

namespace NavLink
{
    public sealed partial class World
    {
        /// <summary>A walker: radius 0.6, no jumps, no drops.</summary>
        public static AgentCapabilities DefaultAgentCapabilities() { LibraryCheck.EnsureLoaded(); return Native.nl_default_agent_capabilities(); }

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
                    PathResultInfo info = Native.nl_path_result_init();
                    points[0] = Native.nl_path_point_init();  // the element size the library writes with
                    uint count;
                    StatusCode status;
                    fixed (PathPoint* p = points)
                        status = Native.nl_path_find(w.Pointer, &def, &info, p, (uint)points.Length, &count);
                    if (Status.IsBufferTooSmall(status))
                    {
                        // More points than room: this thread kept the plan, the second call copies it.
                        points = new PathPoint[count];
                        continue;
                    }
                    Status.Check(status);
                    Array.Resize(ref points, (int)count);
                    return new PathResult(info, points);
                }
            }
        }

        /// <summary>Why the query's path falls short of its goal (nl_path_explain): plans it as FindPath does and,
        /// for a Partial or NoPath outcome, plans again with one limit lifted at a time (the body's width, the
        /// excluded areas, the links the body cannot take) and names the first that gets there. Reason None
        /// when the path reaches the goal or an end is off the navmesh. Up to five searches on the calling
        /// thread: for tools, logs and debugging.</summary>
        public unsafe PathShortfall ExplainPath(PathQuery query)
        {
            float[] costs = query.AreaCosts;
            fixed (float* c = costs)
            using (var w = Enter())
            {
                PathRequestDef def = ToDef(query, c);
                PathShortfallInfo info = Native.nl_path_shortfall_init();
                Status.Check(Native.nl_path_explain(w.Pointer, &def, &info));
                return new PathShortfall(info);
            }
        }

        /// <summary>Queues a request; onFinished (optional) runs once when it finishes, on a NavLink path
        /// worker, in ProcessPaths, WaitPath, CancelPath, ReleasePath or Dispose. Release the ticket when done
        /// with it (ReleasePath); QueuePath returns a PathRequest that does so itself.</summary>
        public unsafe PathTicket RequestPath(PathQuery query, PathFinishedHandler onFinished = null)
        {
            float[] costs = query.AreaCosts;
            // Keeps the handler (and what it holds) alive until the trampoline has called it and frees this.
            GCHandle context = onFinished == null ? default(GCHandle) : GCHandle.Alloc(onFinished);
            PathTicket ticket;
            StatusCode status;
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
            if (Status.Failed(status))
            {
                string message = Status.LastErrorMessage();
                if (context.IsAllocated) context.Free();  // a refused request never calls back
                throw new NavLinkException(status, message);
            }
            return ticket;
        }

        /// <summary>Queues a request and returns it as a PathRequest: a Task (Finished) that completes when
        /// it finishes, a blocking Wait, and Dispose to release its ticket (use it in a using block). onFinished
        /// as for RequestPath. A request is kept alive while it is queued or running, so one dropped unfinished
        /// still completes its Task; once it has finished and is dropped, its finalizer releases the ticket.</summary>
        public PathRequest QueuePath(PathQuery query, PathFinishedHandler onFinished = null)
        {
            var request = new PathRequest(this);
            request.Ticket = RequestPath(query, (ticket, outcome) =>
            {
                // The Task first: a throwing handler must not leave it pending.
                request.Complete(outcome);
                if (onFinished != null) onFinished(ticket, outcome);
            });
            return request;
        }

        /// <summary>Queues the query and completes with its result; the ticket is released. The Task completes
        /// on a thread pool thread (never on a NavLink worker). With PathWorkerCount 0 the host must run the
        /// queue (ProcessPaths, WaitPath) for it to complete.</summary>
        public async Task<PathResult> FindPathAsync(PathQuery query)
        {
            using (PathRequest request = QueuePath(query))
            {
                await request.Finished.ConfigureAwait(false);
                return request.GetResult();
            }
        }

        /// <summary>The request's outcome; PathOutcome.Pending while it runs.</summary>
        public unsafe PathOutcome PollPath(PathTicket ticket)
        {
            PathOutcome outcome;
            using (var w = Enter()) Status.Check(Native.nl_path_poll(w.Pointer, ticket, &outcome));
            return outcome;
        }

        /// <summary>Blocks until the request has finished or the timeout has passed (null or
        /// Timeout.InfiniteTimeSpan: as long as it takes; TimeSpan.Zero: only looks) and returns its outcome,
        /// PathOutcome.Pending on a timeout. With PathWorkerCount 0 this thread plans queued requests, oldest
        /// first, until this one has finished (their callbacks run here); a request is never split, so the wait
        /// can overrun the timeout by one request. Not from a path callback (InvalidArgument).</summary>
        public unsafe PathOutcome WaitPath(PathTicket ticket, TimeSpan? timeout = null)
        {
            uint milliseconds = WaitMilliseconds(timeout);
            PathOutcome outcome;
            using (var w = Enter()) Status.Check(Native.nl_path_wait(w.Pointer, ticket, milliseconds, &outcome));
            return outcome;
        }

        private static uint WaitMilliseconds(TimeSpan? timeout)
        {
            if (!timeout.HasValue || timeout.Value == Timeout.InfiniteTimeSpan) return Limits.PathWaitForever;
            if (timeout.Value < TimeSpan.Zero)
                throw new ArgumentOutOfRangeException("timeout", "a wait's timeout is >= 0, or infinite");
            // Rounded up, so that a wait of 0.5 ms is not a mere look; 49 days and more are forever.
            double milliseconds = Math.Ceiling(timeout.Value.TotalMilliseconds);
            return milliseconds >= Limits.PathWaitForever ? Limits.PathWaitForever : (uint)milliseconds;
        }

        /// <summary>The finished request's result, or false while it is still pending.</summary>
        public unsafe bool TryGetPathResult(PathTicket ticket, out PathResult result)
        {
            result = null;
            using (var w = Enter())
            {
                while (true)
                {
                    PathResultInfo info = Native.nl_path_result_init();
                    uint count;
                    StatusCode status = Native.nl_path_get_result(w.Pointer, ticket, &info, null, 0, &count);
                    if ((status & StatusCode.InProgress) != 0) return false;
                    if (!(Status.IsBufferTooSmall(status))) Status.Check(status);
                    var points = new PathPoint[count];
                    if (count > 0) points[0] = Native.nl_path_point_init();
                    fixed (PathPoint* p = points)
                        status = Native.nl_path_get_result(w.Pointer, ticket, &info, p, count, &count);
                    if (Status.IsBufferTooSmall(status)) continue;
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

        // PathRequest's Dispose and finalizer: nothing to release once the world is gone (its tickets went
        // with it), and a finalizer must not throw. The world's handle is a SafeHandle, finalized after
        // ordinary finalizers such as PathRequest's, so a request and its world dropped together release in
        // that order.
        internal void ReleasePathIfAlive(PathTicket ticket)
        {
            if (handle.IsClosed) return;
            try
            {
                using (var w = Enter()) Native.nl_path_release(w.Pointer, ticket);
            }
            catch (ObjectDisposedException)
            {
                // Disposed by another thread meanwhile: the ticket went with the world.
            }
        }

        /// <summary>No limits: a PathBudget to change the fields of.</summary>
        public static PathBudget DefaultPathBudget() { LibraryCheck.EnsureLoaded(); return Native.nl_default_path_budget(); }

        /// <summary>Plans queued requests on this thread until the queue is empty or a limit is reached
        /// (each 0, or maxMilliseconds &lt;= 0: no limit; maxSearchNodes bounds the polygons the searches
        /// visit in all); returns how many finished here. How a world with PathWorkerCount 0 runs its
        /// queue, e.g. ProcessPaths(maxMilliseconds: 2) in Update().</summary>
        public uint ProcessPaths(uint maxRequests = 0, double maxMilliseconds = 0, ulong maxSearchNodes = 0)
        {
            PathBudget budget = Native.nl_default_path_budget();
            budget.MaxRequests = maxRequests;
            budget.MaxMilliseconds = maxMilliseconds;
            budget.MaxSearchNodes = maxSearchNodes;
            return ProcessPaths(budget);
        }

        /// <summary>Plans queued requests on this thread within the budget (start from DefaultPathBudget()).</summary>
        public unsafe uint ProcessPaths(PathBudget budget)
        {
            uint processed;
            using (var w = Enter()) Status.Check(Native.nl_path_process(w.Pointer, &budget, &processed));
            return processed;
        }

        // Finished requests taken per call at first; more calls take the rest.
        private const int FinishedChunk = 16;

        /// <summary>The requests that finished since the last call, oldest first, each reported once: the way
        /// to learn of finished requests on your own thread without a callback (callbacks still run too).
        /// Requests whose ticket was released are not reported.</summary>
        public unsafe FinishedPath[] TakeFinishedPaths()
        {
            var taken = new List<FinishedPath>();
            var buffer = new PathFinished[FinishedChunk];
            using (var w = Enter())
            {
                while (true)
                {
                    buffer[0] = Native.nl_path_finished_init();  // the element size the library writes with
                    uint count, remaining;
                    fixed (PathFinished* b = buffer)
                        Status.Check(Native.nl_path_take_finished(w.Pointer, b, (uint)buffer.Length, &count, &remaining));
                    for (int i = 0; i < count; ++i) taken.Add(new FinishedPath(buffer[i].Ticket, buffer[i].Outcome));
                    if (remaining == 0) return taken.ToArray();
                    if (remaining > buffer.Length) buffer = new PathFinished[remaining];
                }
            }
        }

        public unsafe PathQueueStats GetPathQueueStats()
        {
            PathQueueStats stats = Native.nl_path_queue_stats_init();
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
            def.Capabilities = query.Capabilities;
            def.AreaCosts = (IntPtr)areaCosts;
            def.AreaCostCount = (uint)(query.AreaCosts == null ? 0 : query.AreaCosts.Length);
            def.LinkCost = query.LinkCost;
            def.MaxNodes = query.MaxNodes;
            def.AcceptPartial = (byte)(query.AcceptPartial ? 1 : 0);
            return def;
        }
    }
}
